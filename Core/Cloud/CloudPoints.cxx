#include "Cloud/CloudPoints.h"
#include "Common/Hash.h"

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
/// The six values of point i (coordinates, normal), -0 read as +0 so that
/// equal values hash alike.
std::array<double, 6> PointRecord(const CloudPoints& cloud, std::int64_t i)
{
  std::array<double, 6> record;
  for (int k = 0; k < 3; ++k)
  {
    record[k] = cloud.Coordinates[3 * i + k] + 0.0;
    record[3 + k] = cloud.Normals[3 * i + k] + 0.0;
  }
  return record;
}

std::uint64_t HashRecord(const std::array<double, 6>& record)
{
  std::uint64_t hash = 0;
  for (const double value : record)
  {
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    hash = Mix(hash ^ bits);
  }
  return hash;
}

/// For the points [first, end) of the cloud: the index of the earliest
/// point each repeats exactly (points from `first` on are compared with
/// every point from 0 on), or -1. The points are first spread by the top
/// bits of their hashes over groups of a few thousand (one sequential pass),
/// then each group is searched with an open-addressing table small enough
/// to stay in cache: linear in the number of points, and cheap (one table
/// over the whole cloud missed the cache at every point).
std::vector<std::int64_t> EarlierEqualPoints(const CloudPoints& cloud, std::int64_t first)
{
  const std::int64_t n = cloud.GetNumberOfPoints();
  std::vector<std::uint64_t> hashes(n);
  for (std::int64_t i = 0; i < n; ++i)
  {
    hashes[i] = HashRecord(PointRecord(cloud, i));
  }
  int groupBits = 0;
  while (groupBits < 16 && (n >> groupBits) > 4096)
  {
    ++groupBits;
  }
  const auto groupOf = [groupBits](std::uint64_t hash)
  { return groupBits == 0 ? std::uint64_t{ 0 } : hash >> (64 - groupBits); };
  std::vector<std::int64_t> starts((std::size_t{ 1 } << groupBits) + 1, 0);
  for (const std::uint64_t hash : hashes)
  {
    ++starts[groupOf(hash) + 1];
  }
  for (std::size_t g = 1; g < starts.size(); ++g)
  {
    starts[g] += starts[g - 1];
  }
  std::vector<std::int64_t> grouped(n);
  std::vector<std::int64_t> fill(starts.begin(), starts.end() - 1);
  for (std::int64_t i = 0; i < n; ++i) // in index order within each group
  {
    grouped[fill[groupOf(hashes[i])]++] = i;
  }

  std::vector<std::int64_t> earlier(n - first, -1);
  std::vector<std::int64_t> table;
  for (std::size_t g = 0; g + 1 < starts.size(); ++g)
  {
    std::size_t size = 16;
    while (size < 2 * static_cast<std::size_t>(starts[g + 1] - starts[g]))
    {
      size *= 2;
    }
    table.assign(size, -1);
    for (std::int64_t k = starts[g]; k < starts[g + 1]; ++k)
    {
      const std::int64_t i = grouped[k];
      for (std::size_t slot = hashes[i] & (size - 1);; slot = (slot + 1) & (size - 1))
      {
        const std::int64_t j = table[slot];
        if (j < 0)
        {
          table[slot] = i;
          break;
        }
        if (hashes[j] == hashes[i] && PointRecord(cloud, j) == PointRecord(cloud, i))
        {
          if (i >= first)
          {
            earlier[i - first] = j;
          }
          break;
        }
      }
    }
  }
  return earlier;
}

/// Keeps the points i for which keep(i) holds, in order. The input ids are
/// listed only once an own point is dropped (before, they stay 0, 1, 2, ...).
template<typename Keep>
void KeepPoints(CloudPoints& cloud, Keep&& keep)
{
  std::int64_t kept = 0, keptOwn = 0;
  for (std::int64_t i = 0; i < cloud.GetNumberOfPoints(); ++i)
  {
    if (!keep(i))
    {
      if (cloud.IsOwn(i))
      {
        cloud.ListInputIds();
      }
      continue;
    }
    std::copy_n(&cloud.Coordinates[3 * i], 3, &cloud.Coordinates[3 * kept]);
    std::copy_n(&cloud.Normals[3 * i], 3, &cloud.Normals[3 * kept]);
    if (cloud.IsOwn(i))
    {
      if (!cloud.InputIds.empty())
      {
        cloud.InputIds[keptOwn] = cloud.InputIds[i];
      }
      ++keptOwn;
    }
    ++kept;
  }
  cloud.Coordinates.resize(3 * kept);
  cloud.Normals.resize(3 * kept);
  if (!cloud.InputIds.empty())
  {
    cloud.InputIds.resize(keptOwn);
  }
  cloud.NumberOfOwnPoints = keptOwn;
}

} // namespace

void MakeUnitNormal(double n[3])
{
  // Divided by its largest component first, so that the squares neither
  // overflow (length 1e170) nor underflow (length 1e-170).
  const double largest = std::max({ std::fabs(n[0]), std::fabs(n[1]), std::fabs(n[2]) });
  if (!(largest > 0.0 && std::isfinite(largest + n[0] + n[1] + n[2])))
  {
    n[0] = n[1] = n[2] = 0.0;
    return;
  }
  for (int k = 0; k < 3; ++k)
  {
    n[k] /= largest;
  }
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (int k = 0; k < 3; ++k)
  {
    n[k] /= length;
  }
}

void CloudPoints::Reset(std::int64_t numberOfInputPoints)
{
  this->Coordinates.clear();
  this->Normals.clear();
  this->InputIds.clear();
  this->FiniteInput.assign(numberOfInputPoints, 0);
  this->NumberOfInputPoints = numberOfInputPoints;
  this->Coordinates.reserve(3 * numberOfInputPoints);
  this->Normals.reserve(3 * numberOfInputPoints);
  this->NumberOfOwnPoints = 0;
}

void CloudPoints::ListInputIds()
{
  if (this->InputIds.empty() && this->NumberOfOwnPoints > 0)
  {
    this->InputIds.resize(static_cast<std::size_t>(this->NumberOfOwnPoints));
    std::iota(this->InputIds.begin(), this->InputIds.end(), std::int64_t{ 0 });
  }
}

void CloudPoints::AddInputPoint(std::int64_t id, const double x[3], const double normal[3])
{
  if (!(std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2])))
  {
    return;
  }
  double n[3] = { normal[0], normal[1], normal[2] };
  MakeUnitNormal(n);
  this->FiniteInput[id] = 1;
  this->Coordinates.insert(this->Coordinates.end(), x, x + 3);
  this->Normals.insert(this->Normals.end(), n, n + 3);
  if (this->InputIds.empty() && id == this->NumberOfOwnPoints)
  {
    ++this->NumberOfOwnPoints; // the ids are still 0, 1, 2, ...
    return;
  }
  if (this->InputIds.empty())
  {
    this->InputIds.reserve(this->FiniteInput.size());
    this->ListInputIds();
  }
  this->InputIds.push_back(id);
  this->NumberOfOwnPoints = static_cast<std::int64_t>(this->InputIds.size());
}

std::vector<RepeatedPoint> RemoveRepeatedPoints(CloudPoints& cloud)
{
  cloud.DropHalo();
  const std::vector<std::int64_t> earlier = EarlierEqualPoints(cloud, 0);
  std::vector<RepeatedPoint> repeats;
  for (std::int64_t i = 0; i < cloud.NumberOfOwnPoints; ++i)
  {
    if (earlier[i] >= 0) // the earliest of equal points, which is kept
    {
      repeats.push_back({ cloud.InputId(i), cloud.InputId(earlier[i]) });
    }
  }
  if (!repeats.empty())
  {
    KeepPoints(cloud, [&](std::int64_t i) { return earlier[i] < 0; });
  }
  return repeats;
}

std::vector<std::int64_t> RemoveOwnPoints(CloudPoints& cloud,
  const std::vector<unsigned char>& remove)
{
  std::vector<std::int64_t> removed;
  for (std::int64_t i = 0; i < static_cast<std::int64_t>(remove.size()); ++i)
  {
    if (remove[i])
    {
      removed.push_back(cloud.InputId(i));
    }
  }
  if (!removed.empty())
  {
    cloud.DropHalo();
    KeepPoints(cloud,
      [&](std::int64_t i)
      { return i >= static_cast<std::int64_t>(remove.size()) || remove[i] == 0; });
  }
  return removed;
}

void RemoveRepeatedHalo(CloudPoints& cloud)
{
  if (cloud.GetNumberOfPoints() == cloud.NumberOfOwnPoints)
  {
    return;
  }
  const std::int64_t own = cloud.NumberOfOwnPoints;
  const std::vector<std::int64_t> earlier = EarlierEqualPoints(cloud, own);
  if (std::any_of(earlier.begin(), earlier.end(), [](std::int64_t e) { return e >= 0; }))
  {
    KeepPoints(cloud, [&](std::int64_t i) { return i < own || earlier[i - own] < 0; });
  }
}

void CloudPoints::OwnBounds(double lower[3], double upper[3]) const
{
  for (int k = 0; k < 3; ++k)
  {
    lower[k] = std::numeric_limits<double>::infinity();
    upper[k] = -std::numeric_limits<double>::infinity();
  }
  for (std::int64_t i = 0; i < this->NumberOfOwnPoints; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      lower[k] = std::min(lower[k], this->Coordinates[3 * i + k]);
      upper[k] = std::max(upper[k], this->Coordinates[3 * i + k]);
    }
  }
}

void CloudPoints::ScaleCoordinates(double factor)
{
  for (double& coordinate : this->Coordinates)
  {
    coordinate *= factor;
  }
}

void CloudPoints::DropHalo()
{
  this->Coordinates.resize(3 * this->NumberOfOwnPoints);
  this->Normals.resize(3 * this->NumberOfOwnPoints);
}

} // namespace pcurv
