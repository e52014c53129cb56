/**
 * @file ResultStore.h
 * @brief Where an estimation's per-point results go: the working length
 * unit and the way back to the input's, the store of each point's results
 * into the caller's buffers (it fills memory, it writes no file), and the
 * passes over all of them at the end (unit, clipped mean, counts, trust and shape classes).
 * No VTK.
 */
#ifndef ResultStore_h
#define ResultStore_h

#include "Estimation/CurvatureOutputs.h"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace pcurv
{

class Collectives;

/// The filter's working length unit (lengths multiplied by Scale, a power
/// of two) and the way back to the input's: the only place lengths and
/// curvatures change unit.
struct WorkingUnit
{
  double Scale = 1.0;

  /// A length the user gave, in the working unit (finite: a huge radius
  /// stays the largest double).
  double FromInput(double length) const
  {
    return std::min(length * this->Scale, std::numeric_limits<double>::max());
  }
  double ToInputLength(double length) const { return length / this->Scale; }
};

/// Stores one point's results in the caller's buffers (each point by
/// exactly one thread), in the working unit until ToInputUnit.
class ResultStore
{
public:
  /// `reasons`: one per input point, why it has no estimate.
  ResultStore(const CurvatureBuffers& out, std::uint8_t* reasons, int minimumPointsPerDirection)
    : Out(out)
    , Reasons(reasons)
    , MinimumPointsPerDirection(minimumPointsPerDirection)
  {
  }

  /// `target`: the adjustment's target count (0 where it has none).
  void Store(std::int64_t i,
    const PointCurvature& r,
    double s,
    double p,
    int target = 0,
    double standardError = std::numeric_limits<double>::quiet_NaN()) const;

  void StoreUnestimated(std::int64_t i, UnestimatedReason reason) const;

  /// Asks for the cache lines Store(i, ...) will write.
  void Prefetch(std::int64_t i) const;

  /// Point `to` gets every result of point `from` (an exact repeat of it);
  /// the outlier verdicts too unless `verdicts` is false (an outlier moved
  /// onto `from` has its own).
  void Copy(std::int64_t from, std::int64_t to, bool verdicts = true) const;
  /// Point i's results as RecordLength values (for another process, which
  /// has the same buffers), and back to point i; the outlier verdicts are
  /// not part of them.
  static constexpr std::size_t RecordLength = 27;
  void Pack(std::int64_t i, double* record) const;
  void Unpack(const double* record, std::int64_t i) const;

private:
  CurvatureBuffers Out;
  std::uint8_t* Reasons;
  int MinimumPointsPerDirection;
};

// The passes over every point's results once all are written.

/// Back from the working unit to the input's: curvatures scale like
/// 1 / length.
void ToInputUnit(const CurvatureBuffers& out, std::int64_t numberOfPoints, const WorkingUnit& unit);

/// The mean curvature clipped to [-clip, clip] (NaN stays NaN).
void WriteClippedMean(const CurvatureBuffers& out, std::int64_t numberOfPoints, double clip);

/// The points without an estimate, by reason (`reasons`: one per point,
/// UnestimatedReason).
UnestimatedCounts CountUnestimated(const CurvatureBuffers& out,
  const std::uint8_t* reasons,
  std::int64_t numberOfPoints);

/// CurvatureBuffers::Trusted and ShapeClass (each where not null) from the
/// reported standard errors, in the input's unit (ShapeClass.h); returns
/// the cloud's curvature scale trust used. Collective: every process calls
/// it when any has either buffer.
double WriteTrustAndShape(const CurvatureBuffers& out,
  std::int64_t numberOfPoints,
  const Collectives& processes);

} // namespace pcurv

#endif
