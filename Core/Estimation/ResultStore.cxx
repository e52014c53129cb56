#include "Estimation/ResultStore.h"
#include "Cloud/CloudStatistics.h"
#include "Estimation/ShapeClass.h"

#include <array>
#include <cmath>
#include <vector>

namespace pcurv
{
namespace
{
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
/// A nearly flat cloud's curvature scale, times its median radius.
constexpr double FlatCloudCurvatureShare = 0.25;

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

/// The real buffers of one value a point (each may be null).
constexpr RealBuffer CurvatureBuffers::*Scalars[] = { &CurvatureBuffers::Minimum,
  &CurvatureBuffers::Maximum,
  &CurvatureBuffers::Mean,
  &CurvatureBuffers::Gauss,
  &CurvatureBuffers::SineFitRms,
  &CurvatureBuffers::Surroundings,
  &CurvatureBuffers::PlaneDistance,
  &CurvatureBuffers::StandardError,
  &CurvatureBuffers::ShapeIndex,
  &CurvatureBuffers::Curvedness };

/// A record: the scalars, four vectors and five integers.
static_assert(sizeof(Scalars) / sizeof(Scalars[0]) + 4 * 3 + 5 == ResultStore::RecordLength);

} // namespace

void ResultStore::Store(std::int64_t i,
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

void ResultStore::StoreUnestimated(std::int64_t i, UnestimatedReason reason) const
{
  PointCurvature none;
  none.Reason = reason;
  this->Store(i, none, NaN, NaN);
}

void ResultStore::Prefetch(std::int64_t i) const
{
  for (const auto member : Scalars)
  {
    if (const RealBuffer& values = this->Out.*member)
    {
      values.Prefetch(i);
    }
  }
  this->Out.MinimumDirection.Prefetch(3 * i);
  this->Out.MaximumDirection.Prefetch(3 * i);
  __builtin_prefetch(this->Out.Valid + i, 1);
  __builtin_prefetch(this->Out.NeighborCount + i, 1);
  __builtin_prefetch(this->Out.ValidDirections + i, 1);
}

void ToInputUnit(const CurvatureBuffers& out, std::int64_t numberOfPoints, const WorkingUnit& unit)
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
  for (const RealBuffer* curvature :
    { &out.Minimum, &out.Maximum, &out.Mean, &out.SineFitRms, &out.StandardError, &out.Curvedness })
  {
    scaleBy(*curvature, lengthScale);
  }
  scaleBy(out.Gauss, lengthScale * lengthScale);
  for (const RealBuffer* length : { &out.Surroundings, &out.PlaneDistance, &out.SurfaceDistance })
  {
    scaleBy(*length, unit.ToInputLength(1.0));
  }
}

void ResultStore::Copy(std::int64_t from, std::int64_t to, bool verdicts) const
{
  for (const auto member : Scalars)
  {
    if (const RealBuffer& values = this->Out.*member)
    {
      values.CopyRange(from, to, 1);
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
  if (verdicts && this->Out.Outlier)
  {
    this->Out.Outlier[to] = this->Out.Outlier[from];
  }
  if (verdicts && this->Out.SurfaceDistance)
  {
    this->Out.SurfaceDistance.CopyRange(from, to, 1);
  }
  this->Reasons[to] = this->Reasons[from];
  this->Out.NeighborCount[to] = this->Out.NeighborCount[from];
  this->Out.ValidDirections[to] = this->Out.ValidDirections[from];
  if (this->Out.TargetCount)
  {
    this->Out.TargetCount[to] = this->Out.TargetCount[from];
  }
}

namespace
{
/// The buffers of three values a point, in the order of a record.
std::array<const RealBuffer*, 4> VectorsOf(const CurvatureBuffers& out)
{
  return { &out.MinimumDirection, &out.MaximumDirection, &out.FittedNormal, &out.Normals };
}
} // namespace

void ResultStore::Pack(std::int64_t i, double* record) const
{
  std::size_t at = 0;
  for (const auto member : Scalars)
  {
    const RealBuffer& values = this->Out.*member;
    record[at++] = values ? values.Get(i) : NaN;
  }
  for (const RealBuffer* vectors : VectorsOf(this->Out))
  {
    for (int c = 0; c < 3; ++c)
    {
      record[at++] = *vectors ? vectors->Get(3 * i + c) : NaN;
    }
  }
  record[at++] = this->Out.Valid[i];
  record[at++] = this->Reasons[i];
  record[at++] = this->Out.NeighborCount[i];
  record[at++] = this->Out.ValidDirections[i];
  record[at] = this->Out.TargetCount ? this->Out.TargetCount[i] : 0;
}

void ResultStore::Unpack(const double* record, std::int64_t i) const
{
  std::size_t at = 0;
  for (const auto member : Scalars)
  {
    const RealBuffer& values = this->Out.*member;
    values ? values.Set(i, record[at]) : void();
    ++at;
  }
  for (const RealBuffer* vectors : VectorsOf(this->Out))
  {
    for (int c = 0; c < 3; ++c, ++at)
    {
      *vectors ? vectors->Set(3 * i + c, record[at]) : void();
    }
  }
  this->Out.Valid[i] = static_cast<unsigned char>(record[at++]);
  this->Reasons[i] = static_cast<std::uint8_t>(record[at++]);
  this->Out.NeighborCount[i] = static_cast<int>(record[at++]);
  this->Out.ValidDirections[i] = static_cast<int>(record[at++]);
  if (this->Out.TargetCount)
  {
    this->Out.TargetCount[i] = static_cast<int>(record[at]);
  }
}

void WriteClippedMean(const CurvatureBuffers& out, std::int64_t numberOfPoints, double clip)
{
  for (std::int64_t i = 0; i < numberOfPoints; ++i)
  {
    const double h = out.Mean.Get(i);
    out.ClippedMean.Set(i, std::isnan(h) ? h : std::min(std::max(h, -clip), clip));
  }
}

UnestimatedCounts CountUnestimated(const CurvatureBuffers& out,
  const std::uint8_t* reasons,
  std::int64_t numberOfPoints)
{
  UnestimatedCounts counts{};
  for (std::int64_t i = 0; i < numberOfPoints; ++i)
  {
    counts[out.Valid[i] ? 0 : std::max<int>(reasons[i], 1)] += 1;
  }
  counts[0] = 0;
  return counts;
}

double WriteTrustAndShape(const CurvatureBuffers& out,
  std::int64_t numberOfPoints,
  const Collectives& processes)
{
  std::vector<double> largest(static_cast<std::size_t>(numberOfPoints), NaN);
  std::vector<double> radii(static_cast<std::size_t>(numberOfPoints), NaN);
  for (std::int64_t i = 0; i < numberOfPoints; ++i)
  {
    if (out.Valid[i])
    {
      largest[i] = std::max(std::fabs(out.Minimum.Get(i)), std::fabs(out.Maximum.Get(i)));
      radii[i] = out.Surroundings.Get(i);
    }
  }
  // The curvatures that matter in this cloud: its large ones, or, where it
  // is (nearly) flat, a bending its typical neighborhood resolves well (a
  // quarter of one over its radius: a larger share would let the errors of
  // gently curved parts, which take large radii, pass as trusted).
  const double typicalRadius = MagnitudeQuantile(radii.data(), numberOfPoints, 0.5, processes);
  const double scale = std::max(MagnitudeQuantile(largest.data(), numberOfPoints, 0.95, processes),
    typicalRadius > 0.0 ? FlatCloudCurvatureShare / typicalRadius : 0.0);
  for (std::int64_t i = 0; i < numberOfPoints; ++i)
  {
    const double error = out.StandardError ? out.StandardError.Get(i) : NaN;
    // An outlier's values are the nearest surface's, not its own.
    const bool outlier = out.Outlier && out.Outlier[i];
    const bool valid = out.Valid[i] != 0;
    const double kMin = valid ? out.Minimum.Get(i) : NaN;
    const double kMax = valid ? out.Maximum.Get(i) : NaN;
    if (out.Trusted)
    {
      out.Trusted[i] = IsTrusted(valid, outlier, kMin, kMax, error, scale) ? 1 : 0;
    }
    if (out.ShapeClass)
    {
      out.ShapeClass[i] = static_cast<unsigned char>(
        ClassifyShape(valid, outlier, kMin, kMax, error, valid ? radii[i] : NaN));
    }
  }
  return scale;
}

} // namespace pcurv
