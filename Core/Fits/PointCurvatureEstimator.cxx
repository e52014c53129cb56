#include "Fits/PrincipalCurvatureCore.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcurv
{

std::uint32_t PointCurvatureEstimator::DirectionMask(double tx, double ty, double p)
{
  // The filter's own classification, in the frame where the tangent
  // coordinates are the offsets themselves.
  const binning::Frame identity{ { 0.0, 0.0, 1.0 }, { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, 1.0, p };
  // A height off the tangent plane, which the plane tests ignore: the
  // neighbor is never taken for the query point itself, however small t
  // (its squared length may underflow to 0).
  const double height = 1.0;
  double h[1 + binning::Padding], d[1 + binning::Padding];
  double x[1 + binning::Padding], y[1 + binning::Padding];
  std::int64_t mask[1 + binning::Padding];
  // Sums the classification adds to and nobody reads: allocated once.
  static thread_local std::vector<double> banks(binning::BankDoubles, 0.0);
  binning::Block block;
  block.H = h;
  block.D = d;
  block.Tx = x;
  block.Ty = y;
  block.Mask = mask;
  block.Banks = banks.data();
  binning::Classify(identity, &tx, &ty, &height, 1, block);
  return static_cast<std::uint32_t>(mask[0]);
}

void PointCurvatureEstimator::Begin(const Vector3& point,
  const Vector3& unitNormal,
  double planeDistance,
  double scale)
{
  this->Point = point;
  this->Frame = MakeTangentFrame(unitNormal);
  // 0 (nothing is estimated) unless both the scale and its inverse are
  // finite: a subnormal scale would make the inverse infinite.
  const double inverse = 1.0 / scale;
  this->InverseScale =
    scale > 0.0 && std::isfinite(scale) && std::isfinite(inverse) ? inverse : 0.0;
  this->ScaledPlaneDistance = planeDistance * this->InverseScale;
  this->NumberOfSlots = 0;
  this->NumberOfAdded = 0;
  this->Banks.assign(binning::BankDoubles, 0.0);
}

void PointCurvatureEstimator::Reserve(std::size_t neighbors)
{
  if (neighbors <= this->Capacity)
  {
    return;
  }
  // The neighbors added so far keep their places; whole vectors are
  // stored past the last one.
  const std::size_t capacity = std::max(neighbors, 2 * this->Capacity);
  for (std::vector<double>* added :
    { &this->AddedH, &this->AddedD, &this->AddedTx, &this->AddedTy })
  {
    added->resize(capacity + binning::Padding);
  }
  this->AddedMask.resize(capacity + binning::Padding);
  this->Capacity = capacity;
}

void PointCurvatureEstimator::AddNeighbors(const double* coordinates, std::size_t count)
{
  double dx[binning::BlockSize], dy[binning::BlockSize], dz[binning::BlockSize];
  for (std::size_t start = 0; start < count; start += binning::BlockSize)
  {
    const std::size_t size = std::min(binning::BlockSize, count - start);
    const double* block = coordinates + 3 * start;
    for (std::size_t j = 0; j < size; ++j)
    {
      dx[j] = block[3 * j] - this->Point[0];
      dy[j] = block[3 * j + 1] - this->Point[1];
      dz[j] = block[3 * j + 2] - this->Point[2];
    }
    this->AddNeighborOffsets(dx, dy, dz, size);
  }
}

void PointCurvatureEstimator::AddNeighborOffsets(const double* dx,
  const double* dy,
  const double* dz,
  std::size_t count)
{
  this->Reserve(this->NumberOfSlots + count);
  const Vector3& n = this->Frame.Normal;
  const Vector3& v = this->Frame.V0;
  const Vector3& w = this->Frame.W0;
  const binning::Frame frame{ { n[0], n[1], n[2] },
    { v[0], v[1], v[2] },
    { w[0], w[1], w[2] },
    this->InverseScale,
    this->ScaledPlaneDistance };
  binning::Block& block = this->Binned;
  for (std::size_t start = 0; start < count; start += binning::BlockSize)
  {
    const std::size_t size = std::min(binning::BlockSize, count - start);
    const std::size_t first = this->NumberOfSlots;
    block.H = this->AddedH.data() + first;
    block.D = this->AddedD.data() + first;
    block.Tx = this->AddedTx.data() + first;
    block.Ty = this->AddedTy.data() + first;
    block.Mask = this->AddedMask.data() + first;
    block.Banks = this->Banks.data();
    block.FirstSlot = first;
    binning::Classify(frame, dx + start, dy + start, dz + start, size, block);
    this->NumberOfSlots = first + size;
    this->NumberOfAdded += size - block.AtQueryPoint;
  }
}

void PointCurvatureEstimator::SumBanks()
{
  double totals[NumberOfDirections * binning::RecordSize];
  binning::CombineBanks(this->Banks.data(), totals);
  for (int i = 0; i < NumberOfDirections; ++i)
  {
    const double* total = totals + i * binning::RecordSize;
    CgaSums& sums = this->Sums[i];
    sums.SumH2 = total[binning::SumH2];
    sums.SumH = total[binning::SumH];
    sums.SumHD = total[binning::SumHD];
    sums.SumD = total[binning::SumD];
    sums.SumD2 = total[binning::SumD2];
    sums.Count = static_cast<int>(total[binning::Count]);
    sums.Extent = total[binning::Extent];
  }
}

namespace
{
/// The circle of each direction with enough points and extent, by the
/// settings' mode, into `candidate12` (the equations 1 and 2) and
/// `candidate23` (the equations 2 and 3, or the previous fit); true where
/// some direction has both (New02 then keeps the closer).
bool FitCandidates(const std::array<CgaSums, NumberOfDirections>& directionSums,
  const FitSettings& settings,
  std::array<CircleFit, NumberOfDirections>& candidate12,
  std::array<CircleFit, NumberOfDirections>& candidate23)
{
  bool needQuality = false;
  for (int i = 0; i < NumberOfDirections; ++i)
  {
    const CgaSums& sums = directionSums[i];
    if (sums.Count < settings.MinimumPointsPerDirection ||
      sums.Extent < settings.MinimumDirectionExtent) // lengths are in units of the scale
    {
      continue;
    }
    switch (settings.Mode)
    {
      case FitMode::Previous:
        candidate23[i] = FitPrevious(sums);
        break;
      case FitMode::New01:
        candidate23[i] = FitEquations23(sums);
        break;
      case FitMode::New02:
        candidate12[i] = FitEquations12(sums);
        candidate23[i] = FitEquations23(sums);
        needQuality = needQuality || (candidate12[i].Valid && candidate23[i].Valid);
        break;
      case FitMode::OrientedCircles:
        // Fits no half planes (OrientedCircleFit.h has its own estimator):
        // every direction stays without a fit.
        break;
    }
  }
  return needQuality;
}
} // namespace

void PointCurvatureEstimator::FitDirections(const FitSettings& settings)
{
  std::array<CircleFit, NumberOfDirections> candidate12{};
  std::array<CircleFit, NumberOfDirections> candidate23{};
  const bool needQuality = FitCandidates(this->Sums, settings, candidate12, candidate23);

  if (needQuality)
  {
    this->KeepCloserCircles(candidate12, candidate23);
  }

  for (int i = 0; i < NumberOfDirections; ++i)
  {
    const CircleFit& chosen = candidate23[i].Valid ? candidate23[i] : candidate12[i];
    this->DirectionValid[i] = chosen.Valid;
    this->DirectionCurvature[i] = chosen.Valid ? chosen.Curvature * this->InverseScale : 0.0;
  }
}

void PointCurvatureEstimator::GatherDirections(std::uint32_t wanted,
  std::size_t stride,
  std::array<std::size_t, NumberOfDirections + 1>& count)
{
  // One more row: a dead end for the neighbors in no wanted direction.
  this->DirectionH.resize((NumberOfDirections + 1) * stride);
  this->DirectionD.resize((NumberOfDirections + 1) * stride);
  // Locals, not members: the stores could alias members.
  double* directionH = this->DirectionH.data();
  double* directionD = this->DirectionD.data();
  const std::int64_t* mask = this->AddedMask.data();
  const double* addedH = this->AddedH.data();
  const double* addedD = this->AddedD.data();
  auto put = [&](std::size_t k, int i, std::size_t keep)
  {
    const std::size_t at = i * stride + count[i];
    directionH[at] = addedH[k];
    directionD[at] = addedD[k];
    count[i] += keep;
  };
  for (std::size_t k = 0; k < this->NumberOfSlots; ++k)
  {
    // The first direction without a branch (most neighbors have one or
    // none: a loop over the bits mispredicted at nearly every one).
    const std::uint32_t bits = static_cast<std::uint32_t>(mask[k]) & wanted;
    put(k, __builtin_ctz(bits | 1u << NumberOfDirections), bits != 0);
    for (std::uint32_t rest = bits & (bits - 1); rest; rest &= rest - 1)
    {
      put(k, __builtin_ctz(rest), 1);
    }
  }
}

void PointCurvatureEstimator::KeepCloserCircles(
  const std::array<CircleFit, NumberOfDirections>& candidate12,
  std::array<CircleFit, NumberOfDirections>& candidate23)
{
  // Q = summed geometric distance of the direction's points to each
  // candidate circle; keep the candidate with the smaller Q.
  // Each direction's points side by side, then a square root and a
  // division per point and circle in vector instructions.
  std::uint32_t wanted = 0;
  for (int i = 0; i < NumberOfDirections; ++i)
  {
    wanted |= (candidate12[i].Valid && candidate23[i].Valid) ? 1u << i : 0u;
  }
  const std::size_t stride = this->Capacity + binning::Padding;
  std::array<std::size_t, NumberOfDirections + 1> count{};
  this->GatherDirections(wanted, stride, count);
  std::array<double, NumberOfDirections> quality12{};
  std::array<double, NumberOfDirections> quality23{};
  for (int i = 0; i < NumberOfDirections; ++i)
  {
    if (!(wanted >> i & 1u))
    {
      continue;
    }
    const double kappa[2] = { candidate12[i].Curvature, candidate23[i].Curvature };
    double sums[2];
    circles::DistanceSums(this->DirectionH.data() + i * stride,
      this->DirectionD.data() + i * stride,
      count[i],
      kappa,
      sums);
    quality12[i] = sums[0];
    quality23[i] = sums[1];
  }
  for (int i = 0; i < NumberOfDirections; ++i)
  {
    if (candidate12[i].Valid && candidate23[i].Valid && quality12[i] < quality23[i])
    {
      candidate23[i] = candidate12[i];
    }
  }
}

PointCurvature PointCurvatureEstimator::Estimate(const FitSettings& settings)
{
  PointCurvature result;
  result.NeighborCount = static_cast<int>(this->NumberOfAdded);
  this->DirectionValid.fill(false);
  this->DirectionCurvature.fill(0.0);
  if (this->NumberOfAdded == 0 || !(this->InverseScale > 0.0) || !(this->ScaledPlaneDistance > 0.0))
  {
    return result;
  }
  this->SumBanks();
  this->FitDirections(settings);
  const SineFit sine = FitSine(this->DirectionCurvature, this->DirectionValid);
  PrincipalCurvaturesFromSine(sine, this->Frame, result);
  return result;
}

UnestimatedReason UnestimatedReasonOf(const PointCurvature& r, int minimumPointsPerDirection)
{
  if (r.Valid)
  {
    return UnestimatedReason::None;
  }
  if (r.Reason != UnestimatedReason::None)
  {
    return r.Reason;
  }
  // Three directions of the fewest points each are the least a sine needs.
  if (r.NeighborCount < 3 * std::max(1, minimumPointsPerDirection))
  {
    return UnestimatedReason::TooFewNeighbors;
  }
  return r.ValidDirections < 3 ? UnestimatedReason::TooFewDirections : UnestimatedReason::FitFailed;
}

} // namespace pcurv
