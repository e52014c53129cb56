/**
 * @file NormalSummary.h
 * @brief What the normal estimation reports of a cloud. No VTK.
 */
#ifndef NormalSummary_h
#define NormalSummary_h

#include <cstdint>

namespace pcurv
{

struct NormalSummary
{
  /// Connected parts of the orientation graph (Outward only).
  std::int64_t Components = 0;
  /// Points with too few neighbors for a plane (their normal is zero).
  std::int64_t Undetermined = 0;
  /// Most points are seen from above (Outward only): the parts that do not
  /// hide half of themselves, as a closed object does, point up.
  bool SeenFromAbove = false;
  /// The progress monitor asked to stop: the normals are incomplete.
  bool Aborted = false;
};

} // namespace pcurv

#endif
