/**
 * @file LineCloud.h
 * @brief The points a process computes curvature lines on: its own and, in
 * a distributed run, the halo its own points' fits and graph edges reach,
 * in an order that does not depend on how the cloud is split; the
 * collective steps around them. No VTK.
 *
 * The lines of a split cloud are those of the whole cloud when every
 * process sees what a serial run sees around each of its own points: the
 * same neighbors (the halo), visited in the same order (one lattice for
 * every process, points ordered by their data), each graph edge crossed by
 * one process only (the one owning the point that crosses it in a serial
 * run), and the crossings traced together in one order.
 */
#ifndef LineCloud_h
#define LineCloud_h

#include "Lines/LineCrossings.h"
#include "Neighbors/GridLattice.h"

#include <cstdint>
#include <vector>

namespace pcurv
{
class Collectives;
class WorkRunner;

/// A process's points, as LineInput's arrays, sorted by coordinates and
/// then by the rest of their data: two processes holding a point list it
/// in the same order relative to the points both hold.
struct LineCloud
{
  std::int64_t Count = 0;
  std::vector<double> Points, Normals, MaximumDirection; ///< 3 per point
  std::vector<double> MaximumCurvature, MinimumCurvature, StandardError, Radius;
  std::vector<unsigned char> Valid;
  std::vector<unsigned char> Owned; ///< 1: this process's point; 0: halo
  bool HasRadius = false;
  bool Distributed = false;
  /// The neighbor grid's lattice, the same on every process.
  GridLattice Lattice;
  /// The number of points over all processes.
  std::int64_t GlobalCount = 0;
  /// The median of the given radii (a sample), 0 without radii.
  double SampledRadius = 0.0;

  /// The arrays as the core's input (Owned given when distributed).
  LineInput AsInput() const;
};

/// The own points of `own` and the halo of other processes' points their
/// fits and graph edges reach. Collective.
LineCloud GatherLineCloud(const LineInput& own,
  const LineSettings& settings,
  const Collectives& processes);

/// What the fits need to know of the whole cloud, the same on every
/// process.
struct GraphScale
{
  /// The typical neighborhood radius (LineInput::TypicalRadius).
  double TypicalRadius = 0.0;
  /// The grid's lattice: cells about the distance to a point's graph
  /// neighbors, so that the nearest-neighbor query of every point visits a
  /// few dozen points, not a neighborhood's thousands.
  GridLattice Lattice;
};

/// Measured on about a thousand of the points, chosen by their
/// coordinates (the same whatever the split). Collective.
GraphScale MeasureGraphScale(const LineCloud& cloud,
  const LineSettings& settings,
  const Collectives& processes,
  WorkRunner* runner);

/// The value at position size / 2 of every process's `values` sorted
/// together (each nonnegative and finite), 0 when there are none: a serial
/// median, whatever the split. Collective.
double GlobalMedian(std::vector<double> values, const Collectives& processes);

/// Every process's crossings, in one order given by their data alone.
/// Collective.
std::vector<LineCrossing> GatherCrossings(const std::vector<LineCrossing>& own,
  const Collectives& processes);

} // namespace pcurv

#endif
