#include "ResultWriter.h"

#include <cmath>

namespace pcurv
{
namespace
{
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

/// Koenderink and van Doorn's shape index of an estimate (NaN where it has
/// none or both curvatures are 0: a plane has no shape); scale free.
double ShapeIndex(const PointCurvature& r)
{
  if (!r.Valid || (r.MinimumCurvature == 0.0 && r.MaximumCurvature == 0.0))
  {
    return NaN;
  }
  constexpr double TwoOverPi = 0.6366197723675814;
  return TwoOverPi *
    std::atan2(r.MaximumCurvature + r.MinimumCurvature, r.MaximumCurvature - r.MinimumCurvature);
}

} // namespace

void ResultWriter::Store(std::int64_t i,
  const PointCurvature& r,
  double s,
  double p,
  int target,
  double standardError) const
{
  if (this->Out.StandardError)
  {
    this->Out.StandardError.Set(i, r.Valid ? standardError : NaN);
  }
  if (this->Out.ShapeIndex)
  {
    this->Out.ShapeIndex.Set(i, ShapeIndex(r));
  }
  const double kMin = r.Valid ? r.MinimumCurvature : NaN;
  const double kMax = r.Valid ? r.MaximumCurvature : NaN;
  this->Out.Minimum.Set(i, kMin);
  this->Out.Maximum.Set(i, kMax);
  this->Out.Mean.Set(i, 0.5 * (kMin + kMax));
  this->Out.Gauss.Set(i, kMin * kMax);
  if (this->Out.Curvedness)
  {
    // In the working unit; like the curvatures it scales exactly by a power
    // of two on the way to the input's.
    this->Out.Curvedness.Set(i, std::sqrt(0.5 * (kMin * kMin + kMax * kMax)));
  }
  this->Out.MinimumDirection.SetRange(3 * i, r.MinimumDirection.data(), 3);
  this->Out.MaximumDirection.SetRange(3 * i, r.MaximumDirection.data(), 3);
  if (this->Out.FittedNormal)
  {
    this->Out.FittedNormal.SetRange(3 * i, r.FittedNormal.data(), 3);
  }
  this->Out.SineFitRms.Set(i, r.Valid ? r.SineFitRms : NaN);
  this->Out.Surroundings.Set(i, s);
  this->Out.PlaneDistance.Set(i, p);
  this->Out.Valid[i] = r.Valid ? 1 : 0;
  this->Out.NeighborCount[i] = r.NeighborCount;
  this->Out.ValidDirections[i] = r.ValidDirections;
  if (this->Out.TargetCount)
  {
    this->Out.TargetCount[i] = target;
  }
  this->Reasons[i] =
    static_cast<std::uint8_t>(UnestimatedReasonOf(r, this->MinimumPointsPerDirection));
}

void ResultWriter::StoreUnestimated(std::int64_t i, UnestimatedReason reason) const
{
  PointCurvature none;
  none.Reason = reason;
  this->Store(i, none, NaN, NaN);
}

void ResultWriter::Prefetch(std::int64_t i) const
{
  for (const RealBuffer* values : { &this->Out.Minimum,
         &this->Out.Maximum,
         &this->Out.Mean,
         &this->Out.Gauss,
         &this->Out.SineFitRms,
         &this->Out.Surroundings,
         &this->Out.PlaneDistance })
  {
    values->Prefetch(i);
  }
  this->Out.MinimumDirection.Prefetch(3 * i);
  this->Out.MaximumDirection.Prefetch(3 * i);
  __builtin_prefetch(this->Out.Valid + i, 1);
  __builtin_prefetch(this->Out.NeighborCount + i, 1);
  __builtin_prefetch(this->Out.ValidDirections + i, 1);
}

void ResultWriter::ToInputUnit(std::int64_t numberOfPoints, const WorkingUnit& unit) const
{
  const double lengthScale = unit.Scale;
  if (lengthScale == 1.0)
  {
    return;
  }
  const auto scaleBy = [numberOfPoints](const RealBuffer& values, double factor)
  {
    if (values)
    {
      for (std::int64_t i = 0; i < numberOfPoints; ++i)
      {
        values.Set(i, values.Get(i) * factor);
      }
    }
  };
  // Curvatures scale like 1 / length (a power of two: exact, also after
  // rounding to single precision).
  for (const RealBuffer* curvature : { &this->Out.Minimum,
         &this->Out.Maximum,
         &this->Out.Mean,
         &this->Out.SineFitRms,
         &this->Out.StandardError,
         &this->Out.Curvedness })
  {
    scaleBy(*curvature, lengthScale);
  }
  scaleBy(this->Out.Gauss, lengthScale * lengthScale);
  for (const RealBuffer* length : { &this->Out.Surroundings, &this->Out.PlaneDistance })
  {
    scaleBy(*length, unit.ToInputLength(1.0));
  }
}

void ResultWriter::Copy(std::int64_t from, std::int64_t to) const
{
  for (const RealBuffer* values : { &this->Out.Minimum,
         &this->Out.Maximum,
         &this->Out.Mean,
         &this->Out.Gauss,
         &this->Out.SineFitRms,
         &this->Out.Surroundings,
         &this->Out.PlaneDistance,
         &this->Out.StandardError,
         &this->Out.ShapeIndex,
         &this->Out.Curvedness })
  {
    if (*values)
    {
      values->CopyRange(from, to, 1);
    }
  }
  for (const RealBuffer* vectors : { &this->Out.MinimumDirection,
         &this->Out.MaximumDirection,
         &this->Out.FittedNormal,
         &this->Out.Normals })
  {
    if (*vectors)
    {
      vectors->CopyRange(3 * from, 3 * to, 3);
    }
  }
  this->Out.Valid[to] = this->Out.Valid[from];
  this->Reasons[to] = this->Reasons[from];
  this->Out.NeighborCount[to] = this->Out.NeighborCount[from];
  this->Out.ValidDirections[to] = this->Out.ValidDirections[from];
  if (this->Out.TargetCount)
  {
    this->Out.TargetCount[to] = this->Out.TargetCount[from];
  }
}

void ResultWriter::WriteClippedMean(std::int64_t numberOfPoints, double clip) const
{
  for (std::int64_t i = 0; i < numberOfPoints; ++i)
  {
    const double h = this->Out.Mean.Get(i);
    this->Out.ClippedMean.Set(i, std::isnan(h) ? h : std::min(std::max(h, -clip), clip));
  }
}

UnestimatedCounts ResultWriter::CountUnestimated(std::int64_t numberOfPoints) const
{
  UnestimatedCounts counts{};
  for (std::int64_t i = 0; i < numberOfPoints; ++i)
  {
    counts[this->Out.Valid[i] ? 0 : std::max<int>(this->Reasons[i], 1)] += 1;
  }
  counts[0] = 0;
  return counts;
}

} // namespace pcurv
