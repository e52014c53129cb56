/**
 * @file NormalEstimation.h
 * @brief Normals of a cloud that has none (no VTK): a plane fitted by PCA to
 * each point's nearest neighbours, the signs made consistent by propagation
 * along a minimum spanning tree of normal agreement (Hoppe et al. 1992), one
 * tree per connected part, then the sign of each part chosen globally:
 * outward, towards a viewpoint, or along an axis.
 *
 * Deterministic: points are handled in the neighbour grid's order, which
 * depends only on the coordinates, and ties in the tree are broken by that
 * order; so the normals do not depend on the input order, the threads, or
 * how the cloud is split among processes (the caller gathers the cloud).
 */
#ifndef NormalEstimation_h
#define NormalEstimation_h

#include "Cloud/CloudStatistics.h"

#include <array>
#include <cstdint>
#include <vector>

namespace pcurv
{
class StageProgress;
class WorkRunner;

/// How the sign of each connected part's normals is chosen.
enum class NormalOrientation : int
{
  /// Away from the part's inside: for a closed part (its normals sum to
  /// about zero) the sign for which the normals point away from its
  /// centroid on the whole; an open part whose normals share a side (a
  /// height field, an aerial scan, a bowl) points up (+z) on the whole,
  /// unless its normals are about horizontal (a wall), where the centroid
  /// decides again.
  Outward = 0,
  /// Each normal towards Viewpoint (where the scanner was), point by point.
  TowardsViewpoint = 1,
  /// Each normal with a positive component along Axis, point by point.
  AlongAxis = 2
};

struct NormalSettings
{
  /// Neighbours of the PCA plane fit (the point itself not counted).
  int NumberOfNeighbors = 30;
  /// Nearest neighbours each point is joined to in the orientation graph.
  int GraphNeighbors = 8;
  NormalOrientation Orientation = NormalOrientation::Outward;
  std::array<double, 3> Viewpoint{ { 0.0, 0.0, 0.0 } };
  std::array<double, 3> Axis{ { 0.0, 0.0, 1.0 } };
};

struct NormalSummary
{
  /// Connected parts of the orientation graph (Outward only).
  std::int64_t Components = 0;
  /// Points with too few neighbours for a plane (their normal is zero).
  std::int64_t Undetermined = 0;
  /// The progress monitor asked to stop: the normals are incomplete.
  bool Aborted = false;
};

/// Unit normals of the own points of `cloud` (coordinates only are read;
/// without a halo they are released while the normals are oriented, the
/// estimate's peak memory, and restored bit for bit before it returns),
/// 3 per point, zero where undetermined. With `progress`, the plane fits
/// (most of the time) are reported to it, one item a point, and it returns
/// early (`normals` then empty) when it is stopped, also during the
/// orientation, which asks it every few thousand points.
NormalSummary EstimateNormals(CloudPoints& cloud,
  const NormalSettings& settings,
  WorkRunner& runner,
  std::vector<double>& normals,
  StageProgress* progress = nullptr);

} // namespace pcurv

#endif
