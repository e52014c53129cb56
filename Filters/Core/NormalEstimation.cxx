#include "NormalEstimation.h"

#include "CloudEstimation.h"
#include "PointGrid.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

namespace pcurv
{
namespace
{
double Dot(const double* a, const double* b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

void Flip(double* n)
{
  n[0] = -n[0];
  n[1] = -n[1];
  n[2] = -n[2];
}

bool IsZero(const double* n)
{
  return n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0;
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
class OrderedCloud
{
public:
  OrderedCloud(const CloudPoints& cloud, const GridLattice& lattice)
    : Lattice(lattice)
  {
    const std::int64_t n = cloud.NumberOfOwnPoints;
    this->Grid.Build(cloud.Coordinates.data(), n, lattice);
    this->Ids.resize(n);
    this->PositionOfId.resize(n);
    for (std::vector<double>* axis : { &this->X, &this->Y, &this->Z })
    {
      axis->resize(n);
    }
    for (std::int64_t p = 0; p < n; ++p)
    {
      const std::int64_t id = this->Grid.GetSortedId(p);
      this->Ids[p] = id;
      this->PositionOfId[id] = p;
      this->X[p] = cloud.Coordinates[3 * id];
      this->Y[p] = cloud.Coordinates[3 * id + 1];
      this->Z[p] = cloud.Coordinates[3 * id + 2];
    }
    this->IndexCells();
  }

  std::int64_t Size() const { return static_cast<std::int64_t>(this->Ids.size()); }
  std::int64_t Id(std::int64_t position) const { return this->Ids[position]; }
  void Point(std::int64_t position, double x[3]) const
  {
    x[0] = this->X[position];
    x[1] = this->Y[position];
    x[2] = this->Z[position];
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
    return this->Grid.SquaredDistanceToKth(x, k, scratch);
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

  /// CellStart from the positions' cells; rows are unusable (every query
  /// then goes through the grid) if the positions were not in cell order.
  void IndexCells();

  GridLattice Lattice;
  PointGrid Grid; // over the cloud's own ids
  std::vector<double> X, Y, Z;
  std::vector<std::int64_t> Ids;          // position -> point id
  std::vector<std::int64_t> PositionOfId; // point id -> position
  std::array<std::int64_t, 3> Low{ { 0, 0, 0 } };
  std::array<std::int64_t, 3> Dimensions{ { 1, 1, 1 } };
  std::vector<std::int64_t> CellStart; // per cell its first position, one extra at the end
  bool RowsUsable = false;
};

void OrderedCloud::IndexCells()
{
  const std::int64_t n = this->Size();
  if (n == 0)
  {
    return;
  }
  double lower[3], upper[3];
  for (int k = 0; k < 3; ++k)
  {
    const std::vector<double>& axis = k == 0 ? this->X : k == 1 ? this->Y : this->Z;
    const auto [smallest, largest] = std::minmax_element(axis.begin(), axis.end());
    lower[k] = *smallest;
    upper[k] = *largest;
  }
  for (int k = 0; k < 3; ++k)
  {
    this->Low[k] = this->Lattice.Cell(lower[k], k);
    this->Dimensions[k] = this->Lattice.Cell(upper[k], k) - this->Low[k] + 1;
  }
  const std::int64_t cells = this->Dimensions[0] * this->Dimensions[1] * this->Dimensions[2];
  this->CellStart.assign(cells + 1, 0);
  std::int64_t previous = 0;
  bool ordered = true;
  for (std::int64_t p = 0; p < n; ++p)
  {
    const std::int64_t cell =
      (this->CellIndex(this->Z[p], 2) * this->Dimensions[1] + this->CellIndex(this->Y[p], 1)) *
        this->Dimensions[0] +
      this->CellIndex(this->X[p], 0);
    ordered = ordered && cell >= previous;
    previous = cell;
    ++this->CellStart[cell + 1];
  }
  for (std::int64_t c = 0; c < cells; ++c)
  {
    this->CellStart[c + 1] += this->CellStart[c];
  }
  this->RowsUsable = ordered;
}

bool OrderedCloud::GatherRows(const double x[3],
  double radius,
  std::size_t limit,
  Candidates& out) const
{
  if (!this->RowsUsable)
  {
    return false;
  }
  std::array<std::int64_t, 3> low, high;
  for (int k = 0; k < 3; ++k)
  {
    low[k] = this->CellIndex(x[k] - radius, k);
    high[k] = this->CellIndex(x[k] + radius, k);
  }
  auto rowStart = [&](std::int64_t iz, std::int64_t iy)
  { return (iz * this->Dimensions[1] + iy) * this->Dimensions[0]; };
  std::size_t total = 0;
  for (std::int64_t iz = low[2]; iz <= high[2]; ++iz)
  {
    for (std::int64_t iy = low[1]; iy <= high[1]; ++iy)
    {
      const std::int64_t row = rowStart(iz, iy);
      total += static_cast<std::size_t>(
        this->CellStart[row + high[0] + 1] - this->CellStart[row + low[0]]);
    }
  }
  if (total > limit)
  {
    return false;
  }
  out.Reserve(total);
  const double radiusSquared = radius * radius;
  const double* xs = this->X.data();
  const double* ys = this->Y.data();
  const double* zs = this->Z.data();
  double* squared = out.Squared.data();
  std::int64_t* positions = out.Positions.data();
  std::size_t kept = 0;
  for (std::int64_t iz = low[2]; iz <= high[2]; ++iz)
  {
    for (std::int64_t iy = low[1]; iy <= high[1]; ++iy)
    {
      const std::int64_t row = rowStart(iz, iy);
      const std::int64_t end = this->CellStart[row + high[0] + 1];
      // Every candidate is written, at the first free place; only those
      // within the radius advance it (branch free: a sphere cuts through
      // the rows too randomly for branch prediction).
      for (std::int64_t j = this->CellStart[row + low[0]]; j < end; ++j)
      {
        const double dx = xs[j] - x[0], dy = ys[j] - x[1], dz = zs[j] - x[2];
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
  const std::size_t count = this->Grid.GatherShell(x, 0.0, radius, shell);
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

/// What the per-point pass leaves for the orientation: in grid order, the
/// normal (arbitrary sign) and the nearest neighbours' grid positions.
struct PlaneFits
{
  std::vector<double> Normals;         // 3 per grid position
  std::vector<std::int64_t> Neighbors; // GraphNeighbors per position, -1 padded
  int GraphNeighbors = 0;
};

/// The normal of the plane through the neighbours (offsets from the point,
/// in units of the radius) by PCA: the eigenvector of the smallest
/// eigenvalue of their covariance; signed so that its largest component is
/// positive (any fixed rule: the orientation decides the sign later). The
/// sums run in the neighbours' order, one accumulator a matrix entry.
void FitPlane(const NeighborOffsets& offsets, double inverseRadius, double* normal)
{
  const std::size_t count = offsets.Count;
  const double* dx = offsets.Dx.data();
  const double* dy = offsets.Dy.data();
  const double* dz = offsets.Dz.data();
  double mx = 0.0, my = 0.0, mz = 0.0;
  for (std::size_t i = 0; i < count; ++i)
  {
    mx += dx[i] * inverseRadius;
    my += dy[i] * inverseRadius;
    mz += dz[i] * inverseRadius;
  }
  const double size = static_cast<double>(count);
  mx /= size;
  my /= size;
  mz /= size;
  double xx = 0.0, yx = 0.0, zx = 0.0, yy = 0.0, zy = 0.0, zz = 0.0;
  for (std::size_t i = 0; i < count; ++i)
  {
    const double x = dx[i] * inverseRadius - mx;
    const double y = dy[i] * inverseRadius - my;
    const double z = dz[i] * inverseRadius - mz;
    xx += x * x;
    yx += y * x;
    zx += z * x;
    yy += y * y;
    zy += z * y;
    zz += z * z;
  }
  Eigen::Matrix3d covariance;
  covariance << xx, yx, zx, yx, yy, zy, zx, zy, zz;
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
}

/// The nearest others of a point by (squared distance, position), at most
/// `wanted` of them: a sorted insertion, the list being short.
class NearestOthers
{
public:
  NearestOthers(int wanted, std::vector<std::pair<double, std::int64_t>>& buffer)
    : Wanted(static_cast<std::size_t>(wanted))
    , Entries(buffer)
  {
    this->Entries.resize(this->Wanted);
  }

  void Offer(double squared, std::int64_t position)
  {
    const std::pair<double, std::int64_t> entry(squared, position);
    if (this->Size == this->Wanted && !(entry < this->Entries[this->Size - 1]))
    {
      return;
    }
    std::size_t i = this->Size < this->Wanted ? this->Size++ : this->Size - 1;
    for (; i > 0 && entry < this->Entries[i - 1]; --i)
    {
      this->Entries[i] = this->Entries[i - 1];
    }
    this->Entries[i] = entry;
  }

  /// Writes the positions, nearest first, -1 padded to `count`.
  void Write(std::int64_t* edges, int count) const
  {
    for (std::size_t e = 0; e < static_cast<std::size_t>(count); ++e)
    {
      edges[e] = e < this->Size ? this->Entries[e].second : -1;
    }
  }

private:
  std::size_t Wanted;
  std::size_t Size = 0;
  std::vector<std::pair<double, std::int64_t>>& Entries;
};

/// One thread's buffers of the k-nearest search, and its guess of the
/// radius: the last point's, the points being visited in grid order (so
/// the next one is near and about as dense).
struct NearestSearch
{
  Candidates Found;
  ShellPoints Shell;
  std::vector<double> Selected;
  NeighborOffsets Offsets;
  std::vector<std::pair<double, std::int64_t>> Nearest;
  double Guess = 0.0;
};

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
/// of them, starting from the guess and growing it; false after a few
/// tries, which a point far from the others needs. Whatever radius finds
/// them, the k-th distance among them is the same: the guess only changes
/// the cost.
bool GatherAtLeast(const OrderedCloud& ordered,
  const double x[3],
  std::size_t wanted,
  NearestSearch& search)
{
  constexpr int Tries = 6;
  double radius = search.Guess;
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

/// The k-th smallest of the candidates' squared distances.
double KthSquared(NearestSearch& search, std::size_t k)
{
  const Candidates& found = search.Found;
  search.Selected.assign(found.Squared.begin(), found.Squared.begin() + found.Count);
  std::nth_element(
    search.Selected.begin(), search.Selected.begin() + (k - 1), search.Selected.end());
  return search.Selected[k - 1];
}

/// Keeps the candidates nearer than `radius` (every point nearer than the
/// k-th): their offsets in position order into search.Offsets, the nearest
/// others into `nearest`.
void KeepWithinRadius(const OrderedCloud& ordered,
  const double x[3],
  std::int64_t position,
  double radius,
  NearestSearch& search,
  NearestOthers& nearest)
{
  Candidates& found = search.Found;
  const double radiusSquared = radius * radius;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < found.Count; ++i)
  {
    const std::int64_t other = found.Positions[i];
    if (found.Squared[i] < radiusSquared)
    {
      found.Positions[kept++] = other;
      if (other != position)
      {
        nearest.Offer(found.Squared[i], other);
      }
    }
  }
  if (!found.InOrder)
  {
    std::sort(found.Positions.begin(), found.Positions.begin() + kept);
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
  const bool found =
    static_cast<std::size_t>(ordered.Size()) > wanted && GatherAtLeast(ordered, x, wanted, search);
  const double squared = found
    ? KthSquared(search, wanted)
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
  NearestOthers nearest(fits.GraphNeighbors, search.Nearest);
  KeepWithinRadius(ordered, x, position, radius, search, nearest);
  search.Guess = 1.1 * radius;
  if (search.Offsets.Count < 3)
  {
    normal[0] = normal[1] = normal[2] = 0.0;
    return;
  }
  FitPlane(search.Offsets, 1.0 / radius, normal);
  nearest.Write(&fits.Neighbors[position * fits.GraphNeighbors], fits.GraphNeighbors);
}

/// Which graph edges a -> b the orientation can do without: those whose
/// reverse b -> a is an edge too and comes later in a's adjacency list
/// (b > a). The traversal pushes both with the same weight and sign, the
/// later one is popped first (last in, first out within a bucket), and
/// the earlier one then always finds b reached: dropping it changes
/// nothing but the work.
std::vector<unsigned char> FindRepeatedEdges(const PlaneFits& fits, WorkRunner& runner)
{
  const int k = fits.GraphNeighbors;
  const std::int64_t n = static_cast<std::int64_t>(fits.Normals.size() / 3);
  std::vector<unsigned char> repeated(fits.Neighbors.size(), 0);
  runner.For(n,
    4096,
    [&](std::int64_t begin, std::int64_t end, EstimationScratch&)
    {
      for (std::int64_t a = begin; a < end; ++a)
      {
        for (int e = 0; e < k; ++e)
        {
          const std::int64_t b = fits.Neighbors[a * k + e];
          if (b > a)
          {
            const std::int64_t* back = &fits.Neighbors[b * k];
            repeated[a * k + e] = std::find(back, back + k, a) != back + k;
          }
        }
      }
    });
  return repeated;
}

/// The edges of the orientation graph, both directions, as adjacency lists
/// (in the order of the edges a -> b by a, then by b's rank among a's
/// nearest: the order the traversal's ties follow). Targets of type Index:
/// 32 bits where they fit halve the memory the traversal reads.
template<typename Index>
struct Graph
{
  std::vector<std::int64_t> Start; // per position, its first entry of Targets; one extra
  std::vector<Index> Targets;

  Graph(const PlaneFits& fits, WorkRunner& runner)
  {
    const std::vector<unsigned char> repeated = FindRepeatedEdges(fits, runner);
    const int k = fits.GraphNeighbors;
    const std::int64_t n = static_cast<std::int64_t>(fits.Normals.size() / 3);
    std::vector<std::int64_t> degree(n + 1, 0);
    auto forEachEdge = [&](auto&& visit)
    {
      for (std::int64_t a = 0; a < n; ++a)
      {
        for (int e = 0; e < k; ++e)
        {
          const std::int64_t b = fits.Neighbors[a * k + e];
          if (b >= 0 && !repeated[a * k + e])
          {
            visit(static_cast<Index>(a), static_cast<Index>(b));
            visit(static_cast<Index>(b), static_cast<Index>(a));
          }
        }
      }
    };
    forEachEdge([&](Index a, Index) { ++degree[a + 1]; });
    for (std::int64_t a = 0; a < n; ++a)
    {
      degree[a + 1] += degree[a];
    }
    this->Start = degree;
    this->Targets.resize(static_cast<std::size_t>(degree[n]));
    forEachEdge([&](Index a, Index b) { this->Targets[degree[a]++] = b; });
  }
};

/// What the traversal needs of an edge a -> b, worked out in parallel
/// before it: the bucket of its weight sqrt(1 - |n_a . n_b|) (about the
/// angle between the normals), and how b's sign follows a's (the sign of
/// n_a . n_b; zero: b keeps its own). The traversal then reads no normal.
/// Edges to a point without a normal are never followed.
class EdgeWeights
{
public:
  static constexpr int Buckets = 1024;
  static constexpr std::int16_t Unused = -1;

  template<typename Index>
  EdgeWeights(const Graph<Index>& graph, const std::vector<double>& normals, WorkRunner& runner)
    : Codes(graph.Targets.size())
  {
    const std::int64_t n = static_cast<std::int64_t>(graph.Start.size()) - 1;
    runner.For(n,
      4096,
      [&](std::int64_t begin, std::int64_t end, EstimationScratch&)
      {
        for (std::int64_t a = begin; a < end; ++a)
        {
          for (std::int64_t e = graph.Start[a]; e < graph.Start[a + 1]; ++e)
          {
            this->Codes[e] = Code(&normals[3 * a], &normals[3 * std::int64_t{ graph.Targets[e] }]);
          }
        }
      });
  }

  /// The bucket of an edge's weight, from the agreement |n_a . n_b|.
  static int Bucket(double agreement)
  {
    const double weight = std::sqrt(std::max(0.0, 1.0 - agreement));
    return std::min(Buckets - 1, static_cast<int>(weight * Buckets));
  }

  bool Followed(std::int64_t e) const { return this->Codes[e] != Unused; }
  int Bucket(std::int64_t e) const { return this->Codes[e] >> 2; }
  /// The sign of b given the sign of a.
  signed char Propagate(std::int64_t e, signed char sign) const
  {
    const int relation = this->Codes[e] & 3;
    return relation == Same ? sign : relation == Opposite ? static_cast<signed char>(-sign) : 1;
  }

private:
  enum Relation : std::int16_t
  {
    Unrelated = 0,
    Same = 1,
    Opposite = 2
  };

  static std::int16_t Code(const double* a, const double* b)
  {
    if (IsZero(b))
    {
      return Unused;
    }
    // n_b's sign flips exactly with n_a's: the agreement, and the relation,
    // do not depend on the signs chosen so far.
    const double dot = Dot(a, b);
    const std::int16_t relation = dot > 0.0 ? Same : dot < 0.0 ? Opposite : Unrelated;
    return static_cast<std::int16_t>(Bucket(std::fabs(dot)) * 4 + relation);
  }

  std::vector<std::int16_t> Codes; // per adjacency entry: bucket * 4 + relation, or Unused
};

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
  std::vector<std::make_unsigned_t<Index>> Buckets[EdgeWeights::Buckets];
  int Lowest = EdgeWeights::Buckets - 1;
  std::int64_t Size = 0;
};

/// Propagates the sign from `seed` over a minimum spanning tree of the
/// normals' disagreement 1 - |n_a . n_b| (Prim's, weights in buckets):
/// signs[p] becomes +1 or -1 (the normal as fitted, or flipped) for the
/// part's points; returns them in the order reached.
template<typename Index>
std::vector<std::int64_t> OrientPart(const Graph<Index>& graph,
  const EdgeWeights& weights,
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
  frontier.Push(EdgeWeights::Bucket(1.0), static_cast<Index>(seed), 1);
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
      const Index next = graph.Targets[e];
      if (signs[next] == 0 && weights.Followed(e))
      {
        frontier.Push(weights.Bucket(e), next, weights.Propagate(e, sign));
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
/// false when the progress monitor asked to stop.
template<typename Index>
bool OrientOutward(const PlaneFits& fits,
  const OrderedCloud& ordered,
  WorkRunner& runner,
  std::vector<double>& normals,
  NormalSummary& summary,
  StageProgress* progress)
{
  const std::int64_t n = ordered.Size();
  const Graph<Index> graph(fits, runner);
  const EdgeWeights weights(graph, normals, runner);
  std::vector<signed char> signs(n, 0); // 0: not reached yet
  FrontierBuckets<Index> frontier;
  for (std::int64_t p = 0; p < n; ++p)
  {
    if (signs[p] == 0 && !IsZero(&normals[3 * p]))
    {
      TurnPartOutward(
        OrientPart(graph, weights, p, signs, frontier, progress), ordered, normals, signs);
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
} // namespace

NormalSummary EstimateNormals(const CloudPoints& cloud,
  const NormalSettings& settings,
  WorkRunner& runner,
  std::vector<double>& normals,
  StageProgress* progress)
{
  NormalSummary summary;
  const std::int64_t n = cloud.NumberOfOwnPoints;
  normals.assign(3 * n, 0.0);
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
  const double radius = TypicalRadius(cloud, alone, boxes, usable.NumberOfNeighbors);
  // A stop request is looked at between the serial steps too (each up to a
  // second on a million points); nothing is reported yet.
  if (progress && !progress->Reach(0.0))
  {
    return summary;
  }
  const OrderedCloud ordered(cloud, GlobalLattice(boxes, radius));
  if (progress && !progress->Reach(0.0))
  {
    return summary;
  }

  PlaneFits fits;
  fits.GraphNeighbors = usable.GraphNeighbors;
  fits.Normals.assign(3 * n, 0.0);
  fits.Neighbors.assign(n * usable.GraphNeighbors, -1);
  runner.For(n,
    1024,
    [&](std::int64_t begin, std::int64_t end, EstimationScratch&)
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
  for (std::int64_t p = 0; p < n; ++p)
  {
    const double* normal = &fits.Normals[3 * p];
    summary.Undetermined += IsZero(normal);
    std::copy_n(normal, 3, &normals[3 * ordered.Id(p)]);
  }
  return summary;
}

} // namespace pcurv
