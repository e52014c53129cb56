/**
 * @file CloudPoints.h
 * @brief The cloud as the estimation sees it: own points with unit normals,
 * then the halo of other processes' points; the removal of exact repeats.
 * No VTK.
 */
#ifndef CloudPoints_h
#define CloudPoints_h

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
/// scans) then count once in every neighborhood, and cost once, instead of
/// every copy gathering every other. A cloud without repeats is left as it
/// is.
std::vector<RepeatedPoint> RemoveRepeatedPoints(CloudPoints& cloud);

/// Removes the own points i with remove[i] nonzero (no halo: before it is
/// exchanged; `remove` may be shorter than the own points), and returns
/// their input ids.
std::vector<std::int64_t> RemoveOwnPoints(CloudPoints& cloud,
  const std::vector<unsigned char>& remove);

/// Removes the halo points that repeat an own point or an earlier halo
/// point exactly, so that each distinct point counts once whatever the split
/// among processes.
void RemoveRepeatedHalo(CloudPoints& cloud);

/// n scaled to unit length, or zero when it has no direction (zero, NaN or
/// Inf components), without overflow or underflow for any finite length.
void MakeUnitNormal(double n[3]);

} // namespace pcurv

#endif
