#include "Normals/NormalEstimation.h"

#include "Cloud/CloudPoints.h"
#include "Cloud/CloudStatistics.h"
#include "Common/Progress.h"
#include "Common/WorkRunner.h"
#include "Normals/OrderedCloud.h"
#include "Normals/Orientation.h"
#include "Normals/OrientationGraph.h"
#include "Normals/PlaneFitting.h"
#include "Normals/SampleRadius.h"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace pcurv
{
using edge::IsZero;
using normals::FitPoint;
using normals::NearestSearch;
using normals::OrderedCloud;
using normals::OrientOutward;
using normals::OrientPointwise;
using normals::QuickTypicalRadius;

namespace
{

/// Fits a plane to the nearest neighbors of each of the n points of the
/// ordered cloud into fits (their normals and the orientation graph's
/// neighbors), reporting a point an item to progress.
void FitPlanes(const OrderedCloud& ordered,
  const NormalSettings& usable,
  std::int64_t n,
  double radius,
  WorkRunner& runner,
  StageProgress* progress,
  PlaneFits& fits)
{
  fits.GraphNeighbors = usable.GraphNeighbors;
  fits.Normals.assign(3 * n, 0.0);
  fits.Neighbors.Assign(n * usable.GraphNeighbors, n - 1);
  runner.For(n,
    1024,
    [&](std::int64_t begin, std::int64_t end)
    {
      if (progress && progress->Stopped())
      {
        return;
      }
      NearestSearch search;
      search.Guess = radius;
      for (std::int64_t p = begin; p < end; ++p)
      {
        FitPoint(ordered, usable, p, search, fits);
      }
      if (progress)
      {
        progress->Advance(end - begin);
      }
    });
}

/// Writes the cloud's coordinates back from the ordered copy when it goes
/// out of scope, if they were released.
struct CoordinatesAside
{
  CloudPoints& Cloud;
  const OrderedCloud& Ordered;
  WorkRunner& Runner;
  const bool Released;
  ~CoordinatesAside()
  {
    if (this->Released)
    {
      this->Ordered.WriteCoordinates(this->Cloud.Coordinates, this->Runner);
    }
  }
};

/// Gives the fitted normals their signs, as the settings' orientation
/// asks; false when progress was stopped.
bool OrientNormals(const NormalSettings& usable,
  const OrderedCloud& ordered,
  std::int64_t n,
  double radius,
  WorkRunner& runner,
  PlaneFits& fits,
  NormalSummary& summary,
  StageProgress* progress)
{
  if (usable.Orientation == NormalOrientation::Outward)
  {
    // Twice as many points as 32-bit positions hold: the frontier keeps a
    // sign bit beside each.
    const bool small = n < std::numeric_limits<std::int32_t>::max() / 2;
    if (!(small ? OrientOutward<std::int32_t>(
                    fits, ordered, radius, runner, fits.Normals, summary, progress)
                : OrientOutward<std::int64_t>(
                    fits, ordered, radius, runner, fits.Normals, summary, progress)))
    {
      return false;
    }
  }
  else
  {
    OrientPointwise(usable, ordered, fits.Normals);
  }
  return true;
}

} // namespace

NormalSummary EstimateNormals(CloudPoints& cloud,
  const NormalSettings& settings,
  WorkRunner& runner,
  std::vector<double>& normals,
  StageProgress* progress)
{
  NormalSummary summary;
  const std::int64_t n = cloud.NumberOfOwnPoints;
  normals.clear();
  if (n == 0)
  {
    return summary;
  }
  const Collectives alone;
  const CloudBoxes boxes = MeasureBoxes(cloud, alone);
  const NormalSettings usable = [&]()
  {
    NormalSettings s = settings;
    s.NumberOfNeighbors = std::max(3, s.NumberOfNeighbors);
    s.GraphNeighbors = std::max(1, s.GraphNeighbors);
    return s;
  }();
  double radius = 0.0;
  if (!QuickTypicalRadius(cloud, boxes, usable.NumberOfNeighbors, runner, radius))
  {
    radius = TypicalRadius(cloud, alone, boxes, usable.NumberOfNeighbors);
  }
  // A stop request is looked at between the serial steps too (each up to a
  // second on a million points); nothing is reported yet.
  if (progress && !progress->Reach(0.0))
  {
    return summary;
  }
  const OrderedCloud ordered(cloud, GlobalLattice(boxes, radius), runner);
  if (progress && !progress->Reach(0.0))
  {
    return summary;
  }

  PlaneFits fits;
  FitPlanes(ordered, usable, n, radius, runner, progress, fits);
  if (progress && progress->Stopped())
  {
    return summary;
  }

  // The orientation reads the ordered copy alone: without a halo, the
  // cloud's coordinates are released meanwhile and written back from the
  // copy on the way out, whichever it is.
  const CoordinatesAside aside{ cloud, ordered, runner, cloud.GetNumberOfPoints() == n };
  if (aside.Released)
  {
    std::vector<double>().swap(cloud.Coordinates);
  }
  if (!OrientNormals(usable, ordered, n, radius, runner, fits, summary, progress))
  {
    return summary;
  }
  // Allocated last: the orientation's graph is the estimate's peak memory.
  normals.assign(3 * n, 0.0);
  for (std::int64_t p = 0; p < n; ++p)
  {
    const double* normal = &fits.Normals[3 * p];
    summary.Undetermined += IsZero(normal);
    std::copy_n(normal, 3, &normals[3 * ordered.Id(p)]);
  }
  return summary;
}

} // namespace pcurv
