/**
 * @file SurfaceOutliers.h
 * @brief Points far from the surface their neighbors sample (stray returns,
 * mixed pixels, a scanner's ghosts): found by a robust fit of each point's
 * nearest neighbors, and moved onto that surface, so that they neither pull
 * their neighbors' normals and fits nor get the curvature of nothing: each
 * gets the curvature of the surface nearest to it, and a flag. No VTK.
 */
#ifndef SurfaceOutliers_h
#define SurfaceOutliers_h

#include <cstdint>
#include <vector>

namespace pcurv
{

struct CloudPoints;
class Collectives;
class WorkRunner;

/// What the detection found, per own point of the cloud (in its order).
struct SurfaceOutliers
{
  /// Distance from the point as given to the surface fitted to its
  /// neighbors (the working unit); NaN where the cloud has too few points
  /// for a fit.
  std::vector<double> Distance;
  /// 1 where the point is an outlier.
  std::vector<unsigned char> Flag;
  /// Outliers over every process.
  std::int64_t Count = 0;
  /// Distributed: the own outliers whose surface point lies in another
  /// process's part (they are not moved), with that point's coordinates and
  /// normal, 6 values each.
  std::vector<std::int64_t> RemotePoints;
  std::vector<double> RemoteReferences;
};

/// The neighbors each point's surface is fitted to.
constexpr int OutlierNeighbors = 48;

/// Finds the outliers among the own points of `cloud` and moves each onto
/// the surface its neighbors sample: onto the point of that surface
/// nearest to its foot, normal included, whose exact repeat it becomes
/// (RemoveRepeatedPoints then finds it, and it gets that point's results).
/// Distributed, where that point lies in another process's part, the
/// outlier is listed in RemotePoints instead: its results are that
/// process's to give (RemoteCopies.h). Every point is judged on the cloud as
/// given (an outlier moved does not change another's verdict), and a point
/// is an outlier when it lies farther from the surface than both the noise
/// there and two spacings allow, and has no points of its own around it.
/// Distributed, a halo holds every point's neighbors: the same verdicts
/// for any split of the cloud, any order of its points and any number of
/// threads.
SurfaceOutliers MoveOutliersOntoSurface(CloudPoints& cloud,
  const Collectives& processes,
  WorkRunner& runner);

} // namespace pcurv

#endif
