#include "Neighbors/PointGrid.h"

#include "Kernels/SimdKernels.h"

#include <limits>

namespace pcurv
{

GridLattice GridLattice::Make(const double lower[3],
  const double upper[3],
  std::int64_t count,
  double cellSize)
{
  GridLattice lattice;
  double diagonalSquared = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    lattice.Origin[k] = lower[k];
    diagonalSquared += (upper[k] - lower[k]) * (upper[k] - lower[k]);
  }
  // Finite whatever the box: a cell size of Inf would turn cell
  // coordinates into NaN.
  const double largest = std::numeric_limits<double>::max();
  double size = cellSize > 0.0 && std::isfinite(cellSize) ? cellSize : std::sqrt(diagonalSquared);
  if (!(size > 0.0))
  {
    size = 1.0; // all points coincide
  }
  size = std::min(size, largest);
  const double maximumCells = 4.0 * static_cast<double>(count) + 4096.0;
  for (;;)
  {
    // In halves, so that an extent beyond the largest double stays finite;
    // each axis's count capped, so that the product cannot overflow.
    double cells = 1.0;
    for (int k = 0; k < 3; ++k)
    {
      const double halfExtent = 0.5 * upper[k] - 0.5 * lower[k];
      cells *= std::min(std::floor(halfExtent / (0.5 * size)) + 1.0, maximumCells + 1.0);
    }
    if (cells <= maximumCells || size == largest)
    {
      break;
    }
    const double grown = std::min(size * std::max(1.01, std::cbrt(cells / maximumCells)), largest);
    // A subnormal size times 1.01 can round back to itself: double it then.
    size = grown > size ? grown : std::min(2.0 * size, largest);
  }
  lattice.CellSize = size;
  for (int k = 0; k < 3; ++k)
  {
    lattice.LastCell[k] = std::floor((0.5 * upper[k] - 0.5 * lower[k]) / (0.5 * size));
  }
  return lattice;
}

void CellStarts::Bucket(const std::vector<std::int64_t>& cellOf,
  std::int64_t cells,
  std::vector<std::int64_t>& ids)
{
  const std::int64_t count = static_cast<std::int64_t>(cellOf.size());
  this->Starts.Assign(cells + 1, count, 0);
  // Counts, their running sum, then each point placed at its cell's next
  // free place, which moves every start one cell on: moved back after, so
  // that no second array is needed.
  this->Starts.Visit(
    [&](auto* starts)
    {
      for (std::int64_t i = 0; i < count; ++i)
      {
        ++starts[cellOf[i] + 1];
      }
      for (std::int64_t c = 0; c < cells; ++c)
      {
        starts[c + 1] += starts[c];
      }
      ids.resize(static_cast<std::size_t>(count));
      for (std::int64_t i = 0; i < count; ++i)
      {
        ids[starts[cellOf[i]]++] = i;
      }
      // starts[c] is now where cell c + 1 begins.
      for (std::int64_t c = cells; c > 0; --c)
      {
        starts[c] = starts[c - 1];
      }
      starts[0] = 0;
    });
}

void CellStarts::Clear()
{
  this->Starts.Assign(2, 0, 0);
}

void PointGrid::Build(const double* coordinates,
  std::int64_t count,
  const GridLattice& lattice,
  WorkRunner* runner,
  std::int64_t grain)
{
  // Each range writes entries of its own: the same grid on any number of
  // threads.
  const auto inRanges = [runner, grain](std::int64_t n, const RangeWork& work)
  { RunRanges(runner, n, grain, work); };
  this->Lattice = lattice;
  this->Ids.clear();
  for (std::vector<double>& axis : this->Sorted)
  {
    axis.clear();
  }
  this->CellStart.Clear();
  this->Low = { { 0, 0, 0 } };
  this->Dimensions = { { 1, 1, 1 } };
  this->Diagonal = 0.0;
  if (count <= 0)
  {
    return;
  }
  this->SpanPoints(coordinates, count, lattice);

  // Counting sort by cell.
  const std::int64_t numberOfCells =
    this->Dimensions[0] * this->Dimensions[1] * this->Dimensions[2];
  std::vector<std::int64_t> cellOf(count);
  inRanges(count,
    [&](std::int64_t begin, std::int64_t end)
    {
      for (std::int64_t i = begin; i < end; ++i)
      {
        const double* x = coordinates + 3 * i;
        cellOf[i] = (this->CellIndex(x[2], 2) * this->Dimensions[1] + this->CellIndex(x[1], 1)) *
            this->Dimensions[0] +
          this->CellIndex(x[0], 0);
      }
    });
  this->CellStart.Bucket(cellOf, numberOfCells, this->Ids);
  this->FillSorted(coordinates, count, numberOfCells, runner, grain);
  this->BuildDenseCells(coordinates);
}

void PointGrid::SpanPoints(const double* coordinates,
  std::int64_t count,
  const GridLattice& lattice)
{
  std::array<std::int64_t, 3> high;
  std::array<double, 3> lower, upper;
  for (int k = 0; k < 3; ++k)
  {
    lower[k] = upper[k] = coordinates[k];
  }
  for (std::int64_t i = 1; i < count; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      lower[k] = std::min(lower[k], coordinates[3 * i + k]);
      upper[k] = std::max(upper[k], coordinates[3 * i + k]);
    }
  }
  double diagonalSquared = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    this->Low[k] = lattice.Cell(lower[k], k);
    high[k] = lattice.Cell(upper[k], k);
    this->Dimensions[k] = high[k] - this->Low[k] + 1;
    diagonalSquared += (upper[k] - lower[k]) * (upper[k] - lower[k]);
  }
  this->Diagonal = std::sqrt(diagonalSquared);
}

void PointGrid::FillSorted(const double* coordinates,
  std::int64_t count,
  std::int64_t numberOfCells,
  WorkRunner* runner,
  std::int64_t grain)
{
  // The coordinates in cell order (one pass of scattered reads), then each
  // cell sorted by coordinates, which makes the order independent of the
  // input's: the cell's points copied side by side for the sort, whose
  // comparisons would otherwise each read two scattered points.
  for (int k = 0; k < 3; ++k)
  {
    this->Sorted[k].resize(count);
  }
  RunRanges(runner,
    count,
    grain,
    [&](std::int64_t begin, std::int64_t end)
    {
      constexpr std::int64_t Ahead = 16;
      for (std::int64_t j = begin; j < end; ++j)
      {
        if (j + Ahead < end)
        {
          __builtin_prefetch(coordinates + 3 * this->Ids[j + Ahead]);
        }
        const double* x = coordinates + 3 * this->Ids[j];
        for (int k = 0; k < 3; ++k)
        {
          this->Sorted[k][j] = x[k];
        }
      }
    });
  RunRanges(runner,
    numberOfCells,
    grain,
    [&](std::int64_t begin, std::int64_t end)
    {
      std::vector<CellEntry> cell;
      for (std::int64_t c = begin; c < end; ++c)
      {
        if (this->CellStart[c + 1] - this->CellStart[c] > 1)
        {
          this->SortCell(this->CellStart[c], this->CellStart[c + 1], cell);
        }
      }
    });
}

void PointGrid::SortCell(std::int64_t begin, std::int64_t end, std::vector<CellEntry>& cell)
{
  cell.resize(static_cast<std::size_t>(end - begin));
  for (std::int64_t j = begin; j < end; ++j)
  {
    cell[j - begin] = { { this->Sorted[0][j], this->Sorted[1][j], this->Sorted[2][j] },
      this->Ids[j] };
  }
  std::sort(cell.begin(),
    cell.end(),
    [](const CellEntry& a, const CellEntry& b) { return PointPrecedes(a.X, a.Id, b.X, b.Id); });
  for (std::int64_t j = begin; j < end; ++j)
  {
    const CellEntry& entry = cell[j - begin];
    this->Ids[j] = entry.Id;
    for (int k = 0; k < 3; ++k)
    {
      this->Sorted[k][j] = entry.X[k];
    }
  }
}

void PointGrid::BuildDenseCells(const double* coordinates)
{
  this->DenseOfCell.clear();
  this->DenseCells.clear();
  this->FineStart.clear();
  this->FineIds.clear();
  for (std::vector<double>& axis : this->Fine)
  {
    axis.clear();
  }
  const std::int64_t numberOfCells = this->CellStart.Size() - 1;
  std::vector<std::int64_t> counts;
  for (std::int64_t c = 0; c < numberOfCells; ++c)
  {
    const std::int64_t n = this->CellStart[c + 1] - this->CellStart[c];
    if (n > 0)
    {
      counts.push_back(n);
    }
  }
  if (counts.empty())
  {
    return;
  }
  std::nth_element(counts.begin(), counts.begin() + counts.size() / 2, counts.end());
  // Dense: more than 16 times the median cell and than 256 points, where
  // scanning the whole cell for every query costs far more than the
  // neighbors found.
  const std::int64_t dense = std::max<std::int64_t>(256, 16 * counts[counts.size() / 2]);
  for (std::int64_t c = 0; c < numberOfCells; ++c)
  {
    const std::int64_t n = this->CellStart[c + 1] - this->CellStart[c];
    if (n <= dense)
    {
      continue;
    }
    if (this->DenseOfCell.empty())
    {
      this->DenseOfCell.assign(numberOfCells, -1);
    }
    this->AddDenseCell(coordinates, c, n);
  }
}

void PointGrid::AddDenseCell(const double* coordinates, std::int64_t c, std::int64_t n)
{
  DenseCell cell;
  const std::int64_t ix = c % this->Dimensions[0];
  const std::int64_t iy = (c / this->Dimensions[0]) % this->Dimensions[1];
  const std::int64_t iz = c / (this->Dimensions[0] * this->Dimensions[1]);
  cell.Cell = { { this->Low[0] + ix, this->Low[1] + iy, this->Low[2] + iz } };
  // About 8 points a fine cell were the points spread through the volume;
  // on a surface, more (its fine cells are fewer).
  cell.Split = static_cast<int>(std::min(64.0, std::max(2.0, std::cbrt(n / 8.0))));
  cell.First = static_cast<std::int64_t>(this->FineIds.size());
  cell.Starts = static_cast<std::int64_t>(this->FineStart.size());
  const std::int64_t fineCells = static_cast<std::int64_t>(cell.Split) * cell.Split * cell.Split;
  std::vector<std::pair<std::int64_t, std::int64_t>> keyed; // (fine cell, sorted position)
  keyed.reserve(n);
  for (std::int64_t j = this->CellStart[c]; j < this->CellStart[c + 1]; ++j)
  {
    const double* q = coordinates + 3 * this->Ids[j];
    const std::int64_t f =
      (this->FineIndex(cell, q[2], 2) * cell.Split + this->FineIndex(cell, q[1], 1)) * cell.Split +
      this->FineIndex(cell, q[0], 0);
    keyed.emplace_back(f, j); // j: the cell's order by coordinates, kept within a fine cell
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::int64_t> starts(fineCells + 1, 0);
  for (const auto& entry : keyed)
  {
    ++starts[entry.first + 1];
  }
  for (std::int64_t f = 0; f < fineCells; ++f)
  {
    starts[f + 1] += starts[f];
  }
  for (std::int64_t& start : starts)
  {
    start += cell.First;
  }
  this->FineStart.insert(this->FineStart.end(), starts.begin(), starts.end());
  for (const auto& entry : keyed)
  {
    for (int k = 0; k < 3; ++k)
    {
      this->Fine[k].push_back(this->Sorted[k][entry.second]);
    }
    this->FineIds.push_back(this->Ids[entry.second]);
  }
  this->DenseOfCell[c] = static_cast<std::int32_t>(this->DenseCells.size());
  this->DenseCells.push_back(cell);
}

double PointGrid::StartRadius(const double x[3]) const
{
  if (this->DenseCells.empty())
  {
    return this->Lattice.CellSize;
  }
  const std::int64_t c =
    (this->CellIndex(x[2], 2) * this->Dimensions[1] + this->CellIndex(x[1], 1)) *
      this->Dimensions[0] +
    this->CellIndex(x[0], 0);
  const std::int32_t d = this->DenseOfCell[c];
  return d < 0 ? this->Lattice.CellSize : this->Lattice.CellSize / this->DenseCells[d].Split;
}

std::int64_t PointGrid::QueryCells(const double x[3],
  double radius,
  std::array<std::int64_t, 3>& low,
  std::array<std::int64_t, 3>& high) const
{
  this->CellRange(x, radius, low, high);
  std::int64_t candidates = 0;
  for (std::int64_t iz = low[2]; iz <= high[2]; ++iz)
  {
    for (std::int64_t iy = low[1]; iy <= high[1]; ++iy)
    {
      const std::int64_t row = (iz * this->Dimensions[1] + iy) * this->Dimensions[0];
      candidates += this->CellStart[row + high[0] + 1] - this->CellStart[row + low[0]];
    }
  }
  return candidates;
}

void PointGrid::GatherWithinRadius(const double x[3], double radius, std::vector<double>& out) const
{
  out.clear();
  this->ForEachWithinRadius(
    x, radius, [&out](const double* q, std::int64_t) { out.insert(out.end(), q, q + 3); });
}

std::size_t PointGrid::GatherOffsetsWithinRadius(const double x[3],
  double radius,
  NeighborOffsets& out) const
{
  out.Count = 0;
  if (this->Ids.empty() || !(radius > 0.0))
  {
    return 0;
  }
  std::array<std::int64_t, 3> low, high;
  const std::size_t candidates = static_cast<std::size_t>(this->QueryCells(x, radius, low, high));
  if (out.Dx.size() < candidates + gather::Padding)
  {
    for (std::vector<double>* axis : { &out.Dx, &out.Dy, &out.Dz })
    {
      axis->resize(candidates + gather::Padding);
    }
  }
  const double radiusSquared = radius * radius;
  std::size_t kept = 0;
  for (std::int64_t iz = low[2]; iz <= high[2]; ++iz)
  {
    for (std::int64_t iy = low[1]; iy <= high[1]; ++iy)
    {
      // Cells of one row are contiguous in the sorted order.
      const std::int64_t row = (iz * this->Dimensions[1] + iy) * this->Dimensions[0];
      kept = gather::WithinRadius(this->Sorted[0].data(),
        this->Sorted[1].data(),
        this->Sorted[2].data(),
        this->CellStart[row + low[0]],
        this->CellStart[row + high[0] + 1],
        x,
        radiusSquared,
        out.Dx.data(),
        out.Dy.data(),
        out.Dz.data(),
        kept);
    }
  }
  out.Count = kept;
  return kept;
}

std::size_t PointGrid::GatherShell(const double x[3],
  double inner,
  double radius,
  ShellPoints& out) const
{
  out.Count = 0;
  const double innerSquared = inner * inner, radiusSquared = radius * radius;
  this->ForEachCandidateRun(x,
    radius,
    [&](const CandidateRun& run)
    {
      const std::size_t needed =
        out.Count + static_cast<std::size_t>(run.End - run.Begin) + gather::Padding;
      if (out.Dx.size() < needed)
      {
        const std::size_t size = std::max(needed, 2 * out.Dx.size());
        for (std::vector<double>* axis : { &out.Dx, &out.Dy, &out.Dz })
        {
          axis->resize(size);
        }
        out.Ids.resize(size);
      }
      const std::size_t kept = gather::ShellWithin({ run.X, run.Y, run.Z, run.Ids },
        run.Begin,
        run.End,
        { x, innerSquared, radiusSquared },
        { out.Dx.data(), out.Dy.data(), out.Dz.data(), out.Ids.data() },
        out.Count);
      out.Count = kept;
    });
  return out.Count;
}

namespace
{
/// The next radius of a search for `wanted` points that found `found`:
/// points on a surface, whose count grows with the area, radius^2.
double GrownSearchRadius(double radius, std::int64_t wanted, std::int64_t found)
{
  const double factor =
    1.1 * std::sqrt(static_cast<double>(wanted) / std::max<std::int64_t>(found, 1));
  return radius * std::min(4.0, std::max(1.25, factor));
}

/// The value of rank `rank` (from 0) among `values`, each counted into one
/// of the buckets (`bucket`; `starts`: where each bucket starts in the
/// values' order): only the values in its bucket need ordering.
double ValueOfRank(const std::vector<double>& values,
  const std::vector<std::uint32_t>& bucket,
  const std::vector<std::uint32_t>& starts,
  std::size_t rank,
  std::vector<double>& side)
{
  const std::uint32_t b = static_cast<std::uint32_t>(
    std::upper_bound(starts.begin(), starts.end(), rank) - starts.begin() - 1);
  side.resize(values.size());
  std::size_t kept = 0;
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    // Branch-free: which bucket a value falls into is not predictable.
    side[kept] = values[i];
    kept += bucket[i] == b;
  }
  const auto begin = side.begin();
  const std::size_t within = rank - starts[b];
  std::nth_element(begin, begin + within, begin + kept);
  return side[within];
}
} // namespace

std::array<double, 2> SquaredDistanceRanks(const std::vector<double>& squared,
  const std::array<std::size_t, 2>& ranks,
  double top,
  RankScratch& scratch)
{
  const std::size_t n = squared.size();
  std::vector<std::uint32_t>& bucket = scratch.Bucket;
  std::vector<std::uint32_t>& starts = scratch.Starts;
  bucket.resize(n);
  // A last bucket for what lies beyond top (or is not a number), and one
  // more entry: the counts, shifted by one, become where buckets start.
  starts.assign(n + 2, 0);
  const double scale = static_cast<double>(n) / top;
  for (std::size_t i = 0; i < n; ++i)
  {
    const double position = squared[i] * scale;
    bucket[i] = static_cast<std::uint32_t>(position < static_cast<double>(n) ? position : n);
    ++starts[bucket[i] + 1];
  }
  for (std::size_t b = 1; b < starts.size(); ++b)
  {
    starts[b] += starts[b - 1];
  }
  return { ValueOfRank(squared, bucket, starts, ranks[0] - 1, scratch.Side),
    ValueOfRank(squared, bucket, starts, ranks[1] - 1, scratch.Side) };
}

double PointGrid::SquaredDistanceToKth(const double x[3], int k, std::vector<double>& scratch) const
{
  const std::int64_t wanted = std::min<std::int64_t>(std::max(k, 1), this->GetNumberOfPoints());
  if (wanted == 0)
  {
    return 0.0;
  }
  auto squaredDistance = [x](const double* q)
  {
    const double dx = q[0] - x[0], dy = q[1] - x[1], dz = q[2] - x[2];
    return dx * dx + dy * dy + dz * dz;
  };
  // The k-th distance is the same whatever radius finds at least k points
  // and whichever order visits them: the search starts small in dense cells.
  double radius = this->StartRadius(x);
  for (;;)
  {
    scratch.clear();
    // Beyond the whole box, or where radius^2 overflows (and with it maybe
    // the distances, which no radius query would then find), every point
    // is taken: the loop ends.
    if (radius > 2.0 * this->Diagonal + this->Lattice.CellSize || !std::isfinite(radius * radius))
    {
      for (std::int64_t j = 0; j < this->GetNumberOfPoints(); ++j)
      {
        const double q[3] = { this->Sorted[0][j], this->Sorted[1][j], this->Sorted[2][j] };
        scratch.push_back(squaredDistance(q));
      }
      std::nth_element(scratch.begin(), scratch.begin() + (wanted - 1), scratch.end());
      return scratch[wanted - 1];
    }
    this->ForEachWithinRadiusFine(
      x, radius, [&](const double* q, std::int64_t) { scratch.push_back(squaredDistance(q)); });
    const std::int64_t found = static_cast<std::int64_t>(scratch.size());
    if (found >= wanted)
    {
      std::nth_element(scratch.begin(), scratch.begin() + (wanted - 1), scratch.end());
      return scratch[wanted - 1];
    }
    radius = GrownSearchRadius(radius, wanted, found);
  }
}

double PointGrid::GatherNearest(const double x[3], int k, ShellPoints& out) const
{
  out.Count = 0;
  const std::int64_t wanted = std::min<std::int64_t>(std::max(k, 1), this->GetNumberOfPoints());
  if (wanted == 0)
  {
    return 0.0;
  }
  // SquaredDistanceToKth's radii, so that both stop at the same one.
  for (double radius = this->StartRadius(x);
       !(radius > 2.0 * this->Diagonal + this->Lattice.CellSize) && std::isfinite(radius * radius);
       radius = GrownSearchRadius(radius, wanted, static_cast<std::int64_t>(out.Count)))
  {
    if (static_cast<std::int64_t>(this->GatherShell(x, 0.0, radius, out)) >= wanted)
    {
      return radius;
    }
  }
  out.Count = 0;
  return 0.0;
}

} // namespace pcurv
