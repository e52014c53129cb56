#include "Cloud/CloudStatistics.h"
#include "Cloud/Halo.h"
#include "Common/Hash.h"
#include "Neighbors/PointGrid.h"

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
constexpr double Pi = 3.141592653589793;

double SquaredDistance(const double a[3], const double b[3])
{
  double squared = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    squared += (a[k] - b[k]) * (a[k] - b[k]);
  }
  return squared;
}

/// Octave bins of signed values: 0 for zero, +-(1 + OctaveOffset + floor(16
/// log2 |x|)) for others, so a bin spans 2^(1/16) of magnitude over the whole
/// double range.
constexpr int BinsPerOctave = 16;
constexpr int OctaveOffset = 1075 * BinsPerOctave;
constexpr int LargestOctaveBin = OctaveOffset + 1025 * BinsPerOctave;

int OctaveBin(double magnitude)
{
  if (!(magnitude > 0.0))
  {
    return 0;
  }
  const int bin =
    1 + OctaveOffset + static_cast<int>(std::floor(BinsPerOctave * std::log2(magnitude)));
  return std::min(std::max(bin, 1), LargestOctaveBin);
}

/// The magnitude at the upper edge of octave bin `bin` (0 for bin 0).
double OctaveEdge(int bin)
{
  return bin <= 0 ? 0.0
                  : std::min(std::exp2(static_cast<double>(bin - OctaveOffset) / BinsPerOctave),
                      std::numeric_limits<double>::max());
}

int SignedOctaveBin(double x)
{
  return x < 0.0 ? -OctaveBin(-x) : OctaveBin(x);
}

/// Narrows [lower, upper] along `axis` to signed octave bins that hold the
/// points of ranks `firstRank` and `lastRank` (with a bin to spare on each
/// side, against log2's rounding), in one pass: however far a stray lies,
/// the linear zoom then starts within a few octaves of the central points.
void BracketCentralPoints(const CloudPoints& cloud,
  const Collectives& processes,
  int axis,
  std::int64_t firstRank,
  std::int64_t lastRank,
  double& lower,
  double& upper)
{
  std::vector<std::int64_t> counts(2 * LargestOctaveBin + 1, 0);
  for (std::int64_t i = 0; i < cloud.NumberOfOwnPoints; ++i)
  {
    const double x = cloud.Coordinates[3 * i + axis];
    if (x >= lower && x <= upper)
    {
      ++counts[LargestOctaveBin + SignedOctaveBin(x)];
    }
  }
  processes.Sum(counts);
  int first = 0, last = 0;
  std::int64_t cumulative = 0;
  for (int key = -LargestOctaveBin; key <= LargestOctaveBin; ++key)
  {
    const std::int64_t next = cumulative + counts[LargestOctaveBin + key];
    first = cumulative <= firstRank && firstRank < next ? key : first;
    last = cumulative <= lastRank && lastRank < next ? key : last;
    cumulative = next;
  }
  // A bin's lower edge is the next one's upper edge, towards minus infinity.
  const int below = first - 1;
  const int above = last + 1;
  lower = std::max(lower, below > 0 ? OctaveEdge(below - 1) : -OctaveEdge(-below));
  upper = std::min(upper, above >= 0 ? OctaveEdge(above) : -OctaveEdge(-above - 1));
}

/// Narrows [lower, upper] per axis to the range of the central 98 % of the
/// own points of all processes, to within 1/64 of that range (or of a few
/// subnormal steps): the body of the cloud, whatever its far points.
void ZoomOntoCentralPoints(const CloudPoints& cloud,
  const Collectives& processes,
  double lower[3],
  double upper[3])
{
  const std::int64_t total = processes.Sum(cloud.NumberOfOwnPoints);
  // 0-based ranks, in coordinate order, of the points at 1 % and 99 %.
  const std::int64_t firstRank = total / 100;
  const std::int64_t lastRank = total - 1 - total / 100;
  constexpr int Bins = 1024;
  constexpr int EnoughBins = 64; // the central points span 64 of 1024 bins: fine enough
  // A level narrows the range at least 16-fold (64 of 1024 bins); this
  // only guards against a range that stops shrinking.
  constexpr int MaximumLevels = 1100;
  for (int axis = 0; axis < 3 && total > 0; ++axis)
  {
    for (int level = 0; level < MaximumLevels && upper[axis] > lower[axis]; ++level)
    {
      if (level == 1)
      {
        // The first level did not find the central points spread wide: far
        // strays squeeze them. Jump to their octaves instead of zooming
        // 16-fold a level at a time (most clouds never get here).
        BracketCentralPoints(cloud, processes, axis, firstRank, lastRank, lower[axis], upper[axis]);
      }
      const double low = lower[axis];
      // In halves: the range of coordinates of opposite signs can overflow.
      const double halfWidth = (0.5 * upper[axis] - 0.5 * low) / Bins;
      if (!(halfWidth > 0.0))
      {
        break; // a range of a few subnormal steps: nothing left to zoom into
      }
      // Bins, then the count of points below the range.
      std::vector<std::int64_t> counts(Bins + 1, 0);
      for (std::int64_t i = 0; i < cloud.NumberOfOwnPoints; ++i)
      {
        const double x = cloud.Coordinates[3 * i + axis];
        if (x >= low && x <= upper[axis])
        {
          const double bin = std::floor((0.5 * x - 0.5 * low) / halfWidth);
          ++counts[static_cast<int>(std::min(std::max(bin, 0.0), Bins - 1.0))];
        }
        counts[Bins] += x < low ? 1 : 0;
      }
      processes.Sum(counts);
      int firstBin = -1, lastBin = -1;
      std::int64_t cumulative = counts[Bins];
      for (int b = 0; b < Bins && lastBin < 0; ++b)
      {
        if (firstBin < 0 && cumulative + counts[b] > firstRank)
        {
          firstBin = b;
        }
        if (cumulative + counts[b] > lastRank)
        {
          lastBin = b;
        }
        cumulative += counts[b];
      }
      if (firstBin < 0 || lastBin < 0)
      {
        break;
      }
      const double newUpper = lastBin + 1 < Bins
        ? low + (lastBin + 1) * halfWidth + (lastBin + 1) * halfWidth
        : upper[axis];
      lower[axis] = low + firstBin * halfWidth + firstBin * halfWidth;
      upper[axis] = newUpper;
      if (lastBin - firstBin >= EnoughBins)
      {
        break;
      }
    }
  }
}

/// How far beyond the body of the cloud, in the body's largest extent, a
/// point may lie and still count in the boxes: farther ones are strays (a
/// "missing value" sentinel, a point of another scan) that must change
/// nothing for the others. Far enough that a tower over a flat tile, or the
/// sparse tails of a real cloud, are part of the body.
constexpr double StrayDistance = 8.0;

/// The bounds of the own points of all processes that lie within
/// StrayDistance body extents of the body [bodyLower, bodyUpper] on every
/// axis, and how many they are.
std::int64_t BoundsWithoutStrays(const CloudPoints& cloud,
  const Collectives& processes,
  const double bodyLower[3],
  const double bodyUpper[3],
  double lower[3],
  double upper[3])
{
  double extent = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    // In halves: the extent of a body of huge coordinates stays finite.
    extent = std::max(extent, 0.5 * bodyUpper[k] - 0.5 * bodyLower[k]);
  }
  const double reach = 2.0 * StrayDistance * extent;
  double nearLower[3], nearUpper[3];
  for (int k = 0; k < 3; ++k)
  {
    nearLower[k] = bodyLower[k] - reach;
    nearUpper[k] = bodyUpper[k] + reach;
    lower[k] = HUGE_VAL;
    upper[k] = -HUGE_VAL;
  }
  std::int64_t count = 0;
  for (std::int64_t i = 0; i < cloud.NumberOfOwnPoints; ++i)
  {
    const double* x = &cloud.Coordinates[3 * i];
    bool near = true;
    for (int k = 0; k < 3; ++k)
    {
      near = near && x[k] >= nearLower[k] && x[k] <= nearUpper[k];
    }
    if (near)
    {
      ++count;
      for (int k = 0; k < 3; ++k)
      {
        lower[k] = std::min(lower[k], x[k]);
        upper[k] = std::max(upper[k], x[k]);
      }
    }
  }
  processes.Bounds(lower, upper);
  return processes.Sum(count);
}

/// MagnitudeQuantile of the `count` values value(0) ... value(count - 1).
template<typename Value>
double QuantileOfMagnitudes(Value value,
  std::int64_t count,
  double quantile,
  const Collectives& processes)
{
  constexpr int Bins = LargestOctaveBin + 1;
  std::vector<std::int64_t> histogram(Bins, 0);
  for (std::int64_t i = 0; i < count; ++i)
  {
    const double magnitude = std::fabs(value(i));
    if (std::isfinite(magnitude))
    {
      ++histogram[OctaveBin(magnitude)];
    }
  }
  if (processes.IsDistributed())
  {
    processes.Sum(histogram);
  }
  std::int64_t total = 0;
  for (const std::int64_t n : histogram)
  {
    total += n;
  }
  if (total == 0)
  {
    return 0.0;
  }
  const double wanted = std::min(std::max(quantile, 0.0), 1.0) * static_cast<double>(total);
  std::int64_t below = 0;
  for (int bin = 0; bin < Bins; ++bin)
  {
    below += histogram[bin];
    if (static_cast<double>(below) >= wanted && below > 0)
    {
      return OctaveEdge(bin);
    }
  }
  return std::numeric_limits<double>::max();
}

} // namespace

namespace
{
/// How far from a whole multiple of a step, in steps, a coordinate's
/// offset may lie and still be on the step's lattice: rounding leaves far
/// less, a value off the lattice is this close by chance once in 500.
constexpr double LatticeSlack = 1e-3;

/// The greatest common step of two lengths a >= b >= 0 (of a and 0: a): the
/// first divisor that leaves a remainder within LatticeSlack of itself
/// (symmetric remainders: each at most half its divisor); at most
/// `smallest` where the divisors fall that far first (no common step).
double CommonStep(double a, double b, double smallest)
{
  if (b == 0.0)
  {
    return a;
  }
  while (b > smallest)
  {
    const double remainder = std::fabs(a - std::nearbyint(a / b) * b);
    if (remainder <= LatticeSlack * b)
    {
      return b;
    }
    a = b;
    b = remainder;
  }
  return b;
}

/// One axis's lattice step so far (LocalSteps).
struct AxisStep
{
  double Step = 0.0;
  /// The largest offset known to be a multiple of Step.
  double Largest = 0.0;

  /// Takes an offset `d` between neighbors (0 < d <= the reach): Step
  /// stays if d is a multiple of it (made again from d when d is the
  /// largest such: each division multiplies the offsets' rounding by its
  /// quotient, and Step's error is then d's rounding over the multiple),
  /// else becomes the two's common step. False once Step is at most
  /// `smallest`: no lattice.
  bool Take(double d, double smallest)
  {
    const double multiple = this->Step > 0.0 ? std::nearbyint(d / this->Step) : 0.0;
    if (multiple > 0.0 && std::fabs(d / this->Step - multiple) <= LatticeSlack)
    {
      if (d > this->Largest)
      {
        this->Largest = d;
        this->Step = d / multiple;
      }
      return true;
    }
    this->Step = CommonStep(std::max(this->Step, d), std::min(this->Step, d), smallest);
    if (this->Step <= smallest)
    {
      return false;
    }
    this->Largest = d;
    this->Step = d / std::nearbyint(d / this->Step);
    return true;
  }
};

/// The lattice steps of the own coordinates: per axis, the common step of
/// the offsets between points next to each other in the grid's cell order
/// that are no farther apart than `reach` (few steps); 0 where there is
/// none to take, at most `smallest` where there is no lattice. One pass
/// for the three axes, which stops at the first axis without a lattice
/// (the cloud then has none).
std::array<double, 3> LocalSteps(const CloudPoints& cloud,
  const PointGrid& grid,
  double reach,
  const double smallest[3])
{
  std::array<AxisStep, 3> axes;
  const double* previous = nullptr;
  for (std::int64_t j = 0; j < grid.GetNumberOfPoints(); ++j)
  {
    const std::int64_t id = grid.GetSortedId(j);
    if (!cloud.IsOwn(id))
    {
      continue;
    }
    const double* x = &cloud.Coordinates[3 * id];
    for (int k = 0; previous && k < 3; ++k)
    {
      const double d = std::fabs(x[k] - previous[k]);
      if (d > 0.0 && d <= reach && !axes[k].Take(d, smallest[k]))
      {
        return { axes[0].Step, axes[1].Step, axes[2].Step };
      }
    }
    previous = x;
  }
  return { axes[0].Step, axes[1].Step, axes[2].Step };
}
} // namespace

std::array<double, 3> CoordinateSteps(const CloudPoints& cloud,
  const PointGrid& grid,
  const Collectives& processes)
{
  double lower[3], upper[3];
  cloud.OwnBounds(lower, upper);
  processes.Bounds(lower, upper);
  double smallest[3];
  bool spread = true;
  for (int k = 0; k < 3; ++k)
  {
    spread = spread && lower[k] < upper[k];
    // An offset is exact to a few units of the last place of the largest
    // coordinate: a finer lattice could not be told from rounding.
    smallest[k] = 1e4 * std::numeric_limits<double>::epsilon() *
      std::max(std::fabs(lower[k]), std::fabs(upper[k]));
  }
  if (!spread)
  {
    return {};
  }
  const std::array<double, 3> local = LocalSteps(cloud, grid, 4.0 * grid.GetCellSize(), smallest);
  const std::vector<double> all = processes.Gather({ local[0], local[1], local[2] });
  std::array<double, 3> steps{};
  for (int k = 0; k < 3; ++k)
  {
    double step = 0.0;
    for (std::size_t p = k; p < all.size(); p += 3)
    {
      if (all[p] > 0.0 && all[p] <= smallest[k])
      {
        return {};
      }
      step = CommonStep(std::max(step, all[p]), std::min(step, all[p]), smallest[k]);
    }
    // The range is a whole multiple of the step: dividing it by that
    // multiple gives the same bits however the points are ordered or
    // split among processes.
    const double range = upper[k] - lower[k];
    const double multiple = step > smallest[k] ? std::nearbyint(range / step) : 0.0;
    if (!(multiple >= 1.0))
    {
      return {};
    }
    steps[k] = range / multiple;
  }
  return steps;
}

double WorkingLengthScale(const CloudPoints& cloud, const Collectives& processes)
{
  // The 99th percentile of the coordinates' magnitudes rather than the
  // largest: a few strays (a 1e300 sentinel) would otherwise shrink every
  // other coordinate until their squared distances underflow. The strays
  // themselves may then overflow a squared distance: they are flagged.
  const double* coordinates = cloud.Coordinates.data();
  const double largest = QuantileOfMagnitudes(
    [&](std::int64_t i) { return coordinates[i]; }, 3 * cloud.NumberOfOwnPoints, 0.99, processes);
  if (!(largest > 0.0) || (largest >= std::ldexp(1.0, -400) && largest <= std::ldexp(1.0, 400)))
  {
    return 1.0;
  }
  int exponent = 0;
  std::frexp(largest, &exponent); // largest = m 2^exponent, m in [0.5, 1)
  // At most 2^1023, the largest power of two a double holds: a subnormal
  // largest coordinate (2^-1074) would ask for 2^1074, which is Inf and made
  // every coordinate Inf or NaN (found by fuzzing); 2^1023 brings it above
  // 2^-400 all the same.
  return std::ldexp(1.0, std::min(1 - exponent, 1023));
}

bool InSpacingSample(const double x[3],
  const double lower[3],
  const double upper[3],
  std::int64_t stride)
{
  std::uint64_t hash = 0;
  for (int k = 0; k < 3; ++k)
  {
    const double extent = upper[k] - lower[k];
    // Points outside the box (far outliers) share the steps -1 and 2^20.
    const double step = extent > 0.0
      ? std::min(std::max(std::floor((x[k] - lower[k]) / extent * 1048576.0), -1.0), 1048576.0)
      : 0.0;
    hash = Mix(hash ^ static_cast<std::uint64_t>(static_cast<std::int64_t>(step)));
  }
  return hash % static_cast<std::uint64_t>(std::max<std::int64_t>(stride, 1)) == 0;
}

CloudBoxes MeasureBoxes(const CloudPoints& cloud, const Collectives& processes)
{
  double bodyLower[3], bodyUpper[3];
  cloud.OwnBounds(bodyLower, bodyUpper);
  processes.Bounds(bodyLower, bodyUpper);
  ZoomOntoCentralPoints(cloud, processes, bodyLower, bodyUpper);
  CloudBoxes boxes;
  boxes.BodyCount = BoundsWithoutStrays(
    cloud, processes, bodyLower, bodyUpper, boxes.Lower.data(), boxes.Upper.data());
  return boxes;
}

GridLattice GlobalLattice(const CloudBoxes& boxes, double radius)
{
  double lower[3], upper[3];
  for (int k = 0; k < 3; ++k)
  {
    lower[k] = boxes.Lower[k];
    upper[k] = boxes.Upper[k];
    if (!(lower[k] <= upper[k]))
    {
      lower[k] = upper[k] = 0.0; // no point anywhere
    }
  }
  return GridLattice::Make(lower, upper, boxes.BodyCount, 0.5 * radius);
}

double TypicalRadius(const CloudPoints& cloud,
  const Collectives& processes,
  const CloudBoxes& boxes,
  int k,
  WorkRunner* runner)
{
  const std::int64_t count = boxes.BodyCount;
  if (count < 2)
  {
    return 0.0;
  }
  // About 512 sample points whatever the size of the cloud.
  const std::int64_t stride = std::max<std::int64_t>(1, count / 512);
  const double* lower = boxes.Lower.data();
  const double* upper = boxes.Upper.data();
  const double diagonal = std::sqrt(SquaredDistance(lower, upper));
  // Cells for a first guess: the points spread over a square as wide as
  // the box's diagonal.
  const double guess = diagonal * std::sqrt(k / (Pi * count));
  const GridLattice lattice = GridLattice::Make(lower, upper, count, 0.5 * guess);

  std::vector<std::int64_t> sample;
  for (std::int64_t i = 0; i < cloud.NumberOfOwnPoints; ++i)
  {
    if (InSpacingSample(&cloud.Coordinates[3 * i], lower, upper, stride))
    {
      sample.push_back(i);
    }
  }
  PointGrid grid;
  std::vector<double> scratch;
  auto sampleRadii = [&](const CloudPoints& searched)
  {
    grid.Build(searched.Coordinates.data(), searched.GetNumberOfPoints(), lattice, runner);
    std::vector<double> radii;
    for (const std::int64_t i : sample)
    {
      // k + 1: the sample point itself is among the points found.
      radii.push_back(
        std::sqrt(grid.SquaredDistanceToKth(&searched.Coordinates[3 * i], k + 1, scratch)));
    }
    return radii;
  };
  std::vector<double> radii;
  if (processes.IsDistributed())
  {
    // Radii from this process's points alone can only be too large: reach
    // that far into the other pieces, then measure again.
    CloudPoints withHalo = cloud;
    withHalo.DropHalo();
    const std::vector<double> bounds = sampleRadii(withHalo);
    const double reach =
      processes.Max(bounds.empty() ? 0.0 : *std::max_element(bounds.begin(), bounds.end()));
    ExchangeHalo(withHalo, processes, reach);
    radii = processes.Gather(sampleRadii(withHalo));
  }
  else
  {
    radii = processes.Gather(sampleRadii(cloud));
  }
  if (radii.empty())
  {
    return 0.0;
  }
  std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
  return radii[radii.size() / 2];
}

double LargestLocalKthDistance(const CloudPoints& cloud, const GridLattice& lattice, int k)
{
  PointGrid grid;
  grid.Build(cloud.Coordinates.data(), cloud.NumberOfOwnPoints, lattice);
  std::vector<double> scratch;
  double largest = 0.0;
  for (std::int64_t i = 0; i < cloud.NumberOfOwnPoints; ++i)
  {
    largest =
      std::max(largest, grid.SquaredDistanceToKth(&cloud.Coordinates[3 * i], k + 1, scratch));
  }
  return std::nextafter(std::sqrt(largest), HUGE_VAL);
}

double MagnitudeQuantile(const RealBuffer& values,
  std::int64_t count,
  double quantile,
  const Collectives& processes)
{
  return QuantileOfMagnitudes(
    [&](std::int64_t i) { return values.Get(i); }, count, quantile, processes);
}

} // namespace pcurv
