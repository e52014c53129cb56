/**
 * @file PointGrid.h
 * @brief Uniform-grid neighbor search over a fixed point set (no VTK).
 *
 * Why not vtkStaticPointLocator: its FindPointsWithinRadius reads every
 * candidate through a virtual GetTuple call and was measured to take about
 * two thirds of the whole filter's time at ~375 neighbors per point. Here
 * the points are copied, sorted by cell (a counting sort), so a query reads
 * the candidates of each cell from one contiguous block of memory.
 *
 * The sorted order is also a spatially coherent processing order: points
 * handled one after another are neighbors, which keeps their candidates in
 * cache and is what the dynamic variable adjustment assumes.
 *
 * The cells are those of a GridLattice that every process computes alike
 * from global bounds, and the points of a cell are sorted by coordinates:
 * the order in which a query visits its neighbors, hence every sum, does
 * not depend on the order of the input points or on how they are split
 * among processes.
 */
#ifndef PointGrid_h
#define PointGrid_h

#include "Common/IndexList.h"
#include "Neighbors/GridLattice.h"
#include "Common/WorkRunner.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

namespace pcurv
{

/// Neighbors as offsets q - x from the query point x, one array per axis
/// (the layout the half-plane binning reads). The arrays only grow: the
/// first Count values are the neighbors.
struct NeighborOffsets
{
  std::vector<double> Dx, Dy, Dz;
  std::size_t Count = 0;
};

/// A run of candidate points of a query: entries [Begin, End) of the
/// coordinate arrays X, Y, Z and of the ids.
struct CandidateRun
{
  const double* X;
  const double* Y;
  const double* Z;
  const std::int64_t* Ids;
  std::int64_t Begin, End;
};

/// Points of a shell about a query point: offsets and ids, in buffers
/// reused from query to query (Count of them are the shell's).
struct ShellPoints
{
  std::vector<double> Dx, Dy, Dz;
  std::vector<std::int64_t> Ids;
  std::size_t Count = 0;
};

/// Buffers of SquaredDistanceRanks.
struct RankScratch
{
  std::vector<std::uint32_t> Bucket, Starts;
  std::vector<double> Side;
};

/// The k-th and the l-th smallest (ranks = {k, l}, 1 <= k <= l <= size)
/// of the squared distances of the points within a radius whose square is
/// `top` (GatherNearest's). On a surface they spread about evenly over
/// [0, top] (the count grows with the area): counted into buckets of
/// 1 / size of that range, about one a bucket, only the few in a rank's
/// bucket need ordering. Exact whatever the spread: a bucket of many
/// orders them all.
std::array<double, 2> SquaredDistanceRanks(const std::vector<double>& squared,
  const std::array<std::size_t, 2>& ranks,
  double top,
  RankScratch& scratch);

/// Where each cell's points begin in the cell order (one more entry at the
/// end), 32-bit where the points allow (IndexList): the lattice over a
/// surface's bounding box has several cells a point, most of them empty,
/// and this index is then as large as the sorted coordinates.
class CellStarts
{
public:
  /// A counting sort of `cellOf`, which holds each point's cell in
  /// [0, cells): the starts of the cells, and in `ids` the point indices
  /// cell by cell, in increasing index within a cell.
  void Bucket(const std::vector<std::int64_t>& cellOf,
    std::int64_t cells,
    std::vector<std::int64_t>& ids);

  /// No points, in one cell.
  void Clear();

  std::int64_t operator[](std::int64_t cell) const { return this->Starts[cell]; }

  /// Cells, plus one.
  std::int64_t Size() const { return this->Starts.Size(); }

private:
  IndexList Starts;
};

/// The order of two points within a cell: by coordinates (x, then y, then
/// z), identical points by index. A total order that does not depend on
/// the input's order, so that any sort of a cell gives the same.
/// Point a at p before point b at q.
inline bool PointPrecedes(const double p[3], std::int64_t a, const double q[3], std::int64_t b)
{
  for (int k = 0; k < 3; ++k)
  {
    if (p[k] != q[k])
    {
      return p[k] < q[k];
    }
  }
  return a < b;
}

inline bool PrecedesInCell(const double* coordinates, std::int64_t a, std::int64_t b)
{
  return PointPrecedes(coordinates + 3 * a, a, coordinates + 3 * b, b);
}

/// Points or cells per range when a grid is built on several threads.
constexpr std::int64_t GridBuildGrain = 1 << 15;

class PointGrid
{
public:
  /// Builds the grid over `count` points (xyz triplets, all finite) on the
  /// given lattice; only the cells spanned by these points are stored. Its
  /// passes over the points and the cells run in `runner` where given, in
  /// ranges of `grain` (the same grid on any number of threads).
  void Build(const double* coordinates,
    std::int64_t count,
    const GridLattice& lattice,
    WorkRunner* runner = nullptr,
    std::int64_t grain = GridBuildGrain);

  std::int64_t GetNumberOfPoints() const { return static_cast<std::int64_t>(this->Ids.size()); }
  double GetCellSize() const { return this->Lattice.CellSize; }

  /// Id (index into the coordinates given to Build) of the j-th point in
  /// cell order.
  std::int64_t GetSortedId(std::int64_t j) const { return this->Ids[j]; }
  /// Every id in cell order (GetNumberOfPoints of them).
  const std::int64_t* GetSortedIds() const { return this->Ids.data(); }

  /// Calls visit(q, id) for every point q with |q - x| < radius, in a fixed
  /// order that depends only on the grid and x.
  template<typename Visit>
  void ForEachWithinRadius(const double x[3], double radius, Visit&& visit) const
  {
    if (this->Ids.empty() || !(radius > 0.0))
    {
      return;
    }
    std::array<std::int64_t, 3> low, high;
    this->CellRange(x, radius, low, high);
    const double radiusSquared = radius * radius;
    for (std::int64_t iz = low[2]; iz <= high[2]; ++iz)
    {
      for (std::int64_t iy = low[1]; iy <= high[1]; ++iy)
      {
        const std::int64_t row = (iz * this->Dimensions[1] + iy) * this->Dimensions[0];
        const std::int64_t begin = this->CellStart[row + low[0]];
        const std::int64_t end = this->CellStart[row + high[0] + 1];
        // Cells of one row are contiguous in the sorted order.
        for (std::int64_t j = begin; j < end; ++j)
        {
          const double q[3] = { this->Sorted[0][j], this->Sorted[1][j], this->Sorted[2][j] };
          const double dx = q[0] - x[0], dy = q[1] - x[1], dz = q[2] - x[2];
          if (dx * dx + dy * dy + dz * dz < radiusSquared)
          {
            visit(q, this->Ids[j]);
          }
        }
      }
    }
  }

  /// Replaces `out` with the coordinates (xyz triplets) of every point q with
  /// |q - x| < radius, in the same order as ForEachWithinRadius.
  void GatherWithinRadius(const double x[3], double radius, std::vector<double>& out) const;

  /// The same points as offsets q - x (computed as q[k] - x[k]), in the
  /// same order; sets and returns out.Count. The filter's query: the
  /// buffers are reused from query to query, never cleared (resizing them
  /// cost 3 % of the filter's time).
  std::size_t GatherOffsetsWithinRadius(const double x[3],
    double radius,
    NeighborOffsets& out) const;

  /// Squared distance from x to its k-th nearest point (x itself counts
  /// when it is one of the points), found with growing radius queries.
  /// Returns the largest squared distance when there are fewer points.
  double SquaredDistanceToKth(const double x[3], int k, std::vector<double>& scratch) const;

  /// Gathers into `out`, as GatherShell(x, 0, radius, out) does, every
  /// point strictly within a radius that holds at least k of them (x itself
  /// counts), grown as SquaredDistanceToKth's search is: the k nearest and
  /// some more, with their offsets and ids. Returns that radius, or 0 with
  /// nothing gathered where the search would reach beyond the whole box
  /// (SquaredDistanceToKth then finds the k-th distance).
  double GatherNearest(const double x[3], int k, ShellPoints& out) const;

  /// The same points as ForEachWithinRadius, in another fixed order (that
  /// too depends only on the grid and x), at a cost that follows the points
  /// near x rather than the points of x's cells: cells far denser than the
  /// grid's typical one (a dense patch in a sparse cloud, a scan near its
  /// scanner) are searched through finer cells of their own.
  template<typename Visit>
  void ForEachWithinRadiusFine(const double x[3], double radius, Visit&& visit) const;
  /// The points q with inner <= |q - x| < radius (one shell of a growing
  /// neighborhood), in ForEachWithinRadiusFine's order: their offsets
  /// q - x and ids replace `out`'s; sets and returns out.Count. Branch
  /// free: a shell's edges cut through its cells too randomly for branch
  /// prediction.
  std::size_t GatherShell(const double x[3], double inner, double radius, ShellPoints& out) const;

  /// How many points the cells a query of `radius` around x visits hold:
  /// at least those within the radius, counted at the cost of a few sums.
  std::int64_t CountCandidates(const double x[3], double radius) const
  {
    std::array<std::int64_t, 3> low, high;
    return this->Ids.empty() ? 0 : this->QueryCells(x, radius, low, high);
  }

  /// Cells searched through finer cells of their own.
  std::int64_t GetNumberOfDenseCells() const
  {
    return static_cast<std::int64_t>(this->DenseCells.size());
  }

private:
  /// Calls visit(const CandidateRun&) for runs of points that hold every
  /// point within `radius` of x, in ForEachWithinRadiusFine's order: rows
  /// of cells, a dense cell's rows of finer cells in their place.
  template<typename VisitRun>
  void ForEachCandidateRun(const double x[3], double radius, VisitRun&& visit) const;

  /// The cells a query of `radius` around x visits (low..high per axis),
  /// and the number of points in them.
  std::int64_t QueryCells(const double x[3],
    double radius,
    std::array<std::int64_t, 3>& low,
    std::array<std::int64_t, 3>& high) const;

  /// The local cells (low..high per axis) a query of `radius` around x visits.
  void CellRange(const double x[3],
    double radius,
    std::array<std::int64_t, 3>& low,
    std::array<std::int64_t, 3>& high) const
  {
    for (int k = 0; k < 3; ++k)
    {
      low[k] = this->CellIndex(x[k] - radius, k);
      high[k] = this->CellIndex(x[k] + radius, k);
    }
  }

  /// Local cell index along an axis, clamped to the stored cells.
  std::int64_t CellIndex(double coordinate, int axis) const
  {
    const double cell = static_cast<double>(this->Lattice.Cell(coordinate, axis)) -
      static_cast<double>(this->Low[axis]);
    // Comparisons that send NaN to cell 0: a NaN cast to an integer is
    // undefined behavior.
    const double last = static_cast<double>(this->Dimensions[axis] - 1);
    return static_cast<std::int64_t>(cell > 0.0 ? (cell < last ? cell : last) : 0.0);
  }

  /// A cell much denser than the typical one, split into Split^3 finer
  /// cells: its points, sorted by fine cell (then by coordinates), are
  /// [First, First + Count) of the Fine arrays, fine cell f starting at
  /// FineStart[Starts + f].
  struct DenseCell
  {
    std::array<std::int64_t, 3> Cell; // lattice cell
    int Split = 1;
    std::int64_t First = 0, Starts = 0;
  };

  /// A point of a cell being sorted: its coordinates and id.
  struct CellEntry
  {
    double X[3];
    std::int64_t Id;
  };
  /// The local cells the points span (Low, Dimensions) and the diagonal
  /// of their bounding box.
  void SpanPoints(const double* coordinates, std::int64_t count, const GridLattice& lattice);
  /// Sorted: the coordinates of the points in Ids's order, then each cell
  /// sorted into PrecedesInCell's order.
  void FillSorted(const double* coordinates,
    std::int64_t count,
    std::int64_t numberOfCells,
    WorkRunner* runner,
    std::int64_t grain);
  /// Sorts entries [begin, end) of Ids and Sorted into PrecedesInCell's
  /// order, through `cell` (scratch).
  void SortCell(std::int64_t begin, std::int64_t end, std::vector<CellEntry>& cell);
  /// Finds the cells far denser than the median non-empty one and builds
  /// their finer cells.
  void BuildDenseCells(const double* coordinates);
  /// Splits cell c, holding n points, into finer cells: their points
  /// appended to the Fine arrays, the cell to DenseCells.
  void AddDenseCell(const double* coordinates, std::int64_t c, std::int64_t n);
  /// The fine cell along an axis of coordinate c in dense cell `dense`,
  /// clamped to it (monotone in c, so a query's range of fine cells holds
  /// every point within its radius).
  std::int64_t FineIndex(const DenseCell& dense, double c, int axis) const
  {
    const double f =
      (this->Lattice.CellCoordinate(c, axis) - static_cast<double>(dense.Cell[axis])) *
      static_cast<double>(dense.Split);
    const double last = static_cast<double>(dense.Split - 1);
    return static_cast<std::int64_t>(f > 0.0 ? (f < last ? std::floor(f) : last) : 0.0);
  }
  /// The start radius of a k-nearest search at x: a fine cell's size where
  /// x's cell is dense, else the cell size.
  double StartRadius(const double x[3]) const;

  GridLattice Lattice;
  std::array<std::int64_t, 3> Low{ { 0, 0, 0 } }; // lattice cell of local cell 0
  std::array<std::int64_t, 3> Dimensions{ { 1, 1, 1 } };
  double Diagonal = 0.0;
  CellStarts CellStart; // per cell, its first sorted point; one extra at the end
  std::array<std::vector<double>, 3> Sorted; // coordinates in cell order, one array per axis
  std::vector<std::int64_t> Ids;             // original ids in cell order
  std::vector<std::int32_t> DenseOfCell;     // per cell, its DenseCells index or -1 (empty: none)
  std::vector<DenseCell> DenseCells;
  std::vector<std::int64_t> FineStart;
  std::array<std::vector<double>, 3> Fine; // dense cells' coordinates in fine-cell order
  std::vector<std::int64_t> FineIds;
};

template<typename VisitRun>
void PointGrid::ForEachCandidateRun(const double x[3], double radius, VisitRun&& visit) const
{
  if (this->Ids.empty() || !(radius > 0.0))
  {
    return;
  }
  std::array<std::int64_t, 3> low, high;
  this->CellRange(x, radius, low, high);
  const double* xs = this->Sorted[0].data();
  const double* ys = this->Sorted[1].data();
  const double* zs = this->Sorted[2].data();
  for (std::int64_t iz = low[2]; iz <= high[2]; ++iz)
  {
    for (std::int64_t iy = low[1]; iy <= high[1]; ++iy)
    {
      // Cells of one row are contiguous in the sorted order: one run up to
      // each dense cell, whose fine rows are runs of their own.
      const std::int64_t row = (iz * this->Dimensions[1] + iy) * this->Dimensions[0];
      std::int64_t begin = this->CellStart[row + low[0]];
      for (std::int64_t ix = low[0]; ix <= high[0] && !this->DenseCells.empty(); ++ix)
      {
        const std::int32_t d = this->DenseOfCell[row + ix];
        if (d < 0)
        {
          continue;
        }
        visit(CandidateRun{ xs, ys, zs, this->Ids.data(), begin, this->CellStart[row + ix] });
        begin = this->CellStart[row + ix + 1];
        const DenseCell& dense = this->DenseCells[d];
        std::array<std::int64_t, 3> fineLow, fineHigh;
        for (int k = 0; k < 3; ++k)
        {
          fineLow[k] = this->FineIndex(dense, x[k] - radius, k);
          fineHigh[k] = this->FineIndex(dense, x[k] + radius, k);
        }
        const std::int64_t split = dense.Split;
        for (std::int64_t fz = fineLow[2]; fz <= fineHigh[2]; ++fz)
        {
          for (std::int64_t fy = fineLow[1]; fy <= fineHigh[1]; ++fy)
          {
            const std::int64_t fineRow = dense.Starts + (fz * split + fy) * split;
            visit(CandidateRun{ this->Fine[0].data(),
              this->Fine[1].data(),
              this->Fine[2].data(),
              this->FineIds.data(),
              this->FineStart[fineRow + fineLow[0]],
              this->FineStart[fineRow + fineHigh[0] + 1] });
          }
        }
      }
      visit(
        CandidateRun{ xs, ys, zs, this->Ids.data(), begin, this->CellStart[row + high[0] + 1] });
    }
  }
}

template<typename Visit>
void PointGrid::ForEachWithinRadiusFine(const double x[3], double radius, Visit&& visit) const
{
  const double radiusSquared = radius * radius;
  this->ForEachCandidateRun(x,
    radius,
    [&](const CandidateRun& run)
    {
      for (std::int64_t j = run.Begin; j < run.End; ++j)
      {
        const double q[3] = { run.X[j], run.Y[j], run.Z[j] };
        const double dx = q[0] - x[0], dy = q[1] - x[1], dz = q[2] - x[2];
        if (dx * dx + dy * dy + dz * dz < radiusSquared)
        {
          visit(q, run.Ids[j]);
        }
      }
    });
}

} // namespace pcurv

#endif
