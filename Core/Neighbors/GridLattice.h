/**
 * @file GridLattice.h
 * @brief The cells of the neighbor grid, at global positions that every
 * process computes alike from global bounds. No VTK.
 */
#ifndef GridLattice_h
#define GridLattice_h

#include <array>
#include <cmath>
#include <cstdint>

namespace pcurv
{

/// Cubic cells of one size at global positions: the cell of coordinate c
/// along an axis is floor((c - Origin) / CellSize).
struct GridLattice
{
  std::array<double, 3> Origin{ { 0.0, 0.0, 0.0 } };
  double CellSize = 1.0;
  /// Index of the last cell along each axis: the lattice spans the box it
  /// was made for, and points beyond it belong to its outermost cells. A
  /// grid then stays as fine as its box needs even when a few points lie
  /// far outside it; queries stay exact, since clamping keeps the order of
  /// cells.
  std::array<double, 3> LastCell{ { 0.0, 0.0, 0.0 } };

  /// A lattice over the box [lower, upper] holding `count` points, with
  /// cells of about `cellSize`, enlarged when the box would need far more
  /// cells than points (a small radius in a large, sparse box).
  static GridLattice Make(const double lower[3],
    const double upper[3],
    std::int64_t count,
    double cellSize);

  /// (coordinate - origin) / cell size, computed in halves: the difference
  /// of two finite coordinates can overflow, half of it cannot.
  double CellCoordinate(double coordinate, int axis) const
  {
    return (0.5 * coordinate - 0.5 * this->Origin[axis]) / (0.5 * this->CellSize);
  }

  /// The cell along an axis, clamped to the lattice (NaN to cell 0).
  std::int64_t Cell(double coordinate, int axis) const
  {
    const double cell = std::floor(this->CellCoordinate(coordinate, axis));
    const double last = this->LastCell[axis];
    return static_cast<std::int64_t>(cell > 0.0 ? (cell < last ? cell : last) : 0.0);
  }
};

} // namespace pcurv

#endif
