/**
 * @file LineCrossings.h
 * @brief Where the derivative of a principal curvature along its own
 * direction crosses zero on the edges of the nearest-neighbor graph, and
 * of which kind the extremum there is. No VTK.
 */
#ifndef LineCrossings_h
#define LineCrossings_h

#include "Common/WorkRunner.h"
#include "Lines/LineDerivatives.h"

#include <array>
#include <cstdint>
#include <vector>

namespace pcurv
{

/// A point of an extremal line on the edge between two cloud points.
struct LineCrossing
{
  std::array<double, 3> Position;
  std::array<double, 3> Tangent; ///< of the line, up to sign
  double Curvature;              ///< the extremal curvature there
  double EdgeLength;
  LineKind Kind;
};

/// The crossings of the selected kinds, each graph edge once, in the order
/// of their edges' first points in `order` (a permutation of the points
/// that keeps neighbors together, such as a grid's: their data then stay
/// in cache). The order does not depend on `runner`.
std::vector<LineCrossing> FindCrossings(const LineInput& input,
  const LineSettings& settings,
  const PointDerivatives& derivatives,
  const std::int64_t* order,
  WorkRunner* runner);

} // namespace pcurv

#endif
