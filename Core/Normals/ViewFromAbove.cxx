#include "Normals/ViewFromAbove.h"

#include "Normals/OrderedCloud.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace pcurv
{
namespace normals
{
namespace
{
/// A column's index along one axis. Far or non-finite coordinates share
/// the extreme columns, so that the index stays an integer.
std::int64_t ColumnIndex(double coordinate, double width)
{
  constexpr double Limit = 1073741824.0; // 2^30
  const double cell = std::floor(coordinate / width);
  if (!(cell > -Limit))
  {
    return -static_cast<std::int64_t>(Limit);
  }
  return cell < Limit ? static_cast<std::int64_t>(cell) : static_cast<std::int64_t>(Limit);
}

/// Columns are keyed by their two indices packed into one integer.
std::int64_t ColumnKey(double x, double y, double width)
{
  return ColumnIndex(x, width) * (std::int64_t(1) << 32) + ColumnIndex(y, width);
}
} // namespace

std::vector<Sight> SightsFromAbove(const OrderedCloud& ordered,
  const std::vector<double>& normals,
  double width,
  double depth)
{
  const std::int64_t n = ordered.Size();
  if (!(width > 0.0) || !std::isfinite(width) || !std::isfinite(depth))
  {
    return std::vector<Sight>(n, Sight::Steep); // nothing judged: not seen from above
  }
  std::unordered_map<std::int64_t, double> highest;
  highest.reserve(static_cast<std::size_t>(n / 4 + 1));
  std::vector<std::int64_t> keys(n);
  for (std::int64_t p = 0; p < n; ++p)
  {
    double x[3];
    ordered.Point(p, x);
    keys[p] = ColumnKey(x[0], x[1], width);
    const auto [entry, added] = highest.emplace(keys[p], x[2]);
    if (!added)
    {
      entry->second = std::max(entry->second, x[2]);
    }
  }
  std::vector<Sight> sights(n, Sight::Steep);
  for (std::int64_t p = 0; p < n; ++p)
  {
    if (std::fabs(normals[3 * p + 2]) >= SteepBelow)
    {
      double x[3];
      ordered.Point(p, x);
      sights[p] = x[2] >= highest[keys[p]] - depth ? Sight::Top : Sight::Hidden;
    }
  }
  return sights;
}

double ShareOfTops(const std::vector<Sight>& sights, const std::vector<std::int64_t>* part)
{
  std::int64_t tops = 0, judged = 0;
  const auto count = [&](Sight sight)
  {
    tops += sight == Sight::Top;
    judged += sight != Sight::Steep;
  };
  if (part)
  {
    for (const std::int64_t p : *part)
    {
      count(sights[p]);
    }
  }
  else
  {
    for (const Sight sight : sights)
    {
      count(sight);
    }
  }
  return judged ? static_cast<double>(tops) / static_cast<double>(judged) : 0.0;
}

bool SeenFromAbove(const std::vector<Sight>& sights)
{
  // Well above the half a closed surface shows, with room for the
  // vegetation and overhangs of a real tile.
  constexpr double SeenShare = 0.75;
  return ShareOfTops(sights) >= SeenShare;
}

} // namespace normals
} // namespace pcurv
