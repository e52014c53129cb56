#include "Normals/PlaneFitting.h"

#include "Common/ScaledCovariance.h"
#include "Normals/OrderedCloud.h"
#include "Normals/OrientationGraph.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <type_traits>
#include <utility>

namespace pcurv
{
namespace normals
{
namespace
{

/// Below this share of the largest variance, the middle one leaves the
/// neighbors on a line: any plane through it fits them (a scan line's
/// points, 12 times denser along the lines than across them, often are
/// all one line's), and the PCA normal is a random turn about the line.
constexpr double LinearShare = 0.05;

/// The normal of the plane through the neighbors (offsets from the point,
/// in units of the radius) by PCA: the eigenvector of the smallest
/// eigenvalue of their covariance; signed so that its largest component is
/// positive (any fixed rule: the orientation decides the sign later). The
/// sums run in the neighbors' order, one accumulator a matrix entry.
/// Returns whether the neighbors span a plane (LinearShare).
bool FitPlane(const NeighborOffsets& offsets, double inverseRadius, double* normal)
{
  const std::size_t count = offsets.Count;
  const double* dx = offsets.Dx.data();
  const double* dy = offsets.Dy.data();
  const double* dz = offsets.Dz.data();
  const Eigen::Matrix3d covariance = ScaledCovariance(dx, dy, dz, count, inverseRadius);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(covariance);
  Eigen::Vector3d n = solver.eigenvectors().col(0);
  int largest = 0;
  for (int k = 1; k < 3; ++k)
  {
    largest = std::fabs(n[k]) > std::fabs(n[largest]) ? k : largest;
  }
  if (n[largest] < 0.0)
  {
    n = -n;
  }
  n.normalize();
  for (int k = 0; k < 3; ++k)
  {
    normal[k] = std::isfinite(n[k]) ? n[k] : 0.0;
  }
  const Eigen::Vector3d variances = solver.eigenvalues(); // ascending
  return variances[1] >= LinearShare * variances[2];
}

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
    std::sort(scratch.begin(), scratch.begin() + within);
    return scratch[k - below - 1];
  }
  scratch.assign(values, values + count);
  std::nth_element(scratch.begin(), scratch.begin() + (k - 1), scratch.end());
  return scratch[k - 1];
}

/// The points within `radius` of x: through rows of cells unless they hold
/// far more points than wanted (a dense cell).
void Gather(const OrderedCloud& ordered,
  const double x[3],
  double radius,
  std::size_t wanted,
  NearestSearch& search)
{
  const std::size_t limit = std::max<std::size_t>(1024, 32 * wanted);
  if (!ordered.GatherRows(x, radius, limit, search.Found))
  {
    ordered.GatherFine(x, radius, search.Shell, search.Found);
  }
}

/// Gathers the points within a radius of x that holds at least `wanted`
/// of them, starting from the guess and growing it (`radius` receives the
/// one that found them); false after a few tries, which a point far from
/// the others needs. Whatever radius finds them, the k-th distance among
/// them is the same: the guess only changes the cost.
bool GatherAtLeast(const OrderedCloud& ordered,
  const double x[3],
  std::size_t wanted,
  NearestSearch& search,
  double& radius)
{
  constexpr int Tries = 6;
  radius = search.Guess;
  for (int attempt = 0; attempt < Tries && radius > 0.0 && std::isfinite(radius); ++attempt)
  {
    Gather(ordered, x, radius, wanted, search);
    const std::size_t found = search.Found.Count;
    if (found >= wanted)
    {
      return true;
    }
    // Points on a surface: the count grows with the area, radius^2.
    const double factor =
      1.1 * std::sqrt(static_cast<double>(wanted) / std::max<std::size_t>(found, 1));
    radius *= std::min(4.0, std::max(1.25, factor));
  }
  return false;
}

/// The k-th smallest of the candidates' squared distances (all within
/// `radius`), looked for first about where it would lie were the points
/// spread evenly on a surface: there the count within a distance grows
/// with its square.
double KthSquared(NearestSearch& search, double radius, std::size_t k)
{
  const Candidates& found = search.Found;
  const double expected = radius * radius * static_cast<double>(k) /
    static_cast<double>(std::max<std::size_t>(found.Count, 1));
  return KthSmallest(
    found.Squared.data(), found.Count, k, 0.8 * expected, 1.25 * expected, search.Selected);
}

/// Keeps the candidates nearer than `radius` (every point nearer than the
/// k-th): their squared distances and positions, in position order, stay
/// the first `Count` candidates; their offsets go to search.Offsets.
void KeepWithinRadius(const OrderedCloud& ordered,
  const double x[3],
  double radius,
  NearestSearch& search)
{
  Candidates& found = search.Found;
  const double radiusSquared = radius * radius;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < found.Count; ++i)
  {
    const double squared = found.Squared[i];
    found.Squared[kept] = squared;
    found.Positions[kept] = found.Positions[i];
    kept += squared < radiusSquared;
  }
  found.Count = kept;
  if (!found.InOrder)
  {
    std::vector<std::pair<std::int64_t, double>> byPosition(kept);
    for (std::size_t i = 0; i < kept; ++i)
    {
      byPosition[i] = { found.Positions[i], found.Squared[i] };
    }
    std::sort(byPosition.begin(), byPosition.end());
    for (std::size_t i = 0; i < kept; ++i)
    {
      found.Positions[i] = byPosition[i].first;
      found.Squared[i] = byPosition[i].second;
    }
    found.InOrder = true;
  }
  NeighborOffsets& offsets = search.Offsets;
  if (offsets.Dx.size() < kept)
  {
    for (std::vector<double>* axis : { &offsets.Dx, &offsets.Dy, &offsets.Dz })
    {
      axis->resize(kept);
    }
  }
  for (std::size_t i = 0; i < kept; ++i)
  {
    double q[3];
    ordered.Point(found.Positions[i], q);
    offsets.Dx[i] = q[0] - x[0];
    offsets.Dy[i] = q[1] - x[1];
    offsets.Dz[i] = q[2] - x[2];
  }
  offsets.Count = kept;
}

/// The graph edges of the point at `position`: its `count` nearest others
/// among the kept neighbors (within `radius`, `kept` of them), by
/// (squared distance, position), nearest first, -1 padded. Only those
/// within a distance that holds about 1.5 times as many on a surface are
/// ranked; all of them where that is too few. The kept neighbors come in
/// position order, so a stable sort by distance ranks ties by position.
void WriteNearestOthers(std::int64_t position,
  double radius,
  NearestSearch& search,
  int count,
  IndexList& edges)
{
  const std::int64_t first = position * count;
  const Candidates& kept = search.Found;
  const std::size_t wanted = static_cast<std::size_t>(count);
  std::vector<std::pair<double, std::int64_t>>& ranked = search.Ranked;
  ranked.resize(kept.Count + 1); // one written past the last ranked
  const double share = 1.5 * static_cast<double>(wanted + 1) / static_cast<double>(kept.Count);
  std::size_t size = 0;
  for (const double limit : { share * radius * radius, std::numeric_limits<double>::infinity() })
  {
    size = 0;
    for (std::size_t i = 0; i < kept.Count; ++i)
    {
      ranked[size] = { kept.Squared[i], kept.Positions[i] };
      size += (kept.Squared[i] <= limit) & (kept.Positions[i] != position);
    }
    if (size >= wanted)
    {
      break;
    }
  }
  // Insertion sort: few entries, and stable.
  for (std::size_t i = 1; i < size; ++i)
  {
    const std::pair<double, std::int64_t> entry = ranked[i];
    std::size_t at = i;
    for (; at > 0 && entry.first < ranked[at - 1].first; --at)
    {
      ranked[at] = ranked[at - 1];
    }
    ranked[at] = entry;
  }
  for (std::size_t e = 0; e < wanted; ++e)
  {
    edges.Set(first + static_cast<std::int64_t>(e), e < size ? ranked[e].second : -1);
  }
}

/// Where the k nearest lie on a line: the plane through the neighbors of
/// a radius grown until they span one (twice as many each time, on a
/// surface), up to 8 times as many; `normal` unchanged where none does (a
/// point on a line has no plane).
void FitBeyondLine(const OrderedCloud& ordered,
  const double x[3],
  double radius,
  std::size_t wanted,
  NearestSearch& search,
  double* normal)
{
  constexpr int Doublings = 3;
  for (int doubling = 1; doubling <= Doublings; ++doubling)
  {
    const double grown = radius * std::sqrt(static_cast<double>(1 << doubling));
    Gather(ordered, x, grown, wanted << doubling, search);
    KeepWithinRadius(ordered, x, grown, search);
    double candidate[3];
    if (search.Offsets.Count >= 3 && FitPlane(search.Offsets, 1.0 / grown, candidate))
    {
      std::copy_n(candidate, 3, normal);
      return;
    }
  }
}

} // namespace

/// One point's plane and graph neighbors: the k nearest found with one
/// radius query (usually), kept in position order for the fit, the nearest
/// others for the graph.
void FitPoint(const OrderedCloud& ordered,
  const NormalSettings& settings,
  std::int64_t position,
  NearestSearch& search,
  PlaneFits& fits)
{
  double x[3];
  ordered.Point(position, x);
  double* normal = &fits.Normals[3 * position];
  // k + 1: the point itself is among those found.
  const std::size_t wanted = static_cast<std::size_t>(settings.NumberOfNeighbors) + 1;
  double gathered = 0.0; // the radius the candidates were gathered within
  const bool found = static_cast<std::size_t>(ordered.Size()) > wanted &&
    GatherAtLeast(ordered, x, wanted, search, gathered);
  const double squared = found
    ? KthSquared(search, gathered, wanted)
    : ordered.SquaredDistanceToKth(x, static_cast<int>(wanted), search.Selected);
  const double radius = std::nextafter(std::sqrt(squared), HUGE_VAL);
  if (!(radius > 0.0) || !std::isfinite(radius))
  {
    normal[0] = normal[1] = normal[2] = 0.0;
    return;
  }
  if (!found)
  {
    Gather(ordered, x, radius, wanted, search);
  }
  KeepWithinRadius(ordered, x, radius, search);
  search.Guess = 1.1 * radius;
  if (search.Offsets.Count < 3)
  {
    normal[0] = normal[1] = normal[2] = 0.0;
    return;
  }
  const bool planar = FitPlane(search.Offsets, 1.0 / radius, normal);
  WriteNearestOthers(position, radius, search, fits.GraphNeighbors, fits.Neighbors);
  if (!planar)
  {
    FitBeyondLine(ordered, x, radius, wanted, search, normal);
  }
}

} // namespace normals
} // namespace pcurv
