#include "Normals/OrderedCloud.h"

#include "Cloud/CloudPoints.h"
#include "Common/WorkRunner.h"

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

} // namespace normals
} // namespace pcurv
