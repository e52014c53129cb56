#include "Fits/NormalFieldFit.h"
#include "Fits/OrientedCircleFit.h"
#include "Fits/PrincipalCurvatureCore.h"

#include "Common/SmallLeastSquares.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcurv
{
namespace
{
/// Residual degrees of freedom a fit keeps beyond its unknowns.
constexpr int ResidualRows = 2;

/// tan(pi / 8): the sixteenths of the turn's boundaries within an octant.
constexpr double TanEighthPi = 0.41421356237309503;

/// The sixteenth of the turn (0..15) the direction (u, v) lies in, as the
/// oriented circles' kernels count them.
int SixteenthOfTurn(double u, double v)
{
  const double a = std::fabs(u), b = std::fabs(v);
  const int within = b < TanEighthPi * a ? 0 : (b < a ? 1 : (a > TanEighthPi * b ? 2 : 3));
  const int right = v >= 0.0 ? within : -1 - within;
  const int left = v > 0.0 ? 7 - within : -8 + within;
  return (u > 0.0 ? right : left) + 8;
}

using Row = double[NormalFieldSums::Unknowns];

/// Adds a neighbor's two rows (slopes along v0 and w0, targets yu, yv).
void AddRows(const Row& ru, const Row& rv, double yu, double yv, NormalFieldSums& sums)
{
  constexpr int N = NormalFieldSums::Unknowns;
  int k = 0;
  for (int a = 0; a < N; ++a)
  {
    for (int b = a; b < N; ++b, ++k)
    {
      sums.MatrixU[k] += ru[a] * ru[b];
      sums.MatrixV[k] += rv[a] * rv[b];
      sums.MatrixCross[k] += ru[a] * rv[b] + rv[a] * ru[b];
    }
    sums.RightU[a] += ru[a] * yu;
    sums.RightV[a] += rv[a] * yv;
    sums.RightUV[a] += ru[a] * yv;
    sums.RightVU[a] += rv[a] * yu;
  }
  sums.TargetsU += yu * yu;
  sums.TargetsV += yv * yv;
  sums.TargetsUV += yu * yv;
}

/// The leading n x n block of a sums' upper triangle, in full.
template<int N>
small::Matrix<N> Leading(const std::array<double, NormalFieldSums::Entries>& upper)
{
  small::Matrix<N> m;
  constexpr int Full = NormalFieldSums::Unknowns;
  for (int a = 0, k = 0; a < Full; ++a)
  {
    for (int b = a; b < Full; ++b, ++k)
    {
      if (a < N && b < N)
      {
        m(a, b) = m(b, a) = upper[k];
      }
    }
  }
  return m;
}

template<int N>
small::Vector<N> Leading(const std::array<double, NormalFieldSums::Unknowns>& right)
{
  return Eigen::Map<const small::Vector<NormalFieldSums::Unknowns>>(right.data())
    .template head<N>();
}

} // namespace

void NormalFieldAccumulator::Begin(const TangentFrame& frame)
{
  this->Frame = frame;
  this->Totals = NormalFieldSums{};
}

void NormalFieldAccumulator::Add(const double d[3], const double* normal)
{
  const TangentFrame& f = this->Frame;
  const double u = d[0] * f.V0[0] + d[1] * f.V0[1] + d[2] * f.V0[2];
  const double v = d[0] * f.W0[0] + d[1] * f.W0[1] + d[2] * f.W0[2];
  const double h = d[0] * f.Normal[0] + d[1] * f.Normal[1] + d[2] * f.Normal[2];
  const double squared = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  if (!(squared > 0.0))
  {
    return;
  }
  NormalFieldSums& sums = this->Totals;
  ++sums.Neighbors;
  sums.SquaredDistances += squared;
  if (u != 0.0 || v != 0.0)
  {
    const int sector = SixteenthOfTurn(u, v);
    sums.Sectors |= 1u << sector;
    // 2 phi is in the eighth of the turn four after phi's sixteenth.
    sums.HalfTurnPositions |= 1u << ((sector + 4) & 7);
  }
  const bool withNormal = normal && (normal[0] != 0.0 || normal[1] != 0.0 || normal[2] != 0.0);
  double along = 0.0;
  if (withNormal)
  {
    along = normal[0] * f.Normal[0] + normal[1] * f.Normal[1] + normal[2] * f.Normal[2];
    ++sums.NeighborsWithNormal;
  }
  const bool opposing = withNormal && along < 0.0;
  if (opposing)
  {
    ++sums.Opposing;
    sums.OpposingHeights += h;
    sums.OpposingSquaredHeights += h * h;
  }
  else
  {
    sums.AgreeingHeights += h;
    sums.AgreeingSquaredHeights += h * h;
  }
  const double side = opposing ? -1.0 : 1.0;
  if (!withNormal || !std::isfinite(along))
  {
    return;
  }
  const double mu = side * (normal[0] * f.V0[0] + normal[1] * f.V0[1] + normal[2] * f.V0[2]);
  const double mv = side * (normal[0] * f.W0[0] + normal[1] * f.W0[1] + normal[2] * f.W0[2]);
  // The unknowns C, A, B, tu, tv, c30, c21, c12, c03.
  const Row rowU = { u, u, v, 1.0, 0.0, 3.0 * u * u, 2.0 * u * v, v * v, 0.0 };
  const Row rowV = { v, -v, u, 0.0, 1.0, 0.0, u * u, 2.0 * u * v, 3.0 * v * v };
  AddRows(rowU, rowV, -mu, -mv, sums);
  ++sums.Rows;
}

namespace
{
/// The fit's curvatures, directions, errors and surface into `result`,
/// from its unknowns `x`, the covariance of (C, A, B) and the residual
/// variances of a neighbor's two rows (`uu`, `vv`).
template<int N>
void DescribeFieldFit(const small::Vector<N>& x,
  const Eigen::Matrix3d& covariance,
  double uu,
  double vv,
  const TangentFrame& frame,
  double inverseScale,
  OrientedCircleResult& result)
{
  PointCurvature& out = result.Curvature;
  const double variance = 0.5 * (uu + vv);
  const double c = x[1], s = x[2];
  const double amplitude = std::hypot(c, s);
  result.StandardError = CurvatureStandardError(covariance, c, s) * inverseScale;
  result.CombinedStandardError = result.StandardError;
  result.TiltBias = (x[3] * x[3] + x[4] * x[4]) * (std::fabs(x[0]) + amplitude) * inverseScale;
  SineFit sine;
  sine.Valid = true;
  sine.Offset = x[0] * inverseScale;
  sine.CosineAmplitude = c * inverseScale;
  sine.SineAmplitude = s * inverseScale;
  sine.RmsResidual = std::sqrt(variance) * inverseScale;
  sine.ValidDirections = out.ValidDirections;
  // The query point's displacement along the surface tilts an exact
  // normal's frame against the fitted one by the shape operator times that
  // displacement, as a neighbor's displacement moves its rows: the rows'
  // residual is the displacement's expected square tilt.
  const double k1 = x[0] + amplitude, k2 = x[0] - amplitude;
  const double curvatures = k1 * k1 + k2 * k2;
  const double displacement = curvatures > 0.0 ? (uu + vv) / curvatures : 0.0;
  const TangentFrame fitted = FittedFrame(frame, x[3], x[4], k1, k2, displacement);
  PrincipalCurvaturesFromSine(sine, fitted, out);
  std::array<double, 15>& surface = result.Surface.Coefficients;
  std::copy_n(x.data(), N, surface.begin());
  result.Surface.InverseScale = inverseScale;
  result.Surface.NoiseVariance = variance;
  result.Surface.Circles = false;
  out.FittedNormal = out.Valid ? fitted.Normal : Vector3{ { 0.0, 0.0, 0.0 } };
  if (!out.Valid)
  {
    result.StandardError = std::numeric_limits<double>::quiet_NaN();
  }
}
} // namespace

template<int Order>
OrientedCircleResult FitNormalField(const NormalFieldSums& sums,
  const TangentFrame& frame,
  double inverseScale,
  int minimumNeighbors,
  double maximumOpposing)
{
  constexpr int N = Order == 2 ? 5 : NormalFieldSums::Unknowns;
  OrientedCircleResult result;
  result.Order = Order;
  result.StandardError = std::numeric_limits<double>::quiet_NaN();
  PointCurvature& out = result.Curvature;
  out.NeighborCount = sums.Neighbors;
  out.ValidDirections = __builtin_popcount(sums.Sectors);
  out.Reason = sums.WhyUnfit(
    sums.Rows, std::max(minimumNeighbors, (N + 1) / 2 + ResidualRows), maximumOpposing);
  if (out.Reason != UnestimatedReason::None)
  {
    return result;
  }
  const small::Matrix<N> alongU = Leading<N>(sums.MatrixU), alongV = Leading<N>(sums.MatrixV);
  const small::Matrix<N> matrix = alongU + alongV;
  const small::Vector<N> rightU = Leading<N>(sums.RightU), rightV = Leading<N>(sums.RightV);
  const small::Vector<N> right = rightU + rightV;
  const small::Solution<N> fit = small::Solve<N>(matrix, right, true);
  if (!fit.Valid)
  {
    out.Reason = UnestimatedReason::FitFailed;
    return result;
  }
  // The residual covariance of a neighbor's two rows, from the sums:
  // sum (yu - ru x)^2 = sum yu^2 - 2 x . sum ru yu + x' (sum ru ru') x, and
  // so on for the other entries.
  const small::Vector<N>& x = fit.X;
  const small::Matrix<N> cross = Leading<N>(sums.MatrixCross);
  const double degrees = std::max(1.0, sums.Rows - 0.5 * N);
  const double uu =
    std::max(0.0, sums.TargetsU - 2.0 * x.dot(rightU) + x.dot(alongU * x)) / degrees;
  const double vv =
    std::max(0.0, sums.TargetsV - 2.0 * x.dot(rightV) + x.dot(alongV * x)) / degrees;
  const double uv = (sums.TargetsUV - x.dot(Leading<N>(sums.RightUV)) -
                      x.dot(Leading<N>(sums.RightVU)) + 0.5 * x.dot(cross * x)) /
    degrees;
  // The sandwich: (C, A, B)'s covariance is B' (uu Mu + vv Mv + uv Mx) B,
  // B their three columns of the inverse normal matrix.
  const small::Matrix<N> meat = uu * alongU + vv * alongV + uv * cross;
  const Eigen::Matrix<double, N, 3>& columns = fit.Inverse;
  const Eigen::Matrix3d covariance = columns.transpose() * meat * columns;
  DescribeFieldFit<N>(fit.X, covariance, uu, vv, frame, inverseScale, result);
  out.NeighborCount = sums.Neighbors;
  return result;
}

void SetHeightOfPoints(const TangentFrame& frame,
  const double* dx,
  const double* dy,
  const double* dz,
  std::size_t count,
  FittedSurface& surface)
{
  const std::array<double, 15>& x = surface.Coefficients;
  double sum = 0.0, squares = 0.0;
  std::size_t used = 0;
  for (std::size_t i = 0; i < count; ++i)
  {
    const double d[3] = { dx[i], dy[i], dz[i] };
    const double u = d[0] * frame.V0[0] + d[1] * frame.V0[1] + d[2] * frame.V0[2];
    const double v = d[0] * frame.W0[0] + d[1] * frame.W0[1] + d[2] * frame.W0[2];
    const double h = d[0] * frame.Normal[0] + d[1] * frame.Normal[1] + d[2] * frame.Normal[2];
    if (u == 0.0 && v == 0.0 && h == 0.0)
    {
      continue; // the query point: it has no residual of its own
    }
    const double model = x[3] * u + x[4] * v +
      0.5 * ((x[0] + x[1]) * u * u + 2.0 * x[2] * u * v + (x[0] - x[1]) * v * v) +
      x[5] * u * u * u + x[6] * u * u * v + x[7] * u * v * v + x[8] * v * v * v;
    const double residual = h - model;
    sum += residual;
    squares += residual * residual;
    ++used;
  }
  if (used < 2)
  {
    return;
  }
  const double mean = sum / static_cast<double>(used);
  surface.Coefficients[9] = 2.0 * mean;
  surface.NoiseVariance = std::max(0.0, squares - mean * sum) / static_cast<double>(used - 1);
}

template OrientedCircleResult FitNormalField<2>(const NormalFieldSums&,
  const TangentFrame&,
  double,
  int,
  double);
template OrientedCircleResult FitNormalField<3>(const NormalFieldSums&,
  const TangentFrame&,
  double,
  int,
  double);

} // namespace pcurv
