#include "Lines/LineCloud.h"

#include "Cloud/Collectives.h"
#include "Cloud/Halo.h"
#include "Lines/LineDerivatives.h"
#include "Neighbors/PointGrid.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>

namespace pcurv
{
namespace
{
/// A point's record in the halo: x y z, normal, k_max, k_min, d_max,
/// standard error, radius, valid.
constexpr int RecordWidth = 14;
/// A crossing's: position, tangent, curvature, edge length, kind.
constexpr int CrossingWidth = 9;

std::uint64_t Bits(double value)
{
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

/// Records ordered by their first three values (coordinates), then by
/// every value's bits: a total order of distinct records.
bool RecordPrecedes(const double* a, const double* b, int width)
{
  for (int k = 0; k < 3; ++k)
  {
    if (a[k] != b[k])
    {
      return a[k] < b[k];
    }
  }
  for (int k = 0; k < width; ++k)
  {
    if (Bits(a[k]) != Bits(b[k]))
    {
      return Bits(a[k]) < Bits(b[k]);
    }
  }
  return false;
}

/// A hash of a point's coordinates (splitmix64 of their bits).
std::uint64_t SampleHash(const double* x)
{
  std::uint64_t h = 0;
  for (int k = 0; k < 3; ++k)
  {
    h ^= Bits(x[k]) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    h ^= h >> 30;
    h *= 0xbf58476d1ce4e5b9ULL;
    h ^= h >> 27;
    h *= 0x94d049bb133111ebULL;
    h ^= h >> 31;
  }
  return h;
}

void OwnRecord(const LineInput& in, std::int64_t i, double* r)
{
  std::copy_n(in.Points + 3 * i, 3, r);
  std::copy_n(in.Normals + 3 * i, 3, r + 3);
  r[6] = in.MaximumCurvature[i];
  r[7] = in.MinimumCurvature[i];
  std::copy_n(in.MaximumDirection + 3 * i, 3, r + 8);
  r[11] = in.StandardError ? in.StandardError[i] : 0.0;
  r[12] = in.Radius ? in.Radius[i] : 0.0;
  r[13] = !in.Valid || in.Valid[i] ? 1.0 : 0.0;
}

/// The own points of `own`, then the halo's records, as one list.
class PointSource
{
public:
  PointSource(const LineInput& own, const std::vector<double>& halo)
    : Own(own)
    , Halo(halo)
  {
  }
  std::int64_t Size() const
  {
    return this->Own.Count + static_cast<std::int64_t>(this->Halo.size() / RecordWidth);
  }
  const double* Position(std::int64_t i) const
  {
    return i < this->Own.Count ? this->Own.Points + 3 * i
                               : &this->Halo[RecordWidth * (i - this->Own.Count)];
  }
  void Record(std::int64_t i, double* record) const
  {
    if (i < this->Own.Count)
    {
      OwnRecord(this->Own, i, record);
    }
    else
    {
      std::copy_n(&this->Halo[RecordWidth * (i - this->Own.Count)], RecordWidth, record);
    }
  }
  /// By coordinates, then (points at one place, rare) by their records.
  bool Precedes(std::int64_t a, std::int64_t b) const
  {
    const double* p = this->Position(a);
    const double* q = this->Position(b);
    if (p[0] != q[0] || p[1] != q[1] || p[2] != q[2])
    {
      return RecordPrecedes(p, q, 3);
    }
    double ra[RecordWidth], rb[RecordWidth];
    this->Record(a, ra);
    this->Record(b, rb);
    return RecordPrecedes(ra, rb, RecordWidth);
  }

private:
  const LineInput& Own;
  const std::vector<double>& Halo;
};

/// The points of `source` as a cloud, sorted.
LineCloud SortedCloud(const PointSource& source, std::int64_t own)
{
  const std::int64_t n = source.Size();
  std::vector<std::int64_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(),
    order.end(),
    [&](std::int64_t a, std::int64_t b) { return source.Precedes(a, b); });
  LineCloud cloud;
  cloud.Count = n;
  cloud.Points.reserve(3 * n);
  cloud.Normals.reserve(3 * n);
  cloud.MaximumDirection.reserve(3 * n);
  double r[RecordWidth];
  for (const std::int64_t i : order)
  {
    source.Record(i, r);
    cloud.Points.insert(cloud.Points.end(), r, r + 3);
    cloud.Normals.insert(cloud.Normals.end(), r + 3, r + 6);
    cloud.MaximumCurvature.push_back(r[6]);
    cloud.MinimumCurvature.push_back(r[7]);
    cloud.MaximumDirection.insert(cloud.MaximumDirection.end(), r + 8, r + 11);
    cloud.StandardError.push_back(r[11]);
    cloud.Radius.push_back(r[12]);
    cloud.Valid.push_back(r[13] != 0.0 ? 1 : 0);
    cloud.Owned.push_back(i < own ? 1 : 0);
  }
  return cloud;
}

/// The lattice every process makes alike: global bounds and count, cells
/// of the median radius (or, without radii, about RadiusNeighbors points'
/// reach).
GridLattice CommonLattice(const LineInput& own,
  const LineSettings& settings,
  bool hasRadius,
  std::int64_t globalCount,
  const Collectives& processes,
  double& sampledRadius)
{
  double lower[3], upper[3];
  for (int k = 0; k < 3; ++k)
  {
    lower[k] = std::numeric_limits<double>::infinity();
    upper[k] = -std::numeric_limits<double>::infinity();
  }
  for (std::int64_t i = 0; i < own.Count; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      lower[k] = std::min(lower[k], own.Points[3 * i + k]);
      upper[k] = std::max(upper[k], own.Points[3 * i + k]);
    }
  }
  processes.Bounds(lower, upper);
  double cell = 0.0;
  if (hasRadius)
  {
    std::vector<double> radii;
    // A sample of about a thousand radii, chosen by the points' coordinates
    // (not their order): the same whatever the split.
    const std::uint64_t every =
      static_cast<std::uint64_t>(std::max<std::int64_t>(1, globalCount / 1000));
    for (std::int64_t i = 0; i < own.Count; ++i)
    {
      if (SampleHash(own.Points + 3 * i) % every == 0 && own.Radius[i] > 0.0 &&
        std::isfinite(own.Radius[i]))
      {
        radii.push_back(own.Radius[i]);
      }
    }
    cell = GlobalMedian(std::move(radii), processes);
  }
  sampledRadius = cell;
  if (!(cell > 0.0))
  {
    double diagonal = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      diagonal += (upper[k] - lower[k]) * (upper[k] - lower[k]);
    }
    cell = std::sqrt(diagonal) *
        std::sqrt(
          settings.RadiusNeighbors / static_cast<double>(std::max<std::int64_t>(1, globalCount))) +
      1e-300;
  }
  return GridLattice::Make(lower, upper, std::max<std::int64_t>(1, globalCount), cell);
}

/// The largest neighborhood radius of any process's points (an upper bound
/// where the radii are not given: the distance to the RadiusNeighbors-th
/// nearest own point, infinite on a process with fewer points).
/// The largest fit radius of the own points (GrownFitRadius), at least:
/// their graph reach is measured among the own points alone, which can
/// only lengthen it.
double LargestFitRadius(const LineInput& own,
  const LineSettings& settings,
  bool hasRadius,
  const GridLattice& lattice,
  const Collectives& processes)
{
  double largest = 0.0;
  if (own.Count > std::max(settings.RadiusNeighbors, settings.GraphNeighbors))
  {
    PointGrid grid;
    grid.Build(own.Points, own.Count, lattice);
    std::vector<double> scratch;
    for (std::int64_t i = 0; i < own.Count; ++i)
    {
      const double* x = own.Points + 3 * i;
      const double radius = hasRadius
        ? own.Radius[i]
        : std::sqrt(grid.SquaredDistanceToKth(x, settings.RadiusNeighbors, scratch));
      const double graphReach =
        std::sqrt(grid.SquaredDistanceToKth(x, settings.GraphNeighbors + 1, scratch));
      const double fit = GrownFitRadius(radius * settings.FitRadius, graphReach, settings);
      if (std::isfinite(fit))
      {
        largest = std::max(largest, fit);
      }
    }
  }
  else if (own.Count > 0)
  {
    largest = std::numeric_limits<double>::infinity();
  }
  return processes.Max(largest);
}

} // namespace

LineInput LineCloud::AsInput() const
{
  LineInput in;
  in.Count = this->Count;
  in.Points = this->Points.data();
  in.Normals = this->Normals.data();
  in.MaximumCurvature = this->MaximumCurvature.data();
  in.MinimumCurvature = this->MinimumCurvature.data();
  in.MaximumDirection = this->MaximumDirection.data();
  in.StandardError = this->StandardError.data();
  in.Radius = this->HasRadius ? this->Radius.data() : nullptr;
  in.Valid = this->Valid.data();
  in.Owned = this->Distributed ? this->Owned.data() : nullptr;
  return in;
}

LineCloud GatherLineCloud(const LineInput& own,
  const LineSettings& settings,
  const Collectives& processes)
{
  // A process without points has no say on which arrays the points have.
  const bool hasRadius = processes.Min(own.Radius || own.Count == 0 ? 1 : 0) == 1;
  const std::int64_t globalCount = processes.Sum(own.Count);
  double sampledRadius = 0.0;
  const GridLattice lattice =
    CommonLattice(own, settings, hasRadius, globalCount, processes, sampledRadius);
  std::vector<double> halo;
  if (processes.IsDistributed())
  {
    // An own point and its graph neighbors (within a fit radius R) blend
    // the fits of the anchors within R / 2; an anchor fits the points
    // within R of it and is chosen among the points of its cell, each
    // with its graph row; and the grid's cells those queries visit must
    // be whole.
    const double radius = LargestFitRadius(own, settings, hasRadius, lattice, processes);
    const double cells = settings.AnchorSpacing * radius + lattice.CellSize;
    const double reach = (3.0 * radius + std::sqrt(3.0) * cells) * (1.0 + 1e-9);
    halo = ExchangeHaloRecords(
      own.Count,
      RecordWidth,
      [&](std::int64_t i, double* record) { OwnRecord(own, i, record); },
      processes,
      reach);
  }
  LineCloud cloud = SortedCloud(PointSource(own, halo), own.Count);
  cloud.HasRadius = hasRadius;
  cloud.Distributed = processes.IsDistributed();
  cloud.Lattice = lattice;
  cloud.GlobalCount = globalCount;
  cloud.SampledRadius = sampledRadius;
  return cloud;
}

GraphScale MeasureGraphScale(const LineCloud& cloud,
  const LineSettings& settings,
  const Collectives& processes,
  WorkRunner* runner)
{
  PointGrid grid;
  if (cloud.Count > 0)
  {
    grid.Build(cloud.Points.data(), cloud.Count, cloud.Lattice, runner);
  }
  const std::uint64_t every =
    static_cast<std::uint64_t>(std::max<std::int64_t>(1, cloud.GlobalCount / 1000));
  std::vector<double> graph, radii, scratch;
  for (std::int64_t i = 0; i < cloud.Count; ++i)
  {
    const double* x = &cloud.Points[3 * i];
    if (!cloud.Owned[i] || SampleHash(x) % every != 0)
    {
      continue;
    }
    graph.push_back(grid.SquaredDistanceToKth(x, settings.GraphNeighbors + 1, scratch));
    if (!cloud.HasRadius)
    {
      radii.push_back(std::sqrt(grid.SquaredDistanceToKth(x, settings.RadiusNeighbors, scratch)));
    }
  }
  GraphScale scale;
  scale.TypicalRadius =
    cloud.HasRadius ? cloud.SampledRadius : GlobalMedian(std::move(radii), processes);
  scale.Lattice = cloud.Lattice;
  const double cell = 1.5 * std::sqrt(GlobalMedian(std::move(graph), processes));
  if (cell > 0.0 && cell < cloud.Lattice.CellSize)
  {
    double lower[3], upper[3];
    for (int k = 0; k < 3; ++k)
    {
      lower[k] = cloud.Lattice.Origin[k];
      upper[k] =
        cloud.Lattice.Origin[k] + (cloud.Lattice.LastCell[k] + 1.0) * cloud.Lattice.CellSize;
    }
    scale.Lattice =
      GridLattice::Make(lower, upper, std::max<std::int64_t>(1, cloud.GlobalCount), cell);
  }
  return scale;
}

double GlobalMedian(std::vector<double> values, const Collectives& processes)
{
  if (!processes.IsDistributed())
  {
    if (values.empty())
    {
      return 0.0;
    }
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    return values[values.size() / 2];
  }
  const std::int64_t total = processes.Sum(static_cast<std::int64_t>(values.size()));
  if (total == 0)
  {
    return 0.0;
  }
  // Nonnegative doubles order as their bits do: the median's bits, a byte
  // at a time from the top, each from a histogram of the values that
  // share the bytes found so far (eight collective steps).
  std::vector<std::uint64_t> bits(values.size());
  std::transform(values.begin(), values.end(), bits.begin(), Bits);
  std::int64_t rank = total / 2; // among the values sharing `low`'s top bytes
  std::uint64_t low = 0;
  for (int shift = 56; shift >= 0; shift -= 8)
  {
    std::vector<std::int64_t> histogram(256, 0);
    for (const std::uint64_t b : bits)
    {
      if (shift == 56 || (b >> (shift + 8)) == (low >> (shift + 8)))
      {
        ++histogram[(b >> shift) & 0xff];
      }
    }
    processes.Sum(histogram);
    int bucket = 0;
    while (rank >= histogram[bucket])
    {
      rank -= histogram[bucket++];
    }
    low |= static_cast<std::uint64_t>(bucket) << shift;
  }
  double median;
  std::memcpy(&median, &low, sizeof median);
  return median;
}

std::vector<LineCrossing> GatherCrossings(const std::vector<LineCrossing>& own,
  const Collectives& processes)
{
  std::vector<double> records;
  records.reserve(CrossingWidth * own.size());
  for (const LineCrossing& c : own)
  {
    records.insert(records.end(), c.Position.begin(), c.Position.end());
    records.insert(records.end(), c.Tangent.begin(), c.Tangent.end());
    records.push_back(c.Curvature);
    records.push_back(c.EdgeLength);
    records.push_back(static_cast<double>(c.Kind));
  }
  const std::vector<double> all = processes.Gather(records);
  const std::size_t n = all.size() / CrossingWidth;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(),
    order.end(),
    [&](std::size_t a, std::size_t b)
    { return RecordPrecedes(&all[CrossingWidth * a], &all[CrossingWidth * b], CrossingWidth); });
  std::vector<LineCrossing> crossings(n);
  for (std::size_t j = 0; j < n; ++j)
  {
    const double* r = &all[CrossingWidth * order[j]];
    LineCrossing& c = crossings[j];
    std::copy_n(r, 3, c.Position.begin());
    std::copy_n(r + 3, 3, c.Tangent.begin());
    c.Curvature = r[6];
    c.EdgeLength = r[7];
    c.Kind = static_cast<LineKind>(static_cast<int>(r[8]));
  }
  return crossings;
}

} // namespace pcurv
