/**
 * @file PrincipalCurvatureCloud.h
 * @brief The filter's view of its input (private to the module): the points
 * this process estimates, plus, when ParaView runs in parallel, a halo of
 * points from the other processes that lie within reach of them; and the
 * few collective operations that keep every process's choices global.
 *
 * Distributed runs give the same numbers as a serial run because every
 * global choice (lattice, thresholds, sample for the automatic radius,
 * adjustment blocks) is made from globally reduced values, and each process
 * sees every point its own points' neighbourhoods (and their adjustment
 * blocks) can reach.
 */
#ifndef PrincipalCurvatureCloud_h
#define PrincipalCurvatureCloud_h

#include "PointGrid.h"

#include "vtkType.h"

#include <array>
#include <cstdint>
#include <vector>

class vtkDataArray;
class vtkMultiProcessController;
class vtkPointSet;

namespace pcurv
{

/// Own points (finite coordinates) first, then halo points from other
/// processes. Coordinates in double; normals unit, or zero when unusable.
struct CloudPoints
{
  std::vector<double> Coordinates;        // 3 per point
  std::vector<double> Normals;            // 3 per point
  std::vector<vtkIdType> InputIds;        // input id of each own point
  std::vector<unsigned char> FiniteInput; // per input point: coordinates finite
  vtkIdType NumberOfOwnPoints = 0;

  vtkIdType GetNumberOfPoints() const
  {
    return static_cast<vtkIdType>(this->Coordinates.size() / 3);
  }
  bool IsOwn(vtkIdType point) const { return point < this->NumberOfOwnPoints; }

  /// Reads the input's points and normals (non-unit normals normalised;
  /// zero or non-finite ones become zero: such points are not estimated).
  void Read(vtkPointSet* input, vtkDataArray* normals);

  /// Bounding box of the own points (lower, upper); empty: lower > upper.
  void OwnBounds(double lower[3], double upper[3]) const;

  /// Multiplies every coordinate by `factor` (a power of two: exact).
  void ScaleCoordinates(double factor);
};

/// Collective operations over the processes of a parallel run; with no
/// controller or one process they reduce to the local values.
class ProcessGroup
{
public:
  ProcessGroup();
  bool IsDistributed() const { return this->Controller != nullptr; }
  int GetNumberOfProcesses() const;

  std::int64_t Sum(std::int64_t value) const;
  /// Element-wise global sums, in place.
  void Sum(std::vector<std::int64_t>& values) const;
  double Max(double value) const;
  int Min(int value) const;
  /// Global bounds from local ones (empty local boxes ignored).
  void Bounds(double lower[3], double upper[3]) const;
  /// All processes' values, concatenated in process order; `lengths`, when
  /// given, receives how many values each process gave.
  std::vector<double> Gather(const std::vector<double>& values,
    std::vector<vtkIdType>* lengths = nullptr) const;

  /// Replaces the halo of `cloud` by the points of other processes within
  /// `reach` of this process's own bounding box.
  void ExchangeHalo(CloudPoints& cloud, double reach) const;

private:
  vtkMultiProcessController* Controller = nullptr;
};

/// The power of two the filter multiplies all lengths by before it works,
/// so that no coordinate, extent or squared distance can overflow or
/// underflow: 1 (no change at all) for clouds whose largest coordinate
/// magnitude lies within [2^-400, 2^400]; otherwise the factor that brings
/// it to [1, 2). Powers of two scale exactly, so results are unchanged up to
/// the unit.
double WorkingLengthScale(const CloudPoints& cloud, const ProcessGroup& processes);

/// The box the spacing sample is drawn in, zoomed from the global bounding
/// box given in [lower, upper]: unchanged, unless a few far points would
/// squeeze the rest into a handful of quantisation steps; then, per axis,
/// the range of the central 98 % of the points, found by zooming in with
/// global histograms (integer counts: the same for any split among
/// processes).
void SamplingBox(const CloudPoints& cloud,
  const ProcessGroup& processes,
  double lower[3],
  double upper[3]);

/// The box the grid's lattice spans [lower, upper]: the sampling box
/// (returned in [sampleLower, sampleUpper]) widened by half its extent on
/// every side, within the cloud's bounds. For most clouds that is the
/// bounding box; a few far outliers end up in the outermost cells instead of
/// making every cell coarse (one point 1e7 away put a whole torus into one
/// cell).
void GridBox(const CloudPoints& cloud,
  const ProcessGroup& processes,
  double lower[3],
  double upper[3],
  double sampleLower[3],
  double sampleUpper[3]);

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
/// point: a radius holding about k neighbours at a typical point. Exchanges
/// a halo wide enough for the sample's queries first when distributed.
double TypicalRadius(CloudPoints& cloud, const ProcessGroup& processes, int k);

/// The lattice every process uses for a query radius: global bounds and
/// count, cells of half the radius (a query then visits at most 5 x 5 x 5
/// cells, and reads fewer far candidates than with cells of the radius).
GridLattice GlobalLattice(const CloudPoints& cloud, const ProcessGroup& processes, double radius);

} // namespace pcurv

#endif
