#include "Cloud/Halo.h"
#include "Cloud/CloudPoints.h"
#include "Cloud/Collectives.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>

namespace pcurv
{
namespace
{
constexpr int PointRecordSize = 6; // x y z nx ny nz

/// Squared distance from x to the box [lower, upper] (0 inside).
double SquaredDistanceToBox(const double* x, const double lower[3], const double upper[3])
{
  double squared = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const double outside = std::max({ lower[k] - x[k], 0.0, x[k] - upper[k] });
    squared += outside * outside;
  }
  return squared;
}

} // namespace

void ExchangeHalo(CloudPoints& cloud, const Collectives& processes, double reach)
{
  cloud.DropHalo();
  if (!processes.IsDistributed())
  {
    return;
  }
  const int numberOfProcesses = processes.GetNumberOfProcesses();
  const int me = processes.GetLocalProcessId();
  double lower[3], upper[3];
  cloud.OwnBounds(lower, upper);
  const std::vector<double> boxes =
    processes.Gather({ lower[0], lower[1], lower[2], upper[0], upper[1], upper[2] });

  // Own points within reach of another process's box, as records.
  const double reachSquared = reach * reach;
  std::vector<double> outgoing;
  for (std::int64_t i = 0; i < cloud.NumberOfOwnPoints; ++i)
  {
    const double* x = &cloud.Coordinates[3 * i];
    for (int p = 0; p < numberOfProcesses; ++p)
    {
      if (p != me && SquaredDistanceToBox(x, &boxes[6 * p], &boxes[6 * p + 3]) <= reachSquared)
      {
        outgoing.insert(outgoing.end(), x, x + 3);
        outgoing.insert(outgoing.end(), &cloud.Normals[3 * i], &cloud.Normals[3 * i] + 3);
        break;
      }
    }
  }
  // Every process's records reach every process, which keeps those within
  // reach of its own box. Simple and deadlock free; the records are only
  // the points near the boundaries between the pieces.
  std::vector<std::int64_t> lengths;
  const std::vector<double> records = processes.Gather(outgoing, &lengths);
  std::int64_t offset = 0;
  for (int p = 0; p < numberOfProcesses; ++p)
  {
    if (p != me && cloud.NumberOfOwnPoints > 0)
    {
      for (std::int64_t r = offset; r < offset + lengths[p]; r += PointRecordSize)
      {
        const double* record = &records[r];
        if (SquaredDistanceToBox(record, lower, upper) <= reachSquared)
        {
          cloud.Coordinates.insert(cloud.Coordinates.end(), record, record + 3);
          cloud.Normals.insert(cloud.Normals.end(), record + 3, record + 6);
        }
      }
    }
    offset += lengths[p];
  }
}

} // namespace pcurv
