#include "Estimation/CloudEstimation.h"
#include "Estimation/CloudNormals.h"
#include "Cloud/CloudStatistics.h"
#include "Cloud/Halo.h"
#include "Estimation/GivenNormals.h"
#include "Estimation/ResultStore.h"
#include "Normals/NormalEstimation.h"

#include <algorithm>

namespace pcurv
{
namespace
{
/// Replaces the normals of the own points of `cloud` by estimated ones
/// (writing them to out.Normals too). Distributed, every process estimates
/// the whole cloud, gathered, and keeps its own part: the grid's order, not
/// the split, decides the result. Reported to `monitor` as the part [0,
/// share) of the whole: the plane fits (most of the time) counted, the
/// orientation at the end; Aborted when any process was asked to stop
/// (every process then stops: what follows is collective).
NormalSummary ReplaceNormals(CloudPoints& cloud,
  const NormalSettings& settings,
  const Collectives& processes,
  WorkRunner& runner,
  ProgressMonitor* monitor,
  double share,
  const RealBuffer& out)
{
  CloudPoints whole;
  std::int64_t first = 0;
  if (processes.IsDistributed())
  {
    std::vector<std::int64_t> lengths;
    whole.Coordinates = processes.Gather(std::vector<double>(cloud.Coordinates.begin(),
                                           cloud.Coordinates.begin() + 3 * cloud.NumberOfOwnPoints),
      &lengths);
    whole.NumberOfOwnPoints = static_cast<std::int64_t>(whole.Coordinates.size() / 3);
    for (int p = 0; p < processes.GetLocalProcessId(); ++p)
    {
      first += lengths[p] / 3;
    }
  }
  CloudPoints& estimated = processes.IsDistributed() ? whole : cloud;
  StageProgress planes(monitor, 0.0, 0.8 * share, estimated.NumberOfOwnPoints);
  // The cloud's own normals are unknown until estimated (not read by the
  // estimate): released meanwhile, they are not part of its peak memory.
  std::vector<double>().swap(cloud.Normals);
  std::vector<double> normals;
  NormalSummary summary = EstimateNormals(estimated, settings, runner, normals, &planes);
  summary.Aborted =
    !processes.Min(planes.Stopped() ? 0 : 1) || !StageProgress(monitor, 0.0, share, 1).Reach(1.0);
  cloud.DropHalo(); // the normals back, zero
  if (!normals.empty())
  {
    std::copy_n(normals.begin() + 3 * first, 3 * cloud.NumberOfOwnPoints, cloud.Normals.begin());
  }
  if (out)
  {
    for (std::int64_t i = 0; i < 3 * cloud.GetNumberOfInputPoints(); ++i)
    {
      out.Set(i, 0.0);
    }
    for (std::int64_t i = 0; i < cloud.NumberOfOwnPoints; ++i)
    {
      out.SetRange(3 * cloud.InputId(i), &cloud.Normals[3 * i], 3);
    }
  }
  return summary;
}
} // namespace

double SettleNormals(CloudPoints& cloud,
  const EstimationSettings& settings,
  const WorkingUnit& unit,
  const Collectives& processes,
  WorkRunner& runner,
  ProgressMonitor* monitor,
  const RealBuffer& out,
  EstimationSummary& summary)
{
  // Plane fits cost about as much as the curvatures, orientation a little more.
  // Given normals that the positions contradict: estimated, signed as given.
  summary.GivenNormalsReplaced = GivenNormalsDisagree(settings, cloud, processes, runner);
  const std::vector<double> given(
    summary.GivenNormalsReplaced ? cloud.Normals : std::vector<double>{});
  const bool estimate = settings.EstimateNormals || summary.GivenNormalsReplaced;
  const double normalsShare = estimate ? 0.45 : 0.0;
  if (estimate)
  {
    NormalSettings normals = settings.Normals;
    normals.ChooseScale = settings.Mode == FitMode::OrientedCircles;
    for (double& c : normals.Viewpoint)
    {
      c *= unit.Scale;
    }
    summary.Normals = ReplaceNormals(cloud, normals, processes, runner, monitor, normalsShare, out);
    if (!summary.Normals.Aborted)
    {
      SignLikeGiven(cloud.Normals, given);
    }
  }
  return normalsShare;
}

NormalSummary EstimateCloudNormals(CloudPoints cloud,
  const NormalSettings& settings,
  const Collectives& processes,
  WorkRunner& runner,
  const RealBuffer& out,
  ProgressMonitor* monitor)
{
  const std::vector<RepeatedPoint> repeats = RemoveRepeatedPoints(cloud);
  const double scale = WorkingLengthScale(cloud, processes);
  cloud.ScaleCoordinates(scale);
  NormalSettings scaled = settings;
  for (double& c : scaled.Viewpoint)
  {
    c *= scale;
  }
  const NormalSummary summary = ReplaceNormals(cloud, scaled, processes, runner, monitor, 1.0, out);
  for (const RepeatedPoint& repeat : repeats)
  {
    if (out)
    {
      out.CopyRange(3 * repeat.Original, 3 * repeat.Copy, 3);
    }
  }
  return summary;
}

} // namespace pcurv
