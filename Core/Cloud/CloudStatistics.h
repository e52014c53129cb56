/**
 * @file CloudStatistics.h
 * @brief The cloud-level statistics every process must agree on (working
 * unit, the box without strays, typical radius, grid lattice, coordinate steps). No
 * VTK: they are reduced over the processes through Collectives.h.
 *
 * Distributed runs give the same numbers as a serial run because every
 * global choice (lattice, thresholds, sample for the automatic radius,
 * adjustment blocks) is made from globally reduced values, and each process
 * sees every point its own points' neighborhoods (and their adjustment
 * blocks) can reach.
 */
#ifndef CloudStatistics_h
#define CloudStatistics_h

#include "Cloud/CloudPoints.h"
#include "Cloud/Collectives.h"
#include "Common/RealBuffer.h"
#include "Neighbors/GridLattice.h"

#include <array>
#include <cstdint>
#include <vector>

namespace pcurv
{

class PointGrid;
class WorkRunner;

/// The step of the lattice the coordinates lie on, per axis: every
/// coordinate along the axis is a whole multiple of it from the cloud's
/// lowest (positions rounded to a grid, LAS's scaled integers, values stored
/// in single precision), within rounding. All zero unless all three axes
/// have one: a surface sampled on a regular grid of two axes has exact
/// positions, and only rounding puts the third on a lattice too. The same
/// on every process, whatever the order of the points or their split.
std::array<double, 3> CoordinateSteps(const CloudPoints& cloud,
  const PointGrid& grid,
  const Collectives& processes);

/// The power of two the estimation multiplies all lengths by before it
/// works, so that no coordinate, extent or squared distance can overflow or
/// underflow: 1 (no change at all) for clouds whose largest coordinate
/// magnitude lies within [2^-400, 2^400]; otherwise the factor that brings
/// it to [1, 2). Powers of two scale exactly, so results are unchanged up to
/// the unit.
double WorkingLengthScale(const CloudPoints& cloud, const Collectives& processes);

/// The box the statistics are taken in, from the global bounds.
struct CloudBoxes
{
  /// The bounds of the cloud without its strays: points farther from the
  /// range of its central 98 % (per axis) than eight times that range's
  /// largest extent. The spacing sample is drawn in it and the grid's
  /// lattice spans it, so a stray (a 1e110 "missing value" sentinel) changes
  /// neither the sample nor the cells, nor any other point's result; it
  /// shares the outermost cells. For most clouds it is the bounding box.
  std::array<double, 3> Lower, Upper;
  /// The points within the box, over all processes.
  std::int64_t BodyCount = 0;
};

/// The box of the own points of `cloud`, reduced over all processes.
CloudBoxes MeasureBoxes(const CloudPoints& cloud, const Collectives& processes);

/// True for the points of the sample that measures the cloud's spacing:
/// chosen by a hash of the coordinates quantized to 2^20 steps of the
/// box [lower, upper] (CloudBoxes), so that the sample is the same whatever the order of the
/// points, how they are split among processes, or the cloud's unit and
/// position (up to points within 1e-16 of a quantization step).
bool InSpacingSample(const double x[3],
  const double lower[3],
  const double upper[3],
  std::int64_t stride);

/// Median over the global sample of the distance to the k-th nearest other
/// point: a radius holding about k neighbors at a typical point. When
/// distributed, the sample's queries also see a halo of the other pieces
/// (on a copy: `cloud` is not changed). The grid it searches is built in
/// `runner` where given.
double TypicalRadius(const CloudPoints& cloud,
  const Collectives& processes,
  const CloudBoxes& boxes,
  int k,
  WorkRunner* runner = nullptr);

/// The lattice every process uses for a query radius: the grid box and the
/// global count, cells of half the radius (a query then visits at most
/// 5 x 5 x 5 cells, and reads fewer far candidates than with cells of the
/// radius).
GridLattice GlobalLattice(const CloudBoxes& boxes, double radius);

/// The largest distance from an own point to its k-th nearest neighbor
/// among this process's own points alone: at least the true distance, so a
/// halo this wide holds every point's k nearest neighbors.
double LargestLocalKthDistance(const CloudPoints& cloud, const GridLattice& lattice, int k);

/// The `quantile` (in (0, 1]) of |values| over the finite values of every
/// process: the upper edge of the histogram bin (2^(1/16) wide) that holds
/// it. The histogram adds up over processes, so the result does not depend
/// on how the cloud is split. 0 when no value is finite.
double MagnitudeQuantile(const RealBuffer& values,
  std::int64_t count,
  double quantile,
  const Collectives& processes);

} // namespace pcurv

#endif
