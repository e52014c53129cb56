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

std::vector<double> ExchangeHaloRecords(std::int64_t count,
  int width,
  const HaloRecord& recordOf,
  const Collectives& processes,
  double reach)
{
  std::vector<double> halo;
  if (!processes.IsDistributed())
  {
    return halo;
  }
  const int numberOfProcesses = processes.GetNumberOfProcesses();
  const int me = processes.GetLocalProcessId();
  std::vector<double> record(width);
  double lower[3], upper[3];
  for (int k = 0; k < 3; ++k)
  {
    lower[k] = std::numeric_limits<double>::infinity();
    upper[k] = -std::numeric_limits<double>::infinity();
  }
  for (std::int64_t i = 0; i < count; ++i)
  {
    recordOf(i, record.data());
    for (int k = 0; k < 3; ++k)
    {
      lower[k] = std::min(lower[k], record[k]);
      upper[k] = std::max(upper[k], record[k]);
    }
  }
  const std::vector<double> boxes =
    processes.Gather({ lower[0], lower[1], lower[2], upper[0], upper[1], upper[2] });

  // Own records within reach of another process's box.
  const double reachSquared = reach * reach;
  std::vector<double> outgoing;
  for (std::int64_t i = 0; i < count; ++i)
  {
    recordOf(i, record.data());
    for (int p = 0; p < numberOfProcesses; ++p)
    {
      if (p != me &&
        SquaredDistanceToBox(record.data(), &boxes[6 * p], &boxes[6 * p + 3]) <= reachSquared)
      {
        outgoing.insert(outgoing.end(), record.begin(), record.end());
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
    if (p != me && count > 0)
    {
      for (std::int64_t r = offset; r < offset + lengths[p]; r += width)
      {
        if (SquaredDistanceToBox(&records[r], lower, upper) <= reachSquared)
        {
          halo.insert(halo.end(), &records[r], &records[r] + width);
        }
      }
    }
    offset += lengths[p];
  }
  return halo;
}

void ExchangeHalo(CloudPoints& cloud, const Collectives& processes, double reach)
{
  cloud.DropHalo();
  if (!processes.IsDistributed())
  {
    return;
  }
  const std::vector<double> halo = ExchangeHaloRecords(
    cloud.NumberOfOwnPoints,
    PointRecordSize,
    [&](std::int64_t i, double* record)
    {
      std::copy_n(&cloud.Coordinates[3 * i], 3, record);
      std::copy_n(&cloud.Normals[3 * i], 3, record + 3);
    },
    processes,
    reach);
  for (std::size_t r = 0; r < halo.size(); r += PointRecordSize)
  {
    cloud.Coordinates.insert(cloud.Coordinates.end(), &halo[r], &halo[r] + 3);
    cloud.Normals.insert(cloud.Normals.end(), &halo[r] + 3, &halo[r] + 6);
  }
}

} // namespace pcurv
