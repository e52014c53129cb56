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
    this->Out.StandardError[i] = r.Valid ? standardError : NaN;
  }
  if (this->Out.ShapeIndex)
  {
    this->Out.ShapeIndex[i] = ShapeIndex(r);
  }
  const double kMin = r.Valid ? r.MinimumCurvature : NaN;
  const double kMax = r.Valid ? r.MaximumCurvature : NaN;
  this->Out.Minimum[i] = kMin;
  this->Out.Maximum[i] = kMax;
  this->Out.Mean[i] = 0.5 * (kMin + kMax);
  this->Out.Gauss[i] = kMin * kMax;
  std::copy_n(r.MinimumDirection.data(), 3, this->Out.MinimumDirection + 3 * i);
  std::copy_n(r.MaximumDirection.data(), 3, this->Out.MaximumDirection + 3 * i);
  if (this->Out.FittedNormal)
  {
    std::copy_n(r.FittedNormal.data(), 3, this->Out.FittedNormal + 3 * i);
  }
  this->Out.SineFitRms[i] = r.Valid ? r.SineFitRms : NaN;
  this->Out.Surroundings[i] = s;
  this->Out.PlaneDistance[i] = p;
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
  for (const double* values : { this->Out.Minimum,
         this->Out.Maximum,
         this->Out.Mean,
         this->Out.Gauss,
         this->Out.SineFitRms,
         this->Out.Surroundings,
         this->Out.PlaneDistance })
  {
    __builtin_prefetch(values + i, 1);
  }
  __builtin_prefetch(this->Out.MinimumDirection + 3 * i, 1);
  __builtin_prefetch(this->Out.MaximumDirection + 3 * i, 1);
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
  for (std::int64_t i = 0; i < numberOfPoints; ++i)
  {
    for (double* curvature :
      { this->Out.Minimum, this->Out.Maximum, this->Out.Mean, this->Out.SineFitRms })
    {
      curvature[i] = curvature[i] * lengthScale;
    }
    if (this->Out.StandardError)
    {
      this->Out.StandardError[i] = this->Out.StandardError[i] * lengthScale;
    }
    this->Out.Gauss[i] = this->Out.Gauss[i] * lengthScale * lengthScale;
    for (double* length : { this->Out.Surroundings, this->Out.PlaneDistance })
    {
      length[i] = unit.ToInputLength(length[i]);
    }
  }
}

void ResultWriter::Copy(std::int64_t from, std::int64_t to) const
{
  for (double* values : { this->Out.Minimum,
         this->Out.Maximum,
         this->Out.Mean,
         this->Out.Gauss,
         this->Out.SineFitRms,
         this->Out.Surroundings,
         this->Out.PlaneDistance,
         this->Out.StandardError,
         this->Out.ShapeIndex })
  {
    if (values)
    {
      values[to] = values[from];
    }
  }
  for (double* vectors : { this->Out.MinimumDirection,
         this->Out.MaximumDirection,
         this->Out.FittedNormal,
         this->Out.Normals })
  {
    if (vectors)
    {
      std::copy_n(vectors + 3 * from, 3, vectors + 3 * to);
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

void ResultWriter::WriteCurvedness(std::int64_t numberOfPoints) const
{
  if (!this->Out.Curvedness)
  {
    return;
  }
  for (std::int64_t i = 0; i < numberOfPoints; ++i)
  {
    const double a = this->Out.Minimum[i], b = this->Out.Maximum[i];
    this->Out.Curvedness[i] = std::sqrt(0.5 * (a * a + b * b));
  }
}

void ResultWriter::WriteClippedMean(std::int64_t numberOfPoints, double clip) const
{
  for (std::int64_t i = 0; i < numberOfPoints; ++i)
  {
    const double h = this->Out.Mean[i];
    this->Out.ClippedMean[i] = std::isnan(h) ? h : std::min(std::max(h, -clip), clip);
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
