/**
 * @file CloudStatistics.h
 * @brief The cloud as the estimation sees it, and the cloud-level statistics
 * every process must agree on (working unit, sampling box, typical radius,
 * grid lattice). No VTK: collective operations of a parallel run are reached
 * through the Collectives interface, which the VTK glue implements with
 * vtkMultiProcessController and which, as given here, is a single process.
 *
 * Distributed runs give the same numbers as a serial run because every
 * global choice (lattice, thresholds, sample for the automatic radius,
 * adjustment blocks) is made from globally reduced values, and each process
 * sees every point its own points' neighbourhoods (and their adjustment
 * blocks) can reach.
 */
#ifndef CloudStatistics_h
#define CloudStatistics_h

#include "Neighbors/PointGrid.h"
#include "Common/RealBuffer.h"

#include <array>
#include <cstdint>
#include <vector>

namespace pcurv
{

/// Own points (finite coordinates) first, then halo points from other
/// processes. Coordinates in double; normals unit, or zero when unusable.
struct CloudPoints
{
  std::vector<double> Coordinates; // 3 per point
  std::vector<double> Normals;     // 3 per point
  /// The input id of each own point; empty while they are 0, 1, 2, ...
  /// (every input point finite and kept: the usual cloud), which saves a
  /// large array. Read through InputId.
  std::vector<std::int64_t> InputIds;
  /// Per input point: coordinates finite (may be released once read:
  /// ReleaseFiniteInput).
  std::vector<unsigned char> FiniteInput;
  std::int64_t NumberOfOwnPoints = 0;
  std::int64_t NumberOfInputPoints = 0;

  std::int64_t GetNumberOfPoints() const
  {
    return static_cast<std::int64_t>(this->Coordinates.size() / 3);
  }
  bool IsOwn(std::int64_t point) const { return point < this->NumberOfOwnPoints; }
  /// The input id of own point `point`.
  std::int64_t InputId(std::int64_t point) const
  {
    return this->InputIds.empty() ? point : this->InputIds[point];
  }
  void ReleaseFiniteInput() { std::vector<unsigned char>().swap(this->FiniteInput); }
  /// Makes InputIds list every own point's id (before they stop being
  /// 0, 1, 2, ...).
  void ListInputIds();
  std::int64_t GetNumberOfInputPoints() const { return this->NumberOfInputPoints; }

  /// Starts a cloud of `numberOfInputPoints` input points, none added yet.
  void Reset(std::int64_t numberOfInputPoints);
  /// Adds input point `id` (in increasing order): kept as an own point when
  /// its coordinates are finite, with its normal made unit (zero when it has
  /// no direction: such points are not estimated).
  void AddInputPoint(std::int64_t id, const double x[3], const double normal[3]);

  /// Bounding box of the own points (lower, upper); empty: lower > upper.
  void OwnBounds(double lower[3], double upper[3]) const;

  /// Multiplies every coordinate by `factor` (a power of two: exact).
  void ScaleCoordinates(double factor);

  /// Drops the halo: only the own points remain.
  void DropHalo();
};

/// An own point that repeats an earlier one exactly (coordinates and
/// normal), by input id.
struct RepeatedPoint
{
  std::int64_t Copy = 0;
  std::int64_t Original = 0;
};

/// Removes the own points that repeat an earlier own point exactly, and
/// returns them: copies of one point (a lidar's no-return points, merged
/// scans) then count once in every neighbourhood, and cost once, instead of
/// every copy gathering every other. A cloud without repeats is left as it
/// is.
std::vector<RepeatedPoint> RemoveRepeatedPoints(CloudPoints& cloud);

/// Removes the halo points that repeat an own point or an earlier halo
/// point exactly, so that each distinct point counts once whatever the split
/// among processes.
void RemoveRepeatedHalo(CloudPoints& cloud);

/// n scaled to unit length, or zero when it has no direction (zero, NaN or
/// Inf components), without overflow or underflow for any finite length.
void MakeUnitNormal(double n[3]);

/**
 * Collective operations over the processes of a parallel run. This base
 * class is a single process: every reduction returns the local value. The
 * VTK glue overrides it for ParaView's MPI runs.
 */
class Collectives
{
public:
  virtual ~Collectives() = default;
  virtual bool IsDistributed() const { return false; }
  virtual int GetNumberOfProcesses() const { return 1; }
  virtual int GetLocalProcessId() const { return 0; }

  virtual std::int64_t Sum(std::int64_t value) const { return value; }
  /// Element-wise global sums, in place.
  virtual void Sum(std::vector<std::int64_t>&) const {}
  virtual double Max(double value) const { return value; }
  virtual int Min(int value) const { return value; }
  /// Global bounds from local ones (empty local boxes ignored), in place.
  virtual void Bounds(double[3], double[3]) const {}
  /// All processes' values, concatenated in process order; `lengths`, when
  /// given, receives how many values each process gave.
  virtual std::vector<double> Gather(const std::vector<double>& values,
    std::vector<std::int64_t>* lengths = nullptr) const;
};

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

/// Replaces the halo of `cloud` by the points of other processes within
/// `reach` of this process's own bounding box (drops it when not
/// distributed).
void ExchangeHalo(CloudPoints& cloud, const Collectives& processes, double reach);

/// The power of two the estimation multiplies all lengths by before it
/// works, so that no coordinate, extent or squared distance can overflow or
/// underflow: 1 (no change at all) for clouds whose largest coordinate
/// magnitude lies within [2^-400, 2^400]; otherwise the factor that brings
/// it to [1, 2). Powers of two scale exactly, so results are unchanged up to
/// the unit.
double WorkingLengthScale(const CloudPoints& cloud, const Collectives& processes);

/// The boxes the statistics are taken in, from the global bounds.
struct CloudBoxes
{
  /// The box the grid's lattice spans: the sampling box widened by half its
  /// extent on every side, within the cloud's bounds. For most clouds that
  /// is the bounding box; a few far outliers end up in the outermost cells
  /// instead of making every cell coarse.
  std::array<double, 3> GridLower, GridUpper;
  /// The box the spacing sample is drawn in: the bounding box, unless a few
  /// far points would squeeze the rest into a handful of quantisation steps;
  /// then, per axis, the range of the central 98 % of the points, found by
  /// zooming in with global histograms (integer counts: the same for any
  /// split among processes).
  std::array<double, 3> SampleLower, SampleUpper;
  std::int64_t GlobalCount = 0;
};

/// The boxes of the own points of `cloud`, reduced over all processes.
CloudBoxes MeasureBoxes(const CloudPoints& cloud, const Collectives& processes);

/// True for the points of the sample that measures the cloud's spacing:
/// chosen by a hash of the coordinates quantised to 2^20 steps of the
/// sampling box, so that the sample is the same whatever the order of the
/// points, how they are split among processes, or the cloud's unit and
/// position (up to points within 1e-16 of a quantisation step).
bool InSpacingSample(const double x[3],
  const double lower[3],
  const double upper[3],
  std::int64_t stride);

/// Median over the global sample of the distance to the k-th nearest other
/// point: a radius holding about k neighbours at a typical point. When
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

/// The largest distance from an own point to its k-th nearest neighbour
/// among this process's own points alone: at least the true distance, so a
/// halo this wide holds every point's k nearest neighbours.
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
