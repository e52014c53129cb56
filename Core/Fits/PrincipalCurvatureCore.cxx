#include "Fits/PrincipalCurvatureCore.h"

#include <Eigen/Dense>

#include <algorithm>
#include <limits>

namespace pcurv
{
namespace
{
using binning::Directions;
using binning::DirectionTable;

Vector3 Cross(const Vector3& a, const Vector3& b)
{
  return { { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] } };
}

Vector3 Normalized(const Vector3& a)
{
  const double length = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  return { { a[0] / length, a[1] / length, a[2] / length } };
}

/// True when |numerator/denominator| would be meaningless because the
/// denominator vanished relative to the size of the terms it was made of.
bool VanishingDenominator(double denominator, double termMagnitude)
{
  return !(std::fabs(denominator) > 1e-13 * termMagnitude);
}

CircleFit MakeFit(double curvature)
{
  CircleFit fit;
  fit.Valid = std::isfinite(curvature);
  fit.Curvature = fit.Valid ? curvature : 0.0;
  return fit;
}

/// Entries of B named as in the paper: a..f.
struct CgaMatrix
{
  double a, b, c, d, e, f;
  explicit CgaMatrix(const CgaSums& s)
    : a(s.SumH2)
    , b(-s.SumH)
    , c(-0.5 * s.SumHD)
    , d(static_cast<double>(s.Count))
    , e(0.5 * s.SumD)
    , f(0.25 * s.SumD2)
  {
  }
};
} // namespace

TangentFrame MakeTangentFrame(const Vector3& unitNormal)
{
  int leastAligned = 0;
  for (int axis = 1; axis < 3; ++axis)
  {
    if (std::fabs(unitNormal[axis]) < std::fabs(unitNormal[leastAligned]))
    {
      leastAligned = axis;
    }
  }
  Vector3 axisVector{ { 0.0, 0.0, 0.0 } };
  axisVector[leastAligned] = 1.0;
  TangentFrame frame;
  frame.Normal = unitNormal;
  frame.V0 = Normalized(Cross(unitNormal, axisVector));
  frame.W0 = Cross(unitNormal, frame.V0);
  return frame;
}

namespace
{
/// True when the unit eigenvector x of the symmetric B belongs to its
/// smallest eigenvalue lambda = x' B x, well apart from the others: a shift
/// from a poor start can make inverse iteration converge to the middle
/// eigenvalue instead (found with three points nearly on a line). The other
/// two eigenvalues are the roots of mu^2 - (c1 - lambda) mu + c2 -
/// lambda (c1 - lambda) = 0, with c1 the trace and c2 the sum of the
/// principal 2x2 minors; the smaller root in the stable form.
bool IsSmallestEigenpair(const Eigen::Matrix3d& B, const Eigen::Vector3d& x)
{
  const double lambda = x.dot(B * x);
  const double c1 = B.trace();
  const double c2 = B(0, 0) * B(1, 1) - B(0, 1) * B(0, 1) + B(0, 0) * B(2, 2) - B(0, 2) * B(0, 2) +
    B(1, 1) * B(2, 2) - B(1, 2) * B(1, 2);
  const double sum = c1 - lambda;
  const double product = c2 - lambda * sum;
  const double discriminant = std::max(sum * sum - 4.0 * product, 0.0);
  const double smallerOther = 2.0 * product / (sum + std::sqrt(discriminant));
  return lambda < 0.5 * smallerOther;
}

/// The eigenvector of B's smallest eigenvalue by inverse iteration with a
/// shift: start from the solution of B's last two rows with s_n = 1 (what
/// the closed forms solve, close to the eigenvector when the points are
/// near a circle), shift by its Rayleigh quotient (within the square of the
/// start's error of lambda_min), and apply (B - shift I)^-1: each step
/// shrinks the other components by |lambda_min - shift| / |lambda - shift|,
/// so one or two suffice. False when the iterates do not settle (two close
/// small eigenvalues, a shifted matrix of rank 1 or less): the caller then
/// asks Eigen's iterative eigensolver, which is several times slower
/// (Benchmarks/BENCHMARK.md).
bool SmallestEigenvectorByInverseIteration(const Eigen::Matrix3d& B, Eigen::Vector3d& S)
{
  const double determinant = B(1, 1) * B(2, 2) - B(1, 2) * B(1, 2);
  Eigen::Vector3d x(1.0,
    (B(0, 2) * B(1, 2) - B(0, 1) * B(2, 2)) / determinant,
    (B(0, 1) * B(1, 2) - B(0, 2) * B(1, 1)) / determinant);
  if (!std::isfinite(x.squaredNorm()))
  {
    return false;
  }
  x.normalize();
  const double shift = x.dot(B * x);
  // (B - shift I)^-1 x points along adj(B - shift I) x (the determinant
  // only scales it): the adjugate's six distinct cofactors replace a
  // factorisation, at a third of the cost of Eigen's LDLT.
  const Eigen::Matrix3d M = B - shift * Eigen::Matrix3d::Identity();
  Eigen::Matrix3d adjugate;
  adjugate(0, 0) = M(1, 1) * M(2, 2) - M(1, 2) * M(1, 2);
  adjugate(0, 1) = M(0, 2) * M(1, 2) - M(0, 1) * M(2, 2);
  adjugate(0, 2) = M(0, 1) * M(1, 2) - M(0, 2) * M(1, 1);
  adjugate(1, 1) = M(0, 0) * M(2, 2) - M(0, 2) * M(0, 2);
  adjugate(1, 2) = M(0, 1) * M(0, 2) - M(0, 0) * M(1, 2);
  adjugate(2, 2) = M(0, 0) * M(1, 1) - M(0, 1) * M(0, 1);
  adjugate(1, 0) = adjugate(0, 1);
  adjugate(2, 0) = adjugate(0, 2);
  adjugate(2, 1) = adjugate(1, 2);
  for (int iteration = 0; iteration < 4; ++iteration)
  {
    Eigen::Vector3d next = adjugate * x;
    const double length = next.norm();
    if (!(length > 0.0) || !std::isfinite(length))
    {
      return false;
    }
    next /= length;
    if (next.dot(x) < 0.0)
    {
      next = -next; // the sign is free: keep the iterates comparable
    }
    const double change = (next - x).norm();
    x = next;
    if (change < 1e-13)
    {
      return IsSmallestEigenpair(B, x) ? (S = x, true) : false;
    }
  }
  return false;
}
} // namespace

namespace
{
/// B of the sums, as an Eigen matrix.
Eigen::Matrix3d CgaMatrixOf(const CgaSums& sums)
{
  const CgaMatrix m(sums);
  Eigen::Matrix3d B;
  B << m.a, m.b, m.c, m.b, m.d, m.e, m.c, m.e, m.f;
  return B;
}

/// The eigenvector of the smallest eigenvalue from Eigen's iterative
/// solver: computeDirect loses its accuracy when the eigenvalues spread
/// over many orders of magnitude, which is the normal case here
/// (a ~ sum h^2 is tiny next to d = N).
bool SmallestEigenvectorByEigenSolver(const Eigen::Matrix3d& B, Eigen::Vector3d& S)
{
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.compute(B);
  if (solver.info() != Eigen::Success)
  {
    return false;
  }
  S = solver.eigenvectors().col(0);
  return true;
}

/// kappa = sign(s_n) s_0 / sqrt(s_n^2 - 2 s_inf s_0) of the sphere S.
CircleFit CircleOfSphere(const Eigen::Vector3d& S)
{
  const double sN = S[0];
  const double sInf = S[1];
  const double s0 = S[2];
  const double radicand = sN * sN - 2.0 * sInf * s0;
  if (!(radicand > 0.0))
  {
    return CircleFit{}; // imaginary or degenerate sphere
  }
  return MakeFit(std::copysign(1.0, sN) * s0 / std::sqrt(radicand));
}
} // namespace

CircleFit FitPrevious(const CgaSums& sums)
{
  const Eigen::Matrix3d B = CgaMatrixOf(sums);
  Eigen::Vector3d S;
  if (!SmallestEigenvectorByInverseIteration(B, S) && !SmallestEigenvectorByEigenSolver(B, S))
  {
    return CircleFit{};
  }
  return CircleOfSphere(S);
}

CircleFit FitPreviousWithEigenSolver(const CgaSums& sums)
{
  Eigen::Vector3d S;
  return SmallestEigenvectorByEigenSolver(CgaMatrixOf(sums), S) ? CircleOfSphere(S) : CircleFit{};
}

CircleFit FitEquations12(const CgaSums& sums)
{
  const CgaMatrix m(sums);
  const double denominator = m.b * m.e - m.c * m.d;
  if (VanishingDenominator(denominator, std::fabs(m.b * m.e) + std::fabs(m.c * m.d)))
  {
    return CircleFit{};
  }
  return MakeFit((m.a * m.d - m.b * m.b) / denominator);
}

CircleFit FitEquations23(const CgaSums& sums)
{
  const CgaMatrix m(sums);
  const double denominator = m.e * m.e - m.f * m.d;
  if (VanishingDenominator(denominator, m.e * m.e + std::fabs(m.f * m.d)))
  {
    return CircleFit{};
  }
  return MakeFit((m.c * m.d - m.b * m.e) / denominator);
}

SineFit FitSine(const std::array<double, NumberOfDirections>& curvature,
  const std::array<bool, NumberOfDirections>& valid)
{
  SineFit fit;
  // 2 theta_i = i pi / 4: directions i and i + 8 share one position on the
  // circle of 2 theta (they are the two halves of one plane).
  std::array<bool, 8> occupied{};
  // Normal equations of the least-squares fit of k = a + b cos 2t + c sin 2t
  // (symmetric: six entries), and their right-hand side.
  double n00 = 0.0, n01 = 0.0, n02 = 0.0, n11 = 0.0, n12 = 0.0, n22 = 0.0;
  double r0 = 0.0, r1 = 0.0, r2 = 0.0;
  const DirectionTable& table = Directions();
  for (int i = 0; i < NumberOfDirections; ++i)
  {
    if (!valid[i])
    {
      continue;
    }
    ++fit.ValidDirections;
    occupied[i % 8] = true;
    const int doubled = (2 * i) % NumberOfDirections;
    const double c = table.Cos[doubled], s = table.Sin[doubled], k = curvature[i];
    n00 += 1.0;
    n01 += c;
    n02 += s;
    n11 += c * c;
    n12 += c * s;
    n22 += s * s;
    r0 += k;
    r1 += c * k;
    r2 += s * k;
  }

  int distinct = 0;
  int largestGap = 0;
  int firstOccupied = -1;
  int previous = -1;
  for (int position = 0; position < 8; ++position)
  {
    if (!occupied[position])
    {
      continue;
    }
    ++distinct;
    if (previous >= 0)
    {
      largestGap = std::max(largestGap, position - previous);
    }
    else
    {
      firstOccupied = position;
    }
    previous = position;
  }
  if (distinct < 3)
  {
    return fit;
  }
  largestGap = std::max(largestGap, firstOccupied + 8 - previous);
  if (largestGap >= 4) // all positions inside one closed half-turn of 2 theta
  {
    return fit;
  }

  // L D L^T without pivoting: with three directions spread over more than
  // a half-turn the matrix is positive definite and well conditioned (its
  // pivots are at least about 1); written out, it costs a tenth of Eigen's
  // pivoting solver.
  const double l10 = n01 / n00, l20 = n02 / n00;
  const double d1 = n11 - l10 * n01;
  const double l21 = (n12 - l20 * n01) / d1;
  const double d2 = n22 - l20 * n02 - l21 * l21 * d1;
  const double y1 = r1 - l10 * r0;
  const double y2 = r2 - l20 * r0 - l21 * y1;
  fit.SineAmplitude = y2 / d2;
  fit.CosineAmplitude = y1 / d1 - l21 * fit.SineAmplitude;
  fit.Offset = r0 / n00 - l10 * fit.CosineAmplitude - l20 * fit.SineAmplitude;
  // Residuals relative to the largest curvature, so that their squares
  // cannot overflow where the curvatures are huge (a degenerate
  // neighbourhood can give 1e283).
  double largest = 0.0;
  for (int i = 0; i < NumberOfDirections; ++i)
  {
    largest = valid[i] ? std::max(largest, std::fabs(curvature[i])) : largest;
  }
  const double unit = largest > 0.0 ? largest : 1.0;
  double squaredResidual = 0.0;
  for (int i = 0; i < NumberOfDirections; ++i)
  {
    if (valid[i])
    {
      const int doubled = (2 * i) % NumberOfDirections;
      const double model = fit.Offset + fit.CosineAmplitude * table.Cos[doubled] +
        fit.SineAmplitude * table.Sin[doubled];
      const double residual = curvature[i] / unit - model / unit;
      squaredResidual += residual * residual;
    }
  }
  fit.RmsResidual = unit * std::sqrt(squaredResidual / fit.ValidDirections);
  fit.Valid = std::isfinite(fit.Offset) && std::isfinite(fit.CosineAmplitude) &&
    std::isfinite(fit.SineAmplitude) && std::isfinite(fit.RmsResidual);
  return fit;
}

void PrincipalCurvaturesFromSine(const SineFit& fit, const TangentFrame& frame, PointCurvature& out)
{
  out.ValidDirections = fit.ValidDirections;
  out.SineFitRms = fit.RmsResidual;
  out.Valid = fit.Valid;
  if (!fit.Valid)
  {
    return;
  }
  const double amplitude = std::hypot(fit.CosineAmplitude, fit.SineAmplitude);
  // Paper sign: extremes offset -/+ amplitude; output sign flips them.
  out.MaximumCurvature = -(fit.Offset - amplitude);
  out.MinimumCurvature = -(fit.Offset + amplitude);
  if (!std::isfinite(out.MaximumCurvature) || !std::isfinite(out.MinimumCurvature))
  {
    out.Valid = false; // beyond the double range: no estimate
    out.MaximumCurvature = out.MinimumCurvature = 0.0;
    return;
  }
  // The paper-sign maximum (output minimum) lies at 2 theta = atan2(As, Ac),
  // theta in (-pi/2, pi/2]. Its cosine and sine from the half-angle
  // formulas, each from the better conditioned side (atan2, cos and sin
  // cost three times as much).
  double c = 1.0, s = 0.0; // no amplitude: atan2(0, 0) = 0
  if (amplitude > 0.0)
  {
    // Subnormal amplitudes have too few bits for accurate ratios (found by
    // fuzzing: |d_min| = 1 - 7e-7): scaled up first, exactly.
    const bool tiny = amplitude < 0x1p-900;
    const double ac = tiny ? fit.CosineAmplitude * 0x1p600 : fit.CosineAmplitude;
    const double as = tiny ? fit.SineAmplitude * 0x1p600 : fit.SineAmplitude;
    const double norm = tiny ? std::hypot(ac, as) : amplitude;
    const double cosine2 = ac / norm;
    const double sine2 = as / norm;
    if (cosine2 >= 0.0)
    {
      c = std::sqrt(0.5 * (1.0 + cosine2));
      s = sine2 / (2.0 * c);
    }
    else
    {
      s = std::copysign(std::sqrt(0.5 * (1.0 - cosine2)), fit.SineAmplitude);
      c = sine2 / (2.0 * s);
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    out.MinimumDirection[k] = c * frame.V0[k] + s * frame.W0[k];
  }
  out.MaximumDirection = Cross(frame.Normal, out.MinimumDirection);
}

std::uint32_t PointCurvatureEstimator::DirectionMask(double tx, double ty, double p)
{
  // The filter's own classification, in the frame where the tangent
  // coordinates are the offsets themselves.
  const binning::Frame identity{ { 0.0, 0.0, 1.0 }, { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, 1.0, p };
  // A height off the tangent plane, which the plane tests ignore: the
  // neighbour is never taken for the query point itself, however small t
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
  // The neighbours added so far keep their places; whole vectors are
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

void PointCurvatureEstimator::FitDirections(const FitSettings& settings)
{
  std::array<CircleFit, NumberOfDirections> candidate12{};
  std::array<CircleFit, NumberOfDirections> candidate23{};
  bool needQuality = false;
  for (int i = 0; i < NumberOfDirections; ++i)
  {
    const CgaSums& sums = this->Sums[i];
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

  if (needQuality)
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
    // One more row: a dead end for the neighbours in no wanted direction.
    this->DirectionH.resize((NumberOfDirections + 1) * stride);
    this->DirectionD.resize((NumberOfDirections + 1) * stride);
    // Locals, not members: the stores could alias members.
    std::array<std::size_t, NumberOfDirections + 1> count{};
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
      // The first direction without a branch (most neighbours have one or
      // none: a loop over the bits mispredicted at nearly every one).
      const std::uint32_t bits = static_cast<std::uint32_t>(mask[k]) & wanted;
      put(k, __builtin_ctz(bits | 1u << NumberOfDirections), bits != 0);
      for (std::uint32_t rest = bits & (bits - 1); rest; rest &= rest - 1)
      {
        put(k, __builtin_ctz(rest), 1);
      }
    }
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

  for (int i = 0; i < NumberOfDirections; ++i)
  {
    const CircleFit& chosen = candidate23[i].Valid ? candidate23[i] : candidate12[i];
    this->DirectionValid[i] = chosen.Valid;
    this->DirectionCurvature[i] = chosen.Valid ? chosen.Curvature * this->InverseScale : 0.0;
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
