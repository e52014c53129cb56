#include "Normals/PlaneFitting.h"

#include "Common/ScaledCovariance.h"
#include "Normals/OrderedCloud.h"
#include "Normals/OrientationGraph.h"
#include "Normals/PlaneQuadric.h"
#include "Normals/RankSelection.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
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

/// The covariance's eigenvectors (columns, the normal first) and its
/// eigenvalues per point, ascending.
struct PlaneAxes
{
  Eigen::Matrix3d Axes;
  Eigen::Vector3d Variances;
};

/// The normal of the plane through the neighbors (offsets from the point,
/// in units of the radius) by PCA: the eigenvector of the smallest
/// eigenvalue of their covariance; signed so that its largest component is
/// positive (any fixed rule: the orientation decides the sign later). The
/// sums run in the neighbors' order, one accumulator a matrix entry.
/// Returns whether the neighbors span a plane (LinearShare); with `axes`,
/// writes the covariance's eigen-decomposition there.
bool FitPlane(const NeighborOffsets& offsets,
  double inverseRadius,
  double* normal,
  PlaneAxes* axes = nullptr)
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
  if (axes)
  {
    axes->Axes = solver.eigenvectors();
    axes->Variances = variances / static_cast<double>(count);
  }
  return variances[1] >= LinearShare * variances[2];
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
/// `radius`) for each of the `n` ranks ks[] (ascending), into kth[].
void KthSquaredOfEach(NearestSearch& search,
  double radius,
  const std::size_t* ks,
  int n,
  double* kth)
{
  const Candidates& found = search.Found;
  KthSmallestOfEach(
    found.Squared.data(), found.Count, ks, n, radius * radius, kth, search.Selected);
}

/// The k-th smallest of the candidates' squared distances (all within
/// `radius`) for one rank, looked for first about where it would lie were
/// the points spread evenly on a surface (the count within a distance grows
/// with its square): for one rank among a few dozen candidates, a window
/// costs less than buckets.
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

/// The unoriented angle between two unit normals, radians.
double LineAngle(const double* a, const double* b)
{
  const double cosine = std::fabs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
  return std::acos(std::min(1.0, cosine));
}

/// One neighborhood's plane for the normals' scale: the PCA normal and its
/// standard error, and the normal at the point itself and its own.
struct ScaledPlane
{
  double Normal[3] = { 0.0, 0.0, 0.0 };
  double Error = 0.0;
  double AtPoint[3] = { 0.0, 0.0, 0.0 };
  double AtPointError = 0.0;
};

/// The neighbors' ScaledPlane; false where they do not span a plane. One
/// quadric h = a + b u + c v + d u^2 + e u v + f v^2 over the PCA plane
/// (offsets in units of the radius, the point at their origin) gives both
/// the noise (the heights' residual variance about it: the plane's own
/// residual also holds the surface's bending, which is no error of its
/// normal) and the normal at the point (the PCA normal tilted by the
/// slopes b, c: the PCA plane's normal is the surface's near the
/// neighbors' centroid, which a one-sided neighborhood moves away from
/// the point). Errors are infinite where the quadric is undetermined.
bool FitScaledPlane(const NeighborOffsets& offsets, double inverseRadius, ScaledPlane& plane)
{
  PlaneAxes axes;
  if (!FitPlane(offsets, inverseRadius, plane.Normal, &axes))
  {
    return false;
  }
  plane.Error = plane.AtPointError = std::numeric_limits<double>::infinity();
  if (offsets.Count <= 6)
  {
    return true;
  }
  const QuadricSystem system(offsets, inverseRadius, axes.Axes);
  const Eigen::LDLT<QuadricSystem::Matrix6> factors(system.Normal);
  const QuadricSystem::Vector6 pivots = factors.vectorD();
  if (factors.info() != Eigen::Success || !(pivots.minCoeff() > 1e-12 * pivots.maxCoeff()))
  {
    return true;
  }
  const QuadricSystem::Vector6 solution = factors.solve(system.Right);
  const double noise = system.ResidualVariance(solution, offsets.Count);
  plane.Error = NormalStandardError(axes.Variances, noise, offsets.Count);
  // The slopes' variances: the inverse's diagonal entries (1, 1), (2, 2).
  const Eigen::Matrix<double, 6, 2> inverse =
    factors.solve(QuadricSystem::Matrix6::Identity().middleCols<2>(1));
  const Eigen::Vector3d n =
    (axes.Axes.col(0) - solution[1] * axes.Axes.col(1) - solution[2] * axes.Axes.col(2))
      .normalized();
  const double error = std::sqrt(noise * (inverse(1, 0) + inverse(2, 1)));
  if (n.allFinite() && std::isfinite(error))
  {
    std::copy_n(n.data(), 3, plane.AtPoint);
    plane.AtPointError = error;
  }
  return true;
}

/// The kept candidates' offsets (KeepWithinRadius's) nearer than `radius`,
/// in their order, into `out`: the same points and offsets a gather and
/// KeepWithinRadius of that radius would give.
void KeepNearer(const NearestSearch& search, double radius, NeighborOffsets& out)
{
  const Candidates& found = search.Found;
  const NeighborOffsets& from = search.Offsets;
  if (out.Dx.size() < found.Count)
  {
    for (std::vector<double>* axis : { &out.Dx, &out.Dy, &out.Dz })
    {
      axis->resize(found.Count);
    }
  }
  const double radiusSquared = radius * radius;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < found.Count; ++i)
  {
    out.Dx[kept] = from.Dx[i];
    out.Dy[kept] = from.Dy[i];
    out.Dz[kept] = from.Dz[i];
    kept += found.Squared[i] < radiusSquared;
  }
  out.Count = kept;
}

/// The normal at the largest neighborhood that still agrees: the plane
/// through twice, four and eight times the k nearest is taken while its
/// normal lies within AgreementTolerance times the sum of the standard
/// errors of every smaller one's (Lepski's rule, as the curvatures' scale
/// is chosen). Where noise turns the k-neighbor normal, the wider planes
/// average it out; where the surface bends them away (a boundary, a sharp
/// bend), they part and the growth stops. The PCA normals, the more
/// precise, choose the scale; a grown neighborhood's normal at the point
/// itself is the result (the PCA plane's where the quadric is
/// undetermined). `first` is the k nearest's plane. The widest
/// neighborhood is gathered once, and each smaller one is the part of it
/// within its own k-th distance.
void GrowWhileAgreeing(const OrderedCloud& ordered,
  const double x[3],
  double radius,
  std::size_t wanted,
  NearestSearch& search,
  const ScaledPlane& first,
  double* normal)
{
  constexpr int Doublings = 3;
  constexpr double AgreementTolerance = 2.0;
  int levels = Doublings;
  while (levels > 0 && static_cast<std::size_t>(ordered.Size()) <= (wanted << levels))
  {
    --levels;
  }
  const double guess = search.Guess; // the next point's: the k nearest's
  search.Guess = radius * std::sqrt(static_cast<double>(1 << levels));
  double gathered = 0.0;
  double grown[Doublings + 1] = {};
  if (levels > 0 && GatherAtLeast(ordered, x, wanted << levels, search, gathered))
  {
    std::size_t ranks[Doublings];
    double squared[Doublings];
    for (int level = 1; level <= levels; ++level)
    {
      ranks[level - 1] = wanted << level;
    }
    KthSquaredOfEach(search, gathered, ranks, levels, squared);
    for (int level = 1; level <= levels; ++level)
    {
      grown[level] = std::nextafter(std::sqrt(squared[level - 1]), HUGE_VAL);
    }
    KeepWithinRadius(ordered, x, grown[levels], search);
  }
  else
  {
    levels = 0;
  }
  search.Guess = guess;
  ScaledPlane planes[Doublings + 1];
  planes[0] = first;
  int chosen = 0;
  for (int level = 1; level <= levels; ++level)
  {
    if (level < levels)
    {
      KeepNearer(search, grown[level], search.Level);
    }
    const NeighborOffsets& offsets = level < levels ? search.Level : search.Offsets;
    ScaledPlane& candidate = planes[level];
    if (offsets.Count < 3 || !FitScaledPlane(offsets, 1.0 / grown[level], candidate))
    {
      break;
    }
    bool agrees = true;
    for (int smaller = 0; smaller < level; ++smaller)
    {
      agrees = agrees &&
        LineAngle(candidate.Normal, planes[smaller].Normal) <=
          AgreementTolerance * (planes[smaller].Error + candidate.Error);
    }
    if (!agrees)
    {
      break;
    }
    chosen = level;
  }
  // The k nearest keep their plane's normal: their centroid lies near the
  // point, and a quadric's slopes over so few points (a scan's few lines
  // among them) are less certain than the offset they would correct.
  const ScaledPlane& plane = planes[chosen];
  const bool atPoint = chosen > 0 && std::isfinite(plane.AtPointError);
  std::copy_n(atPoint ? plane.AtPoint : plane.Normal, 3, normal);
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
  ScaledPlane first;
  const bool planar = settings.ChooseScale ? FitScaledPlane(search.Offsets, 1.0 / radius, first)
                                           : FitPlane(search.Offsets, 1.0 / radius, normal);
  WriteNearestOthers(position, radius, search, fits.GraphNeighbors, fits.Neighbors);
  if (!planar)
  {
    if (settings.ChooseScale)
    {
      std::copy_n(first.Normal, 3, normal);
    }
    FitBeyondLine(ordered, x, radius, wanted, search, normal);
  }
  else if (settings.ChooseScale)
  {
    GrowWhileAgreeing(ordered, x, radius, wanted, search, first, normal);
  }
}

} // namespace normals
} // namespace pcurv
