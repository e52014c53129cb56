#include "Normals/NormalEstimation.h"

#include "Common/Progress.h"
#include "Common/WorkRunner.h"
#include "Normals/OrientationGraph.h"
#include "Common/ScaledCovariance.h"
#include "Cloud/CloudPoints.h"
#include "Cloud/CloudStatistics.h"
#include "Neighbors/PointGrid.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <type_traits>
#include <utility>

namespace pcurv
{
namespace
{
using edge::Dot;
using edge::IsZero;

void Flip(double* n)
{
  n[0] = -n[0];
  n[1] = -n[1];
  n[2] = -n[2];
}

/// Points found around a query point: squared distances and grid positions
/// (buffers reused from query to query; Count of them are the query's).
struct Candidates
{
  std::vector<double> Squared;
  std::vector<std::int64_t> Positions;
  std::size_t Count = 0;
  /// Positions increasing (a dense cell's finer cells give another order).
  bool InOrder = true;

  void Reserve(std::size_t count)
  {
    if (this->Squared.size() < count)
    {
      this->Squared.resize(count);
      this->Positions.resize(count);
    }
  }
};

/// The cloud's points in the neighbour grid's order (the positions), one
/// array per axis, with the first position of each of the grid's cells.
/// Cells of a row being consecutive in that order, a radius query reads
/// contiguous runs of positions: it finds the neighbours in position order
/// (the order every sum of the fit follows, as before) without looking
/// positions up, and reads the coordinates where they lie in memory.
///
/// The order is PointGrid's (by cell, then by coordinates, then by id),
/// found here with the sorting in parallel; the PointGrid itself, whose
/// finer cells serve queries in cells far denser than the rest, is only
/// built when such a query comes.
class OrderedCloud
{
public:
  OrderedCloud(const CloudPoints& cloud, const GridLattice& lattice, WorkRunner& runner);

  std::int64_t Size() const { return static_cast<std::int64_t>(this->Ids.size()); }
  std::int64_t Id(std::int64_t position) const { return this->Ids[position]; }
  void Point(std::int64_t position, double x[3]) const
  {
    x[0] = this->X[position];
    x[1] = this->Y[position];
    x[2] = this->Z[position];
  }
  /// The cloud's own coordinates (xyz triplets) from the ordered copy, bit
  /// for bit, into `coordinates`.
  void WriteCoordinates(std::vector<double>& coordinates, WorkRunner& runner) const
  {
    coordinates.resize(static_cast<std::size_t>(3 * this->Size()));
    runner.For(this->Size(),
      65536,
      [&](std::int64_t begin, std::int64_t end)
      {
        for (std::int64_t p = begin; p < end; ++p)
        {
          this->Point(p, &coordinates[3 * this->Ids[p]]);
        }
      });
  }

  /// The points q with |q - x| < radius into `out`, in position order;
  /// false, with `out` unusable, where the cells searched hold more than
  /// `limit` points (a dense cell, which GatherFine searches through its
  /// finer cells).
  bool GatherRows(const double x[3], double radius, std::size_t limit, Candidates& out) const;

  /// The same points through the grid's finer cells, in another order.
  void GatherFine(const double x[3], double radius, ShellPoints& shell, Candidates& out) const;

  /// See PointGrid::SquaredDistanceToKth.
  double SquaredDistanceToKth(const double x[3], int k, std::vector<double>& scratch) const
  {
    return this->FineGrid().SquaredDistanceToKth(x, k, scratch);
  }

private:
  /// The grid's local cell of a coordinate along an axis (as PointGrid
  /// numbers its cells: from the cell of the smallest coordinate, clamped).
  std::int64_t CellIndex(double coordinate, int axis) const
  {
    const double cell = static_cast<double>(this->Lattice.Cell(coordinate, axis)) -
      static_cast<double>(this->Low[axis]);
    const double last = static_cast<double>(this->Dimensions[axis] - 1);
    return static_cast<std::int64_t>(cell > 0.0 ? (cell < last ? cell : last) : 0.0);
  }

  std::int64_t CellOf(const double* x) const
  {
    return (this->CellIndex(x[2], 2) * this->Dimensions[1] + this->CellIndex(x[1], 1)) *
      this->Dimensions[0] +
      this->CellIndex(x[0], 0);
  }

  /// Low and Dimensions: the cells from the smallest coordinates' to the
  /// largest's.
  void SpanCells();
  /// Ids and CellStart: a counting sort by cell, then each cell's points
  /// by coordinates (in parallel).
  void SortByCell(WorkRunner& runner);
  /// X, Y, Z from Ids (in parallel).
  void CopyInOrder(WorkRunner& runner);

  /// The PointGrid over the cloud, and PositionOfId, which only its queries
  /// need: built by the first query that needs them.
  const PointGrid& FineGrid() const
  {
    std::call_once(this->GridBuilt,
      [this]()
      {
        this->Grid.Build(this->Cloud.Coordinates.data(), this->Size(), this->Lattice);
        this->PositionOfId.resize(this->Ids.size());
        for (std::int64_t p = 0; p < this->Size(); ++p)
        {
          this->PositionOfId[this->Ids[p]] = p;
        }
      });
    return this->Grid;
  }

  const CloudPoints& Cloud;
  GridLattice Lattice;
  std::vector<double> X, Y, Z;
  std::vector<std::int64_t> Ids;                  // position -> point id
  mutable std::vector<std::int64_t> PositionOfId; // point id -> position (with the PointGrid)
  std::array<std::int64_t, 3> Low{ { 0, 0, 0 } };
  std::array<std::int64_t, 3> Dimensions{ { 1, 1, 1 } };
  CellStarts CellStart; // per cell its first position, one extra at the end
  mutable PointGrid Grid;
  mutable std::once_flag GridBuilt;
};

OrderedCloud::OrderedCloud(const CloudPoints& cloud, const GridLattice& lattice, WorkRunner& runner)
  : Cloud(cloud)
  , Lattice(lattice)
{
  if (cloud.NumberOfOwnPoints == 0)
  {
    return;
  }
  this->SpanCells();
  this->SortByCell(runner);
  this->CopyInOrder(runner);
}

void OrderedCloud::SpanCells()
{
  const std::int64_t n = this->Cloud.NumberOfOwnPoints;
  const double* coordinates = this->Cloud.Coordinates.data();
  double lower[3], upper[3];
  for (int k = 0; k < 3; ++k)
  {
    lower[k] = upper[k] = coordinates[k];
  }
  for (std::int64_t i = 1; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      lower[k] = std::min(lower[k], coordinates[3 * i + k]);
      upper[k] = std::max(upper[k], coordinates[3 * i + k]);
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    this->Low[k] = this->Lattice.Cell(lower[k], k);
    this->Dimensions[k] = this->Lattice.Cell(upper[k], k) - this->Low[k] + 1;
  }
}

void OrderedCloud::SortByCell(WorkRunner& runner)
{
  const std::int64_t n = this->Cloud.NumberOfOwnPoints;
  const double* coordinates = this->Cloud.Coordinates.data();
  std::vector<std::int64_t> cellOf(n);
  runner.For(n,
    65536,
    [&](std::int64_t begin, std::int64_t end)
    {
      for (std::int64_t i = begin; i < end; ++i)
      {
        cellOf[i] = this->CellOf(coordinates + 3 * i);
      }
    });
  const std::int64_t cells = this->Dimensions[0] * this->Dimensions[1] * this->Dimensions[2];
  this->CellStart.Bucket(cellOf, cells, this->Ids);
  // Within a cell by coordinates, as PointGrid.
  auto before = [coordinates](std::int64_t a, std::int64_t b)
  { return PrecedesInCell(coordinates, a, b); };
  runner.For(cells,
    65536,
    [&](std::int64_t begin, std::int64_t end)
    {
      for (std::int64_t c = begin; c < end; ++c)
      {
        if (this->CellStart[c + 1] - this->CellStart[c] > 1)
        {
          std::sort(this->Ids.begin() + this->CellStart[c],
            this->Ids.begin() + this->CellStart[c + 1],
            before);
        }
      }
    });
}

void OrderedCloud::CopyInOrder(WorkRunner& runner)
{
  const std::int64_t n = this->Size();
  const double* coordinates = this->Cloud.Coordinates.data();
  for (std::vector<double>* axis : { &this->X, &this->Y, &this->Z })
  {
    axis->resize(n);
  }
  runner.For(n,
    65536,
    [&](std::int64_t begin, std::int64_t end)
    {
      for (std::int64_t p = begin; p < end; ++p)
      {
        const std::int64_t id = this->Ids[p];
        this->X[p] = coordinates[3 * id];
        this->Y[p] = coordinates[3 * id + 1];
        this->Z[p] = coordinates[3 * id + 2];
      }
    });
}

bool OrderedCloud::GatherRows(const double x[3],
  double radius,
  std::size_t limit,
  Candidates& out) const
{
  std::array<std::int64_t, 3> low, high;
  for (int k = 0; k < 3; ++k)
  {
    low[k] = this->CellIndex(x[k] - radius, k);
    high[k] = this->CellIndex(x[k] + radius, k);
  }
  const double radiusSquared = radius * radius;
  const double* xs = this->X.data();
  const double* ys = this->Y.data();
  const double* zs = this->Z.data();
  const double x0 = x[0], x1 = x[1], x2 = x[2];
  std::size_t seen = 0, kept = 0;
  for (std::int64_t iz = low[2]; iz <= high[2]; ++iz)
  {
    for (std::int64_t iy = low[1]; iy <= high[1]; ++iy)
    {
      const std::int64_t row = (iz * this->Dimensions[1] + iy) * this->Dimensions[0];
      const std::int64_t begin = this->CellStart[row + low[0]];
      const std::int64_t end = this->CellStart[row + high[0] + 1];
      const std::size_t length = static_cast<std::size_t>(end - begin);
      seen += length;
      if (seen > limit)
      {
        return false;
      }
      out.Reserve(kept + length);
      double* squared = out.Squared.data();
      std::int64_t* positions = out.Positions.data();
      // Every candidate is written, at the first free place; only those
      // within the radius advance it (branch free: a sphere cuts through
      // the rows too randomly for branch prediction).
      for (std::int64_t j = begin; j < end; ++j)
      {
        const double dx = xs[j] - x0, dy = ys[j] - x1, dz = zs[j] - x2;
        const double d = dx * dx + dy * dy + dz * dz;
        squared[kept] = d;
        positions[kept] = j;
        kept += d < radiusSquared;
      }
    }
  }
  out.Count = kept;
  out.InOrder = true;
  return true;
}

void OrderedCloud::GatherFine(const double x[3],
  double radius,
  ShellPoints& shell,
  Candidates& out) const
{
  const std::size_t count = this->FineGrid().GatherShell(x, 0.0, radius, shell);
  out.Reserve(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    const double dx = shell.Dx[i], dy = shell.Dy[i], dz = shell.Dz[i];
    out.Squared[i] = dx * dx + dy * dy + dz * dz;
    out.Positions[i] = this->PositionOfId[shell.Ids[i]];
  }
  out.Count = count;
  out.InOrder = false;
}

/// Below this share of the largest variance, the middle one leaves the
/// neighbours on a line: any plane through it fits them (a scan line's
/// points, 12 times denser along the lines than across them, often are
/// all one line's), and the PCA normal is a random turn about the line.
constexpr double LinearShare = 0.05;

/// The normal of the plane through the neighbours (offsets from the point,
/// in units of the radius) by PCA: the eigenvector of the smallest
/// eigenvalue of their covariance; signed so that its largest component is
/// positive (any fixed rule: the orientation decides the sign later). The
/// sums run in the neighbours' order, one accumulator a matrix entry.
/// Returns whether the neighbours span a plane (LinearShare).
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

/// One thread's buffers of the k-nearest search, and its guess of the
/// radius: the last point's, the points being visited in grid order (so
/// the next one is near and about as dense).
struct NearestSearch
{
  Candidates Found;
  ShellPoints Shell;
  std::vector<double> Selected;
  NeighborOffsets Offsets;
  std::vector<std::pair<double, std::int64_t>> Ranked;
  double Guess = 0.0;
};

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
/// among the kept neighbours (within `radius`, `kept` of them), by
/// (squared distance, position), nearest first, -1 padded. Only those
/// within a distance that holds about 1.5 times as many on a surface are
/// ranked; all of them where that is too few. The kept neighbours come in
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

/// Where the k nearest lie on a line: the plane through the neighbours of
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

/// One point's plane and graph neighbours: the k nearest found with one
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

/// Points of the tree's frontier with the sign they would get, by their
/// edge's weight bucket: pushing and popping cost O(1), where a binary
/// heap's cost grew with the frontier. Within a bucket the last in is the
/// first out; ties are thereby decided by the grid's order as well.
template<typename Index>
class FrontierBuckets
{
public:
  void Push(int bucket, Index to, signed char sign)
  {
    // The sign in the lowest bit (positions are far below half the range).
    using Unsigned = std::make_unsigned_t<Index>;
    this->Buckets[bucket].push_back(
      static_cast<Unsigned>(2 * static_cast<Unsigned>(to) + (sign < 0)));
    this->Lowest = std::min(this->Lowest, bucket);
    ++this->Size;
  }

  bool Empty() const { return this->Size == 0; }

  std::pair<Index, signed char> Pop()
  {
    while (this->Buckets[this->Lowest].empty())
    {
      ++this->Lowest;
    }
    const auto entry = this->Buckets[this->Lowest].back();
    this->Buckets[this->Lowest].pop_back();
    --this->Size;
    return { static_cast<Index>(entry >> 1), static_cast<signed char>(entry & 1 ? -1 : 1) };
  }

private:
  std::vector<std::make_unsigned_t<Index>> Buckets[edge::Buckets];
  int Lowest = edge::Buckets - 1;
  std::int64_t Size = 0;
};

/// Propagates the sign from `seed` over a minimum spanning tree of the
/// normals' disagreement 1 - |n_a . n_b| (Prim's, weights in buckets):
/// signs[p] becomes +1 or -1 (the normal as fitted, or flipped) for the
/// part's points; returns them in the order reached.
template<typename Index>
std::vector<std::int64_t> OrientPart(const Graph<Index>& graph,
  std::int64_t seed,
  std::vector<signed char>& signs,
  FrontierBuckets<Index>& frontier,
  StageProgress* progress)
{
  // The traversal is serial and takes a while on millions of points: a
  // stop request is looked at every few thousand points (the normals are
  // then incomplete anyway).
  constexpr std::size_t StopCheckInterval = 4096;
  std::vector<std::int64_t> part;
  frontier.Push(edge::Bucket(1.0), static_cast<Index>(seed), 1);
  while (!frontier.Empty())
  {
    const auto [to, sign] = frontier.Pop();
    if (signs[to] != 0)
    {
      continue;
    }
    if (progress && part.size() % StopCheckInterval == 0 && !progress->Reach(1.0))
    {
      return part;
    }
    signs[to] = sign;
    part.push_back(to);
    for (std::int64_t e = graph.Start[to]; e < graph.Start[to + 1]; ++e)
    {
      const auto& entry = graph.Entries[e];
      if (signs[entry.Target] == 0 && entry.Code != edge::Unused)
      {
        frontier.Push(edge::BucketOf(entry.Code), entry.Target, edge::Propagate(entry.Code, sign));
      }
    }
  }
  return part;
}

/// Turns a part's normals outward (see NormalOrientation::Outward), by
/// their signs. A closed surface's normals sum to about zero (the integral
/// of n over a closed surface vanishes), and outward is where they agree
/// with x - c; an open part whose normals share a side (a height field, an
/// aerial scan, a bowl) points up, unless its normals are about horizontal,
/// where up says nothing and x - c decides again (a wall, an open cylinder).
void TurnPartOutward(const std::vector<std::int64_t>& part,
  const OrderedCloud& ordered,
  const std::vector<double>& normals,
  std::vector<signed char>& signs)
{
  double centroid[3] = { 0.0, 0.0, 0.0 }, sum[3] = { 0.0, 0.0, 0.0 };
  for (const std::int64_t p : part)
  {
    double x[3];
    ordered.Point(p, x);
    for (int k = 0; k < 3; ++k)
    {
      centroid[k] += x[k];
      sum[k] += signs[p] * normals[3 * p + k];
    }
  }
  const double count = static_cast<double>(part.size());
  for (double& c : centroid)
  {
    c /= count;
  }
  double signedSum = 0.0;
  for (const std::int64_t p : part)
  {
    double x[3];
    ordered.Point(p, x);
    const double d[3] = { x[0] - centroid[0], x[1] - centroid[1], x[2] - centroid[2] };
    signedSum += signs[p] * Dot(&normals[3 * p], d);
  }
  const double meanLength = std::sqrt(Dot(sum, sum)) / count;
  const bool open = meanLength > 0.3 && std::fabs(sum[2]) > 0.3 * std::sqrt(Dot(sum, sum));
  const bool flip = open ? sum[2] < 0.0 : signedSum < 0.0;
  if (flip)
  {
    for (const std::int64_t p : part)
    {
      signs[p] = static_cast<signed char>(-signs[p]);
    }
  }
}

/// Each normal on the side the settings ask for, point by point.
void OrientPointwise(const NormalSettings& settings,
  const OrderedCloud& ordered,
  std::vector<double>& normals)
{
  for (std::int64_t p = 0; p < ordered.Size(); ++p)
  {
    double x[3];
    ordered.Point(p, x);
    double towards[3];
    for (int k = 0; k < 3; ++k)
    {
      towards[k] = settings.Orientation == NormalOrientation::TowardsViewpoint
        ? settings.Viewpoint[k] - x[k]
        : settings.Axis[k];
    }
    if (Dot(&normals[3 * p], towards) < 0.0)
    {
      Flip(&normals[3 * p]);
    }
  }
}

/// Orients every connected part of the graph (NormalOrientation::Outward);
/// false when the progress monitor asked to stop. The fits' repeated edges
/// are dropped.
template<typename Index>
bool OrientOutward(PlaneFits& fits,
  const OrderedCloud& ordered,
  WorkRunner& runner,
  std::vector<double>& normals,
  NormalSummary& summary,
  StageProgress* progress)
{
  const std::int64_t n = ordered.Size();
  DropRepeatedEdges(fits, runner);
  const Graph<Index> graph(fits, runner);
  std::vector<signed char> signs(n, 0); // 0: not reached yet
  FrontierBuckets<Index> frontier;
  for (std::int64_t p = 0; p < n; ++p)
  {
    if (signs[p] == 0 && !IsZero(&normals[3 * p]))
    {
      TurnPartOutward(OrientPart(graph, p, signs, frontier, progress), ordered, normals, signs);
      ++summary.Components;
      if (progress && progress->Stopped())
      {
        return false;
      }
    }
  }
  for (std::int64_t p = 0; p < n; ++p)
  {
    if (signs[p] < 0)
    {
      Flip(&normals[3 * p]);
    }
  }
  return true;
}
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
  // Every point's slot (the last, empty one when it is near no sample
  // point), then the points by slot.
  const std::int64_t n = cloud.GetNumberOfPoints();
  const std::int64_t slots = static_cast<std::int64_t>(keys.size()) + 1;
  std::vector<std::int32_t> slotOf(n);
  runner.For(n,
    65536,
    [&](std::int64_t begin, std::int64_t end)
    {
      for (std::int64_t i = begin; i < end; ++i)
      {
        slotOf[i] =
          static_cast<std::int32_t>(this->Find(Key(this->CellOf(&cloud.Coordinates[3 * i]))));
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

/// TypicalRadius(cloud, alone, boxes, k) (CloudStatistics.cxx) without its
/// grid over the whole cloud, which took as long as a tenth of the normals:
/// the same sample (InSpacingSample), the same exact distances to the
/// (k + 1)-th nearest point, the same median; the neighbours of the ~512
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
  const std::int64_t count = boxes.GlobalCount;
  const std::int64_t searched = cloud.GetNumberOfPoints();
  if (count < 2 || searched <= k + 1)
  {
    return false;
  }
  const std::int64_t stride = std::max<std::int64_t>(1, count / 512);
  const double* lower = boxes.SampleLower.data();
  const double* upper = boxes.SampleUpper.data();
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
} // namespace

NormalSummary EstimateNormals(CloudPoints& cloud,
  const NormalSettings& settings,
  WorkRunner& runner,
  std::vector<double>& normals,
  StageProgress* progress)
{
  NormalSummary summary;
  const std::int64_t n = cloud.NumberOfOwnPoints;
  normals.clear();
  if (n == 0)
  {
    return summary;
  }
  const Collectives alone;
  const CloudBoxes boxes = MeasureBoxes(cloud, alone);
  const NormalSettings usable = [&]()
  {
    NormalSettings s = settings;
    s.NumberOfNeighbors = std::max(3, s.NumberOfNeighbors);
    s.GraphNeighbors = std::max(1, s.GraphNeighbors);
    return s;
  }();
  double radius = 0.0;
  if (!QuickTypicalRadius(cloud, boxes, usable.NumberOfNeighbors, runner, radius))
  {
    radius = TypicalRadius(cloud, alone, boxes, usable.NumberOfNeighbors);
  }
  // A stop request is looked at between the serial steps too (each up to a
  // second on a million points); nothing is reported yet.
  if (progress && !progress->Reach(0.0))
  {
    return summary;
  }
  const OrderedCloud ordered(cloud, GlobalLattice(boxes, radius), runner);
  if (progress && !progress->Reach(0.0))
  {
    return summary;
  }

  PlaneFits fits;
  fits.GraphNeighbors = usable.GraphNeighbors;
  fits.Normals.assign(3 * n, 0.0);
  fits.Neighbors.Assign(n * usable.GraphNeighbors, n - 1);
  runner.For(n,
    1024,
    [&](std::int64_t begin, std::int64_t end)
    {
      if (progress && progress->Stopped())
      {
        return;
      }
      NearestSearch search;
      search.Guess = radius;
      for (std::int64_t p = begin; p < end; ++p)
      {
        FitPoint(ordered, usable, p, search, fits);
      }
      if (progress)
      {
        progress->Advance(end - begin);
      }
    });
  if (progress && progress->Stopped())
  {
    return summary;
  }

  // The orientation reads the ordered copy alone: without a halo, the
  // cloud's coordinates are released meanwhile and written back from the
  // copy on the way out, whichever it is.
  struct CoordinatesAside
  {
    CloudPoints& Cloud;
    const OrderedCloud& Ordered;
    WorkRunner& Runner;
    const bool Released;
    ~CoordinatesAside()
    {
      if (this->Released)
      {
        this->Ordered.WriteCoordinates(this->Cloud.Coordinates, this->Runner);
      }
    }
  };
  const CoordinatesAside aside{ cloud, ordered, runner, cloud.GetNumberOfPoints() == n };
  if (aside.Released)
  {
    std::vector<double>().swap(cloud.Coordinates);
  }
  if (usable.Orientation == NormalOrientation::Outward)
  {
    // Twice as many points as 32-bit positions hold: the frontier keeps a
    // sign bit beside each.
    const bool small = n < std::numeric_limits<std::int32_t>::max() / 2;
    if (!(small
            ? OrientOutward<std::int32_t>(fits, ordered, runner, fits.Normals, summary, progress)
            : OrientOutward<std::int64_t>(fits, ordered, runner, fits.Normals, summary, progress)))
    {
      return summary;
    }
  }
  else
  {
    OrientPointwise(usable, ordered, fits.Normals);
  }
  // Allocated last: the orientation's graph is the estimate's peak memory.
  normals.assign(3 * n, 0.0);
  for (std::int64_t p = 0; p < n; ++p)
  {
    const double* normal = &fits.Normals[3 * p];
    summary.Undetermined += IsZero(normal);
    std::copy_n(normal, 3, &normals[3 * ordered.Id(p)]);
  }
  return summary;
}

} // namespace pcurv
