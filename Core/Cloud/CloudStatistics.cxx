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

/// Narrows [lower, upper] per axis to the range of the central 98 % of the
/// own points of all processes (see CloudBoxes::SampleLower).
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
  constexpr int EnoughBins = 64; // the central points span 64 of 1024 bins: no zoom
  // A level that zooms narrows the range at least 16-fold (64 of 1024
  // bins), so even a range from the largest double down to a subnormal
  // step takes fewer levels than this; it only guards against a range that
  // stops shrinking. A smaller cap would leave the box of a cloud with one
  // far point (a 1e110 "missing value" sentinel) about as wide as that
  // point's distance: the grid over it then puts every real point in one
  // cell, and each neighbor query reads them all.
  constexpr int MaximumLevels = 1100;
  for (int axis = 0; axis < 3; ++axis)
  {
    std::int64_t below = 0; // points below lower[axis]
    for (int level = 0; level < MaximumLevels && upper[axis] > lower[axis]; ++level)
    {
      const double low = lower[axis];
      const double width = (upper[axis] - low) / Bins;
      if (!(width > 0.0))
      {
        break; // a range of a few subnormal steps: nothing left to zoom into
      }
      std::vector<std::int64_t> counts(Bins, 0);
      for (std::int64_t i = 0; i < cloud.NumberOfOwnPoints; ++i)
      {
        const double x = cloud.Coordinates[3 * i + axis];
        if (x >= low && x <= upper[axis])
        {
          const double bin = std::floor((x - low) / width);
          ++counts[static_cast<int>(std::min(std::max(bin, 0.0), Bins - 1.0))];
        }
      }
      processes.Sum(counts);
      int firstBin = -1, lastBin = -1;
      std::int64_t cumulative = below;
      for (int b = 0; b < Bins && lastBin < 0; ++b)
      {
        if (firstBin < 0 && cumulative + counts[b] > firstRank)
        {
          firstBin = b;
          below = cumulative;
        }
        if (cumulative + counts[b] > lastRank)
        {
          lastBin = b;
        }
        cumulative += counts[b];
      }
      if (firstBin < 0 || lastBin < 0 || lastBin - firstBin >= EnoughBins)
      {
        break;
      }
      const double newUpper = lastBin + 1 < Bins ? low + (lastBin + 1) * width : upper[axis];
      lower[axis] = low + firstBin * width;
      upper[axis] = newUpper;
    }
  }
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
  double largest = 0.0;
  for (std::int64_t i = 0; i < 3 * cloud.NumberOfOwnPoints; ++i)
  {
    largest = std::max(largest, std::fabs(cloud.Coordinates[i]));
  }
  largest = processes.Max(largest);
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
  double fullLower[3], fullUpper[3];
  cloud.OwnBounds(fullLower, fullUpper);
  processes.Bounds(fullLower, fullUpper);
  CloudBoxes boxes;
  std::copy_n(fullLower, 3, boxes.SampleLower.begin());
  std::copy_n(fullUpper, 3, boxes.SampleUpper.begin());
  ZoomOntoCentralPoints(cloud, processes, boxes.SampleLower.data(), boxes.SampleUpper.data());
  for (int k = 0; k < 3; ++k)
  {
    const double margin = 0.5 * boxes.SampleUpper[k] - 0.5 * boxes.SampleLower[k];
    boxes.GridLower[k] = std::max(fullLower[k], boxes.SampleLower[k] - margin);
    boxes.GridUpper[k] = std::min(fullUpper[k], boxes.SampleUpper[k] + margin);
  }
  boxes.GlobalCount = processes.Sum(cloud.NumberOfOwnPoints);
  return boxes;
}

GridLattice GlobalLattice(const CloudBoxes& boxes, double radius)
{
  double lower[3], upper[3];
  for (int k = 0; k < 3; ++k)
  {
    lower[k] = boxes.GridLower[k];
    upper[k] = boxes.GridUpper[k];
    if (!(lower[k] <= upper[k]))
    {
      lower[k] = upper[k] = 0.0; // no point anywhere
    }
  }
  return GridLattice::Make(lower, upper, boxes.GlobalCount, 0.5 * radius);
}

double TypicalRadius(const CloudPoints& cloud,
  const Collectives& processes,
  const CloudBoxes& boxes,
  int k,
  WorkRunner* runner)
{
  const std::int64_t globalCount = boxes.GlobalCount;
  if (globalCount < 2)
  {
    return 0.0;
  }
  // About 512 sample points whatever the size of the cloud.
  const std::int64_t stride = std::max<std::int64_t>(1, globalCount / 512);
  const double* sampleLower = boxes.SampleLower.data();
  const double* sampleUpper = boxes.SampleUpper.data();
  const double diagonal = std::sqrt(SquaredDistance(sampleLower, sampleUpper));
  // Cells for a first guess: the points spread over a square as wide as
  // the (sampling) box's diagonal.
  const double guess = diagonal * std::sqrt(k / (Pi * globalCount));
  const GridLattice lattice =
    GridLattice::Make(boxes.GridLower.data(), boxes.GridUpper.data(), globalCount, 0.5 * guess);

  std::vector<std::int64_t> sample;
  for (std::int64_t i = 0; i < cloud.NumberOfOwnPoints; ++i)
  {
    if (InSpacingSample(&cloud.Coordinates[3 * i], sampleLower, sampleUpper, stride))
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
  // Bin 0 holds zeros; bin b > 0 the magnitudes in [2^((b - 1 - Offset) / 16),
  // 2^((b - Offset) / 16)), over the whole double range.
  constexpr int BinsPerOctave = 16;
  constexpr int Offset = 1075 * BinsPerOctave;
  constexpr int Bins = Offset + 1025 * BinsPerOctave + 1;
  std::vector<std::int64_t> histogram(Bins, 0);
  for (std::int64_t i = 0; i < count; ++i)
  {
    const double magnitude = std::fabs(values.Get(i));
    if (std::isfinite(magnitude))
    {
      const int bin = magnitude > 0.0
        ? 1 + Offset + static_cast<int>(std::floor(BinsPerOctave * std::log2(magnitude)))
        : 0;
      ++histogram[std::min(std::max(bin, 0), Bins - 1)];
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
      return bin == 0 ? 0.0
                      : std::min(std::exp2(static_cast<double>(bin - Offset) / BinsPerOctave),
                          std::numeric_limits<double>::max());
    }
  }
  return std::numeric_limits<double>::max();
}

} // namespace pcurv
