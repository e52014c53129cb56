/**
 * @file PlaneFitting.h
 * @brief Each point's plane by PCA over its nearest neighbors, and its
 * nearest others for the orientation's graph: internal to the normal
 * estimation. No VTK.
 */
#ifndef PlaneFitting_h
#define PlaneFitting_h

#include "Neighbors/PointGrid.h"
#include "Normals/OrderedCloud.h"
#include "Normals/NormalSettings.h"

#include <cstdint>
#include <vector>

namespace pcurv
{

struct PlaneFits;

namespace normals
{

/// One thread's buffers of the k-nearest search, and its guess of the
/// radius: the last point's, the points being visited in grid order (so
/// the next one is near and about as dense).
struct NearestSearch
{
  Candidates Found;
  ShellPoints Shell;
  std::vector<double> Selected;
  NeighborOffsets Offsets;
  NeighborOffsets Level; // a part of Offsets (the normals' scale)
  std::vector<std::pair<double, std::int64_t>> Ranked;
  double Guess = 0.0;
};

/// One point's plane and graph neighbors: the k nearest found with one
/// radius query (usually), kept in position order for the fit, the nearest
/// others for the graph.
void FitPoint(const OrderedCloud& ordered,
  const NormalSettings& settings,
  std::int64_t position,
  NearestSearch& search,
  PlaneFits& fits);

} // namespace normals
} // namespace pcurv

#endif
