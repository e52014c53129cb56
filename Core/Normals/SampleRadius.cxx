#include "Normals/SampleRadius.h"

#include "Cloud/CloudPoints.h"
#include "Cloud/CloudStatistics.h"
#include "Common/WorkRunner.h"
#include "Neighbors/GridLattice.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <type_traits>
#include <utility>
#include <cstdint>
#include <vector>

namespace pcurv
{
namespace normals
{
namespace
{

/// The points near the sample points of TypicalRadius, found in one pass
/// over the cloud: the sample points' cells of a coarse lattice and the
/// cells around them are looked up in a small hash table.
class SampleNeighborhoods
{
public:
  SampleNeighborhoods(const CloudPoints& cloud,
    const std::vector<std::int64_t>& sample,
    const double origin[3],
    double cellSize,
    WorkRunner& runner);

  bool Usable() const { return this->Valid; }

  /// Calls visit(q) for every point in the cells around sample point x
  /// (every point within 0.9 cell sizes of it, and some more).
  template<typename Visit>
  void ForEachNear(const double x[3], Visit&& visit) const
  {
    const std::array<std::int64_t, 3> cell = this->CellOf(x);
    for (std::int64_t dz = -1; dz <= 1; ++dz)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dx = -1; dx <= 1; ++dx)
        {
          const std::int64_t slot =
            this->Find(Key({ { cell[0] + dx, cell[1] + dy, cell[2] + dz } }));
          for (std::int64_t j = this->SlotStart[slot]; j < this->SlotStart[slot + 1]; ++j)
          {
            visit(&this->Cloud.Coordinates[3 * this->Points[j]]);
          }
        }
  }

  /// Points in the cells around all sample points (counted once a sample
  /// point): the work ForEachNear does.
  std::int64_t Work(const std::vector<std::int64_t>& sample) const;

private:
  static constexpr std::int64_t Limit = std::int64_t{ 1 } << 40;

  std::array<std::int64_t, 3> CellOf(const double* x) const
  {
    std::array<std::int64_t, 3> cell;
    for (int k = 0; k < 3; ++k)
    {
      const double c = std::floor((x[k] - this->Origin[k]) / this->CellSize);
      // Far cells clamped (they can only gather more points than needed);
      // NaN to 0.
      cell[k] = static_cast<std::int64_t>(c > -Limit ? (c < Limit ? c : Limit) : -Limit);
    }
    return cell;
  }
  static std::uint64_t Key(const std::array<std::int64_t, 3>& cell)
  {
    std::uint64_t key = 1469598103934665603ull;
    for (const std::int64_t c : cell)
    {
      key = (key ^ static_cast<std::uint64_t>(c)) * 1099511628211ull;
      key ^= key >> 29;
    }
    return key;
  }
  /// The table from the cells' keys, sorted and unique, to their slots
  /// (their indices).
  void BuildTable(const std::vector<std::uint64_t>& keys);
  /// Points, the cloud's points by slot, and SlotStart, each slot's first;
  /// cells: the number of slots but the last, empty one.
  void SortPointsBySlot(std::size_t cells, WorkRunner& runner);
  /// The slot of a cell's key, or the empty slot of a cell not near any
  /// sample point.
  std::int64_t Find(std::uint64_t key) const
  {
    for (std::uint64_t h = key & this->Mask;; h = (h + 1) & this->Mask)
    {
      if (this->TableSlot[h] < 0)
      {
        return this->EmptySlot;
      }
      if (this->TableKey[h] == key)
      {
        return this->TableSlot[h];
      }
    }
  }

  const CloudPoints& Cloud;
  double Origin[3];
  double CellSize;
  std::uint64_t Mask = 0;
  std::vector<std::uint64_t> TableKey;
  std::vector<std::int64_t> TableSlot; // -1: empty
  std::int64_t EmptySlot = 0;          // after the cells\' slots
  std::vector<std::int64_t> SlotStart; // per slot (one empty one last), its first point; one extra
  std::vector<std::int64_t> Points;    // point ids by slot
  bool Valid = true;
};

SampleNeighborhoods::SampleNeighborhoods(const CloudPoints& cloud,
  const std::vector<std::int64_t>& sample,
  const double origin[3],
  double cellSize,
  WorkRunner& runner)
  : Cloud(cloud)
  , CellSize(cellSize)
{
  std::copy_n(origin, 3, this->Origin);
  // The cells around the sample points, a slot each; keys are compared, so
  // a collision of hashes costs a probe, never a wrong cell.
  std::vector<std::uint64_t> keys;
  for (const std::int64_t i : sample)
  {
    const std::array<std::int64_t, 3> cell = this->CellOf(&cloud.Coordinates[3 * i]);
    for (int k = 0; k < 3; ++k)
    {
      this->Valid = this->Valid && std::llabs(cell[k]) < Limit - 2;
    }
    for (std::int64_t dz = -1; dz <= 1; ++dz)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dx = -1; dx <= 1; ++dx)
        {
          keys.push_back(Key({ { cell[0] + dx, cell[1] + dy, cell[2] + dz } }));
        }
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  this->BuildTable(keys);
  // Every point's slot (the last, empty one when it is near no sample
  // point), then the points by slot.
  this->SortPointsBySlot(keys.size(), runner);
}

void SampleNeighborhoods::BuildTable(const std::vector<std::uint64_t>& keys)
{
  std::uint64_t size = 64;
  while (size < 4 * keys.size())
  {
    size *= 2;
  }
  this->Mask = size - 1;
  this->EmptySlot = static_cast<std::int64_t>(keys.size());
  this->TableKey.assign(size, 0);
  this->TableSlot.assign(size, -1);
  for (std::size_t slot = 0; slot < keys.size(); ++slot)
  {
    std::uint64_t h = keys[slot] & this->Mask;
    while (this->TableSlot[h] >= 0)
    {
      h = (h + 1) & this->Mask;
    }
    this->TableKey[h] = keys[slot];
    this->TableSlot[h] = static_cast<std::int64_t>(slot);
  }
}

void SampleNeighborhoods::SortPointsBySlot(std::size_t cells, WorkRunner& runner)
{
  const std::int64_t n = this->Cloud.GetNumberOfPoints();
  const std::int64_t slots = static_cast<std::int64_t>(cells) + 1;
  std::vector<std::int32_t> slotOf(n);
  runner.For(n,
    65536,
    [&](std::int64_t begin, std::int64_t end)
    {
      for (std::int64_t i = begin; i < end; ++i)
      {
        slotOf[i] =
          static_cast<std::int32_t>(this->Find(Key(this->CellOf(&this->Cloud.Coordinates[3 * i]))));
      }
    });
  this->SlotStart.assign(slots + 1, 0);
  for (std::int64_t i = 0; i < n; ++i)
  {
    ++this->SlotStart[slotOf[i] + 1];
  }
  this->SlotStart[slots] = 0; // the empty slot keeps no point
  for (std::int64_t slot = 0; slot < slots; ++slot)
  {
    this->SlotStart[slot + 1] += this->SlotStart[slot];
  }
  std::vector<std::int64_t> next(this->SlotStart.begin(), this->SlotStart.end() - 1);
  this->Points.resize(static_cast<std::size_t>(this->SlotStart[slots]));
  for (std::int64_t i = 0; i < n; ++i)
  {
    if (slotOf[i] != this->EmptySlot)
    {
      this->Points[next[slotOf[i]]++] = i;
    }
  }
}

std::int64_t SampleNeighborhoods::Work(const std::vector<std::int64_t>& sample) const
{
  std::int64_t work = 0;
  for (const std::int64_t i : sample)
  {
    const std::array<std::int64_t, 3> cell = this->CellOf(&this->Cloud.Coordinates[3 * i]);
    for (std::int64_t dz = -1; dz <= 1; ++dz)
      for (std::int64_t dy = -1; dy <= 1; ++dy)
        for (std::int64_t dx = -1; dx <= 1; ++dx)
        {
          const std::int64_t slot =
            this->Find(Key({ { cell[0] + dx, cell[1] + dy, cell[2] + dz } }));
          work += this->SlotStart[slot + 1] - this->SlotStart[slot];
        }
  }
  return work;
}

/// The own points of the cloud in InSpacingSample's sample, in order.
std::vector<std::int64_t> SpacingSample(const CloudPoints& cloud,
  const double* lower,
  const double* upper,
  std::int64_t stride,
  WorkRunner& runner)
{
  std::vector<unsigned char> sampled(cloud.NumberOfOwnPoints);
  runner.For(cloud.NumberOfOwnPoints,
    65536,
    [&](std::int64_t begin, std::int64_t end)
    {
      for (std::int64_t i = begin; i < end; ++i)
      {
        sampled[i] = InSpacingSample(&cloud.Coordinates[3 * i], lower, upper, stride);
      }
    });
  std::vector<std::int64_t> sample;
  for (std::int64_t i = 0; i < cloud.NumberOfOwnPoints; ++i)
  {
    if (sampled[i])
    {
      sample.push_back(i);
    }
  }
  return sample;
}

} // namespace

/// TypicalRadius(cloud, alone, boxes, k) (CloudStatistics.cxx) without its
/// grid over the whole cloud, which took as long as a tenth of the normals:
/// the same sample (InSpacingSample), the same exact distances to the
/// (k + 1)-th nearest point, the same median; the neighbors of the ~512
/// sample points found in one parallel pass (SampleNeighborhoods). False
/// where it cannot vouch for the value (a sample point whose k nearest lie
/// beyond the cells searched, few points, a cloud far from a surface): the
/// caller then calls TypicalRadius itself.
bool QuickTypicalRadius(const CloudPoints& cloud,
  const CloudBoxes& boxes,
  int k,
  WorkRunner& runner,
  double& radius)
{
  const std::int64_t count = boxes.BodyCount;
  const std::int64_t searched = cloud.GetNumberOfPoints();
  if (count < 2 || searched <= k + 1)
  {
    return false;
  }
  const std::int64_t stride = std::max<std::int64_t>(1, count / 512);
  const double* lower = boxes.Lower.data();
  const double* upper = boxes.Upper.data();
  const std::vector<std::int64_t> sample = SpacingSample(cloud, lower, upper, stride, runner);
  if (sample.empty())
  {
    return false;
  }
  // Cells of twice TypicalRadius's first guess (a surface as wide as the
  // sampling box's diagonal): for a surface, the sample points' k nearest
  // lie within 0.9 cells.
  double diagonal = 0.0;
  for (int axis = 0; axis < 3; ++axis)
  {
    diagonal += (upper[axis] - lower[axis]) * (upper[axis] - lower[axis]);
  }
  const double cellSize =
    2.0 * std::sqrt(diagonal) * std::sqrt(k / (3.14159265358979323846 * count));
  if (!(cellSize > 0.0) || !std::isfinite(cellSize))
  {
    return false;
  }
  const SampleNeighborhoods near(cloud, sample, lower, cellSize, runner);
  // Beyond a few times the points a surface puts there, the cells are
  // wrong for this cloud: TypicalRadius's grid does better.
  if (!near.Usable() || near.Work(sample) > 64 * static_cast<std::int64_t>(sample.size()) * (k + 1))
  {
    return false;
  }
  const double reach = 0.9 * cellSize;
  std::vector<double> radii, squared;
  for (const std::int64_t i : sample)
  {
    const double* x = &cloud.Coordinates[3 * i];
    squared.clear();
    near.ForEachNear(x,
      [&](const double* q)
      {
        const double dx = q[0] - x[0], dy = q[1] - x[1], dz = q[2] - x[2];
        squared.push_back(dx * dx + dy * dy + dz * dz);
      });
    if (static_cast<std::int64_t>(squared.size()) < k + 1)
    {
      return false;
    }
    std::nth_element(squared.begin(), squared.begin() + k, squared.end());
    if (!(squared[k] < reach * reach))
    {
      return false;
    }
    radii.push_back(std::sqrt(squared[k]));
  }
  std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
  radius = radii[radii.size() / 2];
  return true;
}

} // namespace normals
} // namespace pcurv
