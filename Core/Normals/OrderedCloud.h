/**
 * @file OrderedCloud.h
 * @brief The cloud in the neighbor grid's order, one array per axis, for the
 * normals' radius queries: internal to the normal estimation. No VTK.
 */
#ifndef OrderedCloud_h
#define OrderedCloud_h

#include "Cloud/CloudPoints.h"
#include "Common/IndexList.h"
#include "Neighbors/PointGrid.h"

#include <cstdint>
#include <mutex>
#include <vector>

namespace pcurv
{

class WorkRunner;

namespace normals
{

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

/// The cloud's points in the neighbor grid's order (the positions), one
/// array per axis, with the first position of each of the grid's cells.
/// Cells of a row being consecutive in that order, a radius query reads
/// contiguous runs of positions: it finds the neighbors in position order
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

} // namespace normals
} // namespace pcurv

#endif
