/**
 * @file ViewFromAbove.h
 * @brief Which points a view from above (+z) reaches, and whether the cloud
 * is a scan seen from that side (an airborne or terrain tile): internal to
 * the normal orientation. No VTK.
 */
#ifndef ViewFromAbove_h
#define ViewFromAbove_h

#include <cstdint>
#include <vector>

namespace pcurv
{
namespace normals
{
class OrderedCloud;

/// The vertical component of a normal more than 60 degrees from vertical,
/// as half of a closed surface's are.
constexpr double SteepBelow = 0.5;

/// What a view from above tells of a point.
enum class Sight : signed char
{
  /// About vertical surface (a wall, a crown's side): seen from the side
  /// whatever the scan, so it tells nothing.
  Steep = -1,
  /// Something lies above it.
  Hidden = 0,
  /// Within `depth` of the highest point of its vertical column.
  Top = 1
};

/// Each point's Sight from above, by position in the ordered cloud; its
/// vertical column is `width` wide; `normals` are the fitted planes'
/// (their signs do not matter).
std::vector<Sight> SightsFromAbove(const OrderedCloud& ordered,
  const std::vector<double>& normals,
  double width,
  double depth);

/// The share of the points (positions) that are tops, among those that
/// are not steep; 0 when all are steep.
double ShareOfTops(const std::vector<Sight>& sights,
  const std::vector<std::int64_t>* part = nullptr);

/// A cloud most of whose points a view from above reaches. A closed
/// surface hides about half of itself from every direction (each vertical
/// line crosses it an even number of times, and only the first crossing
/// is seen), a scan taken from above hides only what lies under
/// vegetation or overhangs.
bool SeenFromAbove(const std::vector<Sight>& sights);

} // namespace normals
} // namespace pcurv

#endif
