#include "Normals/RankSelection.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace pcurv
{
namespace normals
{

/// The k-th smallest (k from 1) of values[0, count): exact whatever the
/// bounds, and quick when it lies in [low, high): the values below and
/// within are counted without branches (a sphere's distances come too
/// randomly for branch prediction) and only those within are sorted.
double KthSmallest(const double* values,
  std::size_t count,
  std::size_t k,
  double low,
  double high,
  std::vector<double>& scratch)
{
  std::size_t below = 0, within = 0;
  for (std::size_t i = 0; i < count; ++i)
  {
    const double v = values[i];
    below += v < low;
    within += (v >= low) & (v < high);
  }
  if (below < k && k <= below + within)
  {
    scratch.resize(within + 1); // one written past the last kept
    std::size_t kept = 0;
    for (std::size_t i = 0; i < count; ++i)
    {
      const double v = values[i];
      scratch[kept] = v;
      kept += (v >= low) & (v < high);
    }
    std::nth_element(scratch.begin(), scratch.begin() + (k - below - 1), scratch.begin() + within);
    return scratch[k - below - 1];
  }
  scratch.assign(values, values + count);
  std::nth_element(scratch.begin(), scratch.begin() + (k - 1), scratch.end());
  return scratch[k - 1];
}

/// The k-th smallest (k from 1, at most count) of values[0, count), all
/// in [0, high), for each of the `n` ranks ks[] (ascending), into kth[]:
/// exact, in two passes whatever n. The values are counted into buckets of
/// equal width (squared distances within a radius spread about evenly over
/// them on a surface), and only the few that hold a wanted rank are
/// copied out and selected in.
void KthSmallestOfEach(const double* values,
  std::size_t count,
  const std::size_t* ks,
  int n,
  double high,
  double* kth,
  std::vector<double>& scratch)
{
  constexpr int Buckets = 256;
  const double scale = Buckets / high;
  if (!(high > 0.0) || !std::isfinite(scale))
  {
    for (int j = 0; j < n; ++j)
    {
      scratch.assign(values, values + count);
      std::nth_element(scratch.begin(), scratch.begin() + (ks[j] - 1), scratch.end());
      kth[j] = scratch[ks[j] - 1];
    }
    return;
  }
  // Monotone in the value (values at or beyond `high` share the last).
  const auto bucketOf = [scale](double v)
  { return static_cast<int>(std::min(std::max(v * scale, 0.0), Buckets - 1.0)); };
  std::array<std::uint32_t, Buckets> counts{};
  for (std::size_t i = 0; i < count; ++i)
  {
    ++counts[bucketOf(values[i])];
  }
  // Per bucket holding a wanted rank, its slot: where its values go in
  // scratch (small arrays: most calls read a few hundred values).
  constexpr int MostRanks = 8;
  n = std::min(n, MostRanks);
  std::array<std::int8_t, Buckets> slotOf;
  slotOf.fill(-1);
  std::array<std::size_t, MostRanks> start{}, filled{}, size{}, rank{};
  std::array<int, MostRanks> slotOfRank{};
  std::size_t below = 0, used = 0;
  int slots = 0;
  for (int b = 0, j = 0; b < Buckets && j < n; ++b)
  {
    for (; j < n && ks[j] <= below + counts[b]; ++j)
    {
      if (slotOf[b] < 0)
      {
        slotOf[b] = static_cast<std::int8_t>(slots);
        start[slots] = used;
        size[slots] = counts[b];
        used += counts[b];
        ++slots;
      }
      rank[j] = ks[j] - below - 1;
      slotOfRank[j] = slotOf[b];
    }
    below += counts[b];
  }
  scratch.resize(used);
  for (std::size_t i = 0; i < count; ++i)
  {
    const int slot = slotOf[bucketOf(values[i])];
    if (slot >= 0)
    {
      scratch[start[slot] + filled[slot]++] = values[i];
    }
  }
  for (int j = 0; j < n; ++j)
  {
    const int slot = slotOfRank[j];
    const auto first = scratch.begin() + static_cast<std::ptrdiff_t>(start[slot]);
    const auto nth = first + static_cast<std::ptrdiff_t>(rank[j]);
    std::nth_element(first, nth, first + static_cast<std::ptrdiff_t>(size[slot]));
    kth[j] = *nth;
  }
}

} // namespace normals
} // namespace pcurv
