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

namespace
{
/// Normal equations of the least-squares fit of k = a + b cos 2t + c sin 2t
/// (symmetric: six entries), and their right-hand side.
struct SineEquations
{
  double n00 = 0.0, n01 = 0.0, n02 = 0.0, n11 = 0.0, n12 = 0.0, n22 = 0.0;
  double r0 = 0.0, r1 = 0.0, r2 = 0.0;
};

/// The normal equations of the valid directions' curvatures; counts them
/// in fit.ValidDirections and marks their positions on the circle of
/// 2 theta in `occupied`.
SineEquations SumSineEquations(const std::array<double, NumberOfDirections>& curvature,
  const std::array<bool, NumberOfDirections>& valid,
  const DirectionTable& table,
  std::array<bool, 8>& occupied,
  SineFit& fit)
{
  SineEquations e;
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
    e.n00 += 1.0;
    e.n01 += c;
    e.n02 += s;
    e.n11 += c * c;
    e.n12 += c * s;
    e.n22 += s * s;
    e.r0 += k;
    e.r1 += c * k;
    e.r2 += s * k;
  }
  return e;
}

/// Whether at least three positions of 2 theta are occupied and no closed
/// half-turn holds them all.
bool SpreadOverHalfTurn(const std::array<bool, 8>& occupied)
{
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
    return false;
  }
  largestGap = std::max(largestGap, firstOccupied + 8 - previous);
  if (largestGap >= 4) // all positions inside one closed half-turn of 2 theta
  {
    return false;
  }
  return true;
}

/// The sine's offset and amplitudes from its normal equations into `fit`.
void SolveSineEquations(const SineEquations& e, SineFit& fit)
{
  // L D L^T without pivoting: with three directions spread over more than
  // a half-turn the matrix is positive definite and well conditioned (its
  // pivots are at least about 1); written out, it costs a tenth of Eigen's
  // pivoting solver.
  const double l10 = e.n01 / e.n00, l20 = e.n02 / e.n00;
  const double d1 = e.n11 - l10 * e.n01;
  const double l21 = (e.n12 - l20 * e.n01) / d1;
  const double d2 = e.n22 - l20 * e.n02 - l21 * l21 * d1;
  const double y1 = e.r1 - l10 * e.r0;
  const double y2 = e.r2 - l20 * e.r0 - l21 * y1;
  fit.SineAmplitude = y2 / d2;
  fit.CosineAmplitude = y1 / d1 - l21 * fit.SineAmplitude;
  fit.Offset = e.r0 / e.n00 - l10 * fit.CosineAmplitude - l20 * fit.SineAmplitude;
}

/// The RMS of the valid directions' residuals from the fitted sine.
double SineRmsResidual(const std::array<double, NumberOfDirections>& curvature,
  const std::array<bool, NumberOfDirections>& valid,
  const DirectionTable& table,
  const SineFit& fit)
{
  // Residuals relative to the largest curvature, so that their squares
  // cannot overflow where the curvatures are huge (a degenerate
  // neighborhood can give 1e283).
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
  return unit * std::sqrt(squaredResidual / fit.ValidDirections);
}
} // namespace

SineFit FitSine(const std::array<double, NumberOfDirections>& curvature,
  const std::array<bool, NumberOfDirections>& valid)
{
  SineFit fit;
  // 2 theta_i = i pi / 4: directions i and i + 8 share one position on the
  // circle of 2 theta (they are the two halves of one plane).
  std::array<bool, 8> occupied{};
  const DirectionTable& table = Directions();
  const SineEquations equations = SumSineEquations(curvature, valid, table, occupied, fit);
  if (!SpreadOverHalfTurn(occupied))
  {
    return fit;
  }
  SolveSineEquations(equations, fit);
  fit.RmsResidual = SineRmsResidual(curvature, valid, table, fit);
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

} // namespace pcurv
