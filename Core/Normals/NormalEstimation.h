/**
 * @file NormalEstimation.h
 * @brief Normals of a cloud that has none (no VTK): a plane fitted by PCA to
 * each point's nearest neighbors, the signs made consistent by propagation
 * along a minimum spanning tree of normal agreement (Hoppe et al. 1992), one
 * tree per connected part, then the sign of each part chosen globally:
 * outward, towards a viewpoint, or along an axis.
 *
 * Deterministic: points are handled in the neighbor grid's order, which
 * depends only on the coordinates, and ties in the tree are broken by that
 * order; so the normals do not depend on the input order, the threads, or
 * how the cloud is split among processes (the caller gathers the cloud).
 */
#ifndef NormalEstimation_h
#define NormalEstimation_h

#include "Normals/NormalSettings.h"
#include "Normals/NormalSummary.h"

#include <vector>

namespace pcurv
{
struct CloudPoints;
class StageProgress;
class WorkRunner;

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
