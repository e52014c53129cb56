/**
 * @file CloudEstimation.h
 * @brief The cloud-level entry point of the numeric core: from a cloud with
 * normals and the settings to the curvatures of every point. No VTK: the
 * caller provides the output buffers, the collectives of a parallel run and
 * the threads (WorkRunner), and gets a summary back.
 *
 * What happens, in order: the cloud is moved into a power-of-two working
 * unit (CloudStatistics.h), the thresholds are chosen (fixed, automatic, k
 * nearest or the dynamic adjustment), the grid lattice is made from global
 * bounds, a halo is exchanged when distributed, the points are put into a
 * global processing order (the grid's order; blocks of space with the
 * dynamic adjustment), each work item is estimated, and the results are
 * written back in the input's unit.
 */
#ifndef CloudEstimation_h
#define CloudEstimation_h

#include "Cloud/CloudPoints.h"
#include "Cloud/Collectives.h"
#include "Common/Progress.h"
#include "Common/RealBuffer.h"
#include "Common/WorkRunner.h"
#include "Estimation/CurvatureOutputs.h"
#include "Estimation/EstimationSettings.h"

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace pcurv
{

/// The curvatures of every input point of `cloud` (consumed: it is scaled
/// and given a halo), written to `out`. The same results for any runner,
/// thread count or split of the cloud among processes.
EstimationSummary EstimateCloud(CloudPoints cloud,
  const EstimationSettings& settings,
  const Collectives& processes,
  WorkRunner& runner,
  ProgressMonitor* monitor,
  const CurvatureBuffers& out);

/// The normals of every input point of `cloud` alone (NormalEstimation.h),
/// written to `out` (3 per input point, zero where undetermined or the
/// coordinates are not finite); the same for any runner or split. With a
/// monitor that asks to stop, the summary says Aborted and `out` is
/// incomplete.
NormalSummary EstimateCloudNormals(CloudPoints cloud,
  const NormalSettings& settings,
  const Collectives& processes,
  WorkRunner& runner,
  const RealBuffer& out,
  ProgressMonitor* monitor = nullptr);

} // namespace pcurv

#endif
