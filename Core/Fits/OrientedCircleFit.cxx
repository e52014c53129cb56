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
template<int N>
using Vector = small::Vector<N>;
template<int N>
using Matrix = small::Matrix<N>;
using small::Solution;
using small::Solve;
/// Fewer neighbors than the unknowns and two leave the fit without a
/// residual to weigh it.
constexpr int ResidualNeighbors = 2;

/// A variance below this (in units of the scale) is taken as this: exact
/// data would otherwise get an infinite weight.
constexpr double VarianceFloor = 1e-24;

template<int N>
Matrix<N> Full(const std::array<double, N*(N + 1) / 2>& upper)
{
  Matrix<N> m;
  int k = 0;
  for (int a = 0; a < N; ++a)
  {
    for (int b = a; b < N; ++b)
    {
      m(a, b) = m(b, a) = upper[k++];
    }
  }
  return m;
}

template<int N>
Vector<N> Full(const std::array<double, N>& right)
{
  return Eigen::Map<const Vector<N>>(right.data());
}

/// The mean squared residual of a least-squares solution from the sums:
/// sum (row x - y)^2 = sum y^2 - x . b at the solution.
template<int N>
double ResidualVariance(const Solution<N>& s, const Vector<N>& right, double targets, int rows)
{
  return std::max(0.0, targets - s.X.dot(right)) / std::max(1, rows - N);
}

} // namespace

/// The largest circular gap between the occupied eighths of 2 phi is below
/// a half-turn, and at least three are occupied (the sine fit's rule).
bool AnglesDetermineSine(std::uint32_t positions)
{
  int occupied = 0, largestGap = 0;
  for (int i = 0; i < 8; ++i)
  {
    if (positions & (1u << i))
    {
      ++occupied;
      int gap = 1;
      while (gap < 8 && !(positions & (1u << ((i + gap) % 8))))
      {
        ++gap;
      }
      largestGap = std::max(largestGap, gap);
    }
  }
  return occupied >= 3 && largestGap < 4;
}

/// The frame of the fitted tangent plane, for the principal directions.
/// The fit's tilt (delta_u, delta_v) is the surface's slope in the query
/// normal's frame, so n - delta_u v0 - delta_w w0 is the fitted normal. An
/// estimated query normal is off by its error, and directions in its plane
/// would inherit it, however good the curvatures; an exact normal is off by
/// nothing, and its fitted tilt is the query point's displacement along the
/// surface (a point displaced by e sees the surface tilted by W e, W the
/// shape operator: |W e|^2 is sigma^2 (k1^2 + k2^2) on average) and the fit's
/// own bias. So the tilt is applied by the share of it that the
/// displacement does not explain, none when it explains the tilt's square
/// DisplacementTiltAllowance times over. In units of the scale:
/// `noiseVariance` is the positions' (a quarter of the residual variance
/// of their rows, which are 2 h), k1, k2 the principal curvatures.
TangentFrame FittedFrame(const TangentFrame& frame,
  double tiltU,
  double tiltV,
  double k1,
  double k2,
  double noiseVariance)
{
  const double tilt = tiltU * tiltU + tiltV * tiltV;
  const double share = TiltShare(tilt, noiseVariance * (k1 * k1 + k2 * k2));
  if (!(share > 0.0))
  {
    return frame;
  }
  using Vector3d = Eigen::Vector3d;
  const Vector3d normal(frame.Normal.data()), v0(frame.V0.data()), w0(frame.W0.data());
  const Vector3d fitted = (normal - share * (tiltU * v0 + tiltV * w0)).normalized();
  // v0 turned into the fitted plane: the angles phi of the sine stay those
  // the neighbors were fitted at, to first order in the tilt.
  const Vector3d v = (v0 - v0.dot(fitted) * fitted).normalized();
  const Vector3d w = fitted.cross(v);
  if (!fitted.allFinite() || !v.allFinite())
  {
    return frame;
  }
  TangentFrame turned;
  for (int i = 0; i < 3; ++i)
  {
    turned.Normal[i] = fitted[i];
    turned.V0[i] = v[i];
    turned.W0[i] = w[i];
  }
  return turned;
}

namespace
{
int PopCount(std::uint32_t bits)
{
  int count = 0;
  for (; bits; bits &= bits - 1)
  {
    ++count;
  }
  return count;
}
} // namespace

template<int Order>
void OrientedCircleAccumulatorOf<Order>::Begin(const TangentFrame& frame)
{
  for (int k = 0; k < 3; ++k)
  {
    this->Frame.Normal[k] = frame.Normal[k];
    this->Frame.V[k] = frame.V0[k];
    this->Frame.W[k] = frame.W0[k];
  }
  this->Banked = oriented::BankedSums<Order>{};
  this->PendingCount = 0;
}

template<int Order>
void OrientedCircleAccumulatorOf<Order>::AddPending()
{
  const oriented::NeighborBatch pending{ this->Pending[0].data(),
    this->Pending[1].data(),
    this->Pending[2].data(),
    this->Pending[3].data(),
    this->Pending[4].data(),
    this->Pending[5].data(),
    static_cast<std::size_t>(this->PendingCount) };
  oriented::AddNeighbors(this->Frame, pending, this->Banked);
  this->PendingCount = 0;
}

template<int Order>
const OrientedCircleSumsOf<Order>& OrientedCircleAccumulatorOf<Order>::Sums()
{
  using L = oriented::Layout<Order>;
  this->AddPending();
  // Each sum's eight banks, added in a fixed order.
  double totals[L::NumberOfEntries];
  oriented::CombineBanks(this->Banked.Banks, L::NumberOfEntries, totals);
  OrientedCircleSumsOf<Order>& sums = this->Totals;
  std::copy_n(totals + L::PositionMatrix, sums.PositionMatrix.size(), sums.PositionMatrix.begin());
  std::copy_n(totals + L::PositionRight, sums.PositionRight.size(), sums.PositionRight.begin());
  std::copy_n(totals + L::NormalMatrix, sums.NormalMatrix.size(), sums.NormalMatrix.begin());
  std::copy_n(totals + L::NormalRight, sums.NormalRight.size(), sums.NormalRight.begin());
  sums.PositionTargets = totals[L::PositionTargets];
  sums.NormalTargets = totals[L::NormalTargets];
  sums.Neighbors = static_cast<int>(totals[L::Neighbors]);
  sums.NeighborsWithNormal = static_cast<int>(totals[L::NeighborsWithNormal]);
  sums.Opposing = static_cast<int>(totals[L::Opposing]);
  sums.OpposingHeights = totals[L::OpposingHeights];
  sums.AgreeingHeights = totals[L::AgreeingHeights];
  sums.OpposingSquaredHeights = totals[L::OpposingSquaredHeights];
  sums.AgreeingSquaredHeights = totals[L::AgreeingSquaredHeights];
  sums.SquaredDistances = totals[L::SquaredDistances];
  sums.Sectors = this->Banked.Sectors;
  sums.HalfTurnPositions = this->Banked.HalfTurnPositions;
  return sums;
}

bool OrientedCircleTallies::ReachesAcross(double maximumOpposing) const
{
  if (this->Opposing == 0 || !(this->Opposing > maximumOpposing * this->Neighbors))
  {
    return false;
  }
  if (this->Opposing == this->Neighbors)
  {
    return true; // every neighbor's normal opposes the point's own
  }
  const double opposing = this->Opposing, agreeing = this->Neighbors - this->Opposing;
  const double opposingLevel = this->OpposingHeights / opposing;
  const double agreeingLevel = this->AgreeingHeights / agreeing;
  // The heights' spread about each group's level, pooled.
  const double spread = std::max(0.0,
    (this->OpposingSquaredHeights - opposing * opposingLevel * opposingLevel +
      this->AgreeingSquaredHeights - agreeing * agreeingLevel * agreeingLevel) /
      std::max(1.0, opposing + agreeing - 2.0));
  const double difference = std::fabs(opposingLevel - agreeingLevel);
  const double size = std::sqrt(this->SquaredDistances / this->Neighbors);
  return difference > 3.0 * std::sqrt(spread * (1.0 / opposing + 1.0 / agreeing)) &&
    difference > 0.05 * size;
}

UnestimatedReason OrientedCircleTallies::WhyUnfit(int count,
  int fewest,
  double maximumOpposing) const
{
  if (count < fewest)
  {
    return UnestimatedReason::TooFewNeighbors;
  }
  if (this->ReachesAcross(maximumOpposing))
  {
    return UnestimatedReason::ReachesAcross;
  }
  if (!AnglesDetermineSine(this->HalfTurnPositions))
  {
    return UnestimatedReason::TooFewDirections;
  }
  return UnestimatedReason::None;
}

namespace
{
/// The fit of the positions' rows and the normals' together, each weighted
/// by the inverse of its residual variance, into `combined` where it
/// solves (where the normals' rows determine their unknowns); true where
/// combined.Inverse is then the combined fit's covariance (with
/// `combinedError`).
template<int Order>
bool CombineWithNormals(const OrientedCircleSumsOf<Order>& sums,
  const Matrix<OrientedCircleSumsOf<Order>::PositionUnknowns>& positionMatrix,
  const Vector<OrientedCircleSumsOf<Order>::PositionUnknowns>& positionRight,
  double positionVariance,
  bool combinedError,
  Solution<OrientedCircleSumsOf<Order>::PositionUnknowns>& combined)
{
  constexpr int PositionUnknowns = OrientedCircleSumsOf<Order>::PositionUnknowns;
  constexpr int NormalUnknowns = OrientedCircleSumsOf<Order>::NormalUnknowns;
  using PositionVector = Vector<PositionUnknowns>;
  using PositionMatrix = Matrix<PositionUnknowns>;
  using NormalVector = Vector<NormalUnknowns>;
  using NormalMatrix = Matrix<NormalUnknowns>;
  bool hasCombinedCovariance = false;
  if (sums.NeighborsWithNormal > NormalUnknowns)
  {
    const NormalMatrix normalMatrix = Full<NormalUnknowns>(sums.NormalMatrix);
    const NormalVector normalRight = Full<NormalUnknowns>(sums.NormalRight);
    const Solution<NormalUnknowns> normals =
      Solve<NormalUnknowns>(normalMatrix, normalRight, false);
    if (normals.Valid)
    {
      const double normalVariance = std::max(
        ResidualVariance(normals, normalRight, sums.NormalTargets, sums.NeighborsWithNormal),
        VarianceFloor);
      // The normals do not see the height (the last unknown): their rows
      // are zero there.
      PositionMatrix matrix = positionMatrix / positionVariance;
      PositionVector right = positionRight / positionVariance;
      matrix.template topLeftCorner<NormalUnknowns, NormalUnknowns>() +=
        normalMatrix / normalVariance;
      right.template head<NormalUnknowns>() += normalRight / normalVariance;
      const Solution<PositionUnknowns> both = Solve<PositionUnknowns>(matrix, right, combinedError);
      combined = both.Valid ? both : combined;
      hasCombinedCovariance = both.Valid && combinedError;
    }
  }
  return hasCombinedCovariance;
}

/// The surface's coefficients of the fit's unknowns `x`, which have the
/// height last: up to the cubic's, the height, the quartic's.
template<int N>
void SetSurfaceCoefficients(const Vector<N>& x, std::array<double, 15>& surface)
{
  // (A fit of the second order leaves the cubic's zero.)
  constexpr int Leading = std::min(oriented::FirstQuarticColumn, N - 1);
  std::copy_n(x.data(), Leading, surface.begin());
  surface[oriented::FirstQuarticColumn] = x[N - 1];
  std::copy_n(
    x.data() + Leading, N - 1 - Leading, surface.begin() + FittedSurface::FirstQuarticCoefficient);
}

/// The fit's curvatures, directions, errors and surface into `result`,
/// from the positions' rows alone (`positions`, of residual variance
/// `positionVariance`) and the combined fit (`combined`, its covariance
/// in combined.Inverse where `hasCombinedCovariance`).
template<int Order>
void DescribeCircleFit(const OrientedCircleSumsOf<Order>& sums,
  const Matrix<OrientedCircleSumsOf<Order>::PositionUnknowns>& positionMatrix,
  const Solution<OrientedCircleSumsOf<Order>::PositionUnknowns>& positions,
  const Solution<OrientedCircleSumsOf<Order>::PositionUnknowns>& combined,
  double positionVariance,
  bool hasCombinedCovariance,
  const TangentFrame& frame,
  double inverseScale,
  OrientedCircleResult& result)
{
  constexpr int PositionUnknowns = OrientedCircleSumsOf<Order>::PositionUnknowns;
  PointCurvature& out = result.Curvature;
  const Eigen::Matrix<double, PositionUnknowns, 3> covariance =
    positions.Inverse * positionVariance;
  const double c = combined.X[1], s = combined.X[2];
  const double amplitude = std::hypot(c, s);
  result.StandardError =
    CurvatureStandardError(covariance.template topRows<3>(), c, s) * inverseScale;
  result.CombinedCovariance = hasCombinedCovariance;
  result.CombinedStandardError = hasCombinedCovariance
    ? CurvatureStandardError(combined.Inverse.template topRows<3>(), c, s) * inverseScale
    : result.StandardError;
  result.PositionsDiscrepancy =
    (std::fabs(combined.X[0] - positions.X[0]) +
      std::fabs(amplitude - std::hypot(positions.X[1], positions.X[2]))) *
    inverseScale;

  result.TiltBias = (combined.X[3] * combined.X[3] + combined.X[4] * combined.X[4]) *
    (std::fabs(combined.X[0]) + amplitude) * inverseScale;
  SineFit sine;
  sine.Valid = true;
  sine.Offset = combined.X[0] * inverseScale;
  sine.CosineAmplitude = c * inverseScale;
  sine.SineAmplitude = s * inverseScale;
  // The positions' residual (in 2 h) as a curvature: over the RMS of D.
  const double rmsD = std::sqrt(positionMatrix(0, 0) / sums.Neighbors);
  sine.RmsResidual = rmsD > 0.0 ? std::sqrt(positionVariance) / rmsD * inverseScale : 0.0;
  sine.ValidDirections = out.ValidDirections;
  const TangentFrame fitted = FittedFrame(frame,
    combined.X[3],
    combined.X[4],
    combined.X[0] + amplitude,
    combined.X[0] - amplitude,
    positionVariance / 4.0);
  PrincipalCurvaturesFromSine(sine, fitted, out);
  SetSurfaceCoefficients<PositionUnknowns>(combined.X, result.Surface.Coefficients);
  result.Surface.InverseScale = inverseScale;
  result.Surface.NoiseVariance = positionVariance / 4.0;
  out.FittedNormal = out.Valid ? fitted.Normal : Vector3{ { 0.0, 0.0, 0.0 } };
  out.NeighborCount = sums.Neighbors;
  if (!out.Valid)
  {
    result.StandardError = std::numeric_limits<double>::quiet_NaN();
  }
}
} // namespace

template<int Order>
OrientedCircleResult FitOrientedCircles(const OrientedCircleSumsOf<Order>& sums,
  const TangentFrame& frame,
  double inverseScale,
  double heightVarianceFloor,
  int minimumNeighbors,
  double maximumOpposing,
  bool combinedError)
{
  constexpr int PositionUnknowns = OrientedCircleSumsOf<Order>::PositionUnknowns;
  using PositionVector = Vector<PositionUnknowns>;
  using PositionMatrix = Matrix<PositionUnknowns>;
  OrientedCircleResult result;
  result.Order = Order;
  PointCurvature& out = result.Curvature;
  result.StandardError = std::numeric_limits<double>::quiet_NaN();
  out.NeighborCount = sums.Neighbors;
  out.ValidDirections = PopCount(sums.Sectors);
  out.Reason = sums.WhyUnfit(sums.Neighbors,
    std::max(minimumNeighbors, PositionUnknowns + ResidualNeighbors),
    maximumOpposing);
  if (out.Reason != UnestimatedReason::None)
  {
    return result;
  }
  const PositionMatrix positionMatrix = Full<PositionUnknowns>(sums.PositionMatrix);
  const PositionVector positionRight = Full<PositionUnknowns>(sums.PositionRight);
  const Solution<PositionUnknowns> positions =
    Solve<PositionUnknowns>(positionMatrix, positionRight, true);
  if (!positions.Valid)
  {
    return result;
  }
  // The positions' rows fit twice the height (in units of the scale).
  const double positionVariance =
    std::max({ ResidualVariance(positions, positionRight, sums.PositionTargets, sums.Neighbors),
      4.0 * heightVarianceFloor * inverseScale * inverseScale,
      VarianceFloor });
  Solution<PositionUnknowns> combined = positions;
  // With `combinedError`: combined.Inverse is the combined fit's covariance
  // (its rows are weighted by the inverse of their variances).
  const bool hasCombinedCovariance = CombineWithNormals<Order>(
    sums, positionMatrix, positionRight, positionVariance, combinedError, combined);
  DescribeCircleFit<Order>(sums,
    positionMatrix,
    positions,
    combined,
    positionVariance,
    hasCombinedCovariance,
    frame,
    inverseScale,
    result);
  return result;
}

double ReportedStandardError(const OrientedCircleResult& chosen,
  const OrientedCircleResult* previous,
  double precision)
{
  const PointCurvature& k = chosen.Curvature;
  const double grown = previous
    ? std::max(std::fabs(k.MinimumCurvature - previous->Curvature.MinimumCurvature),
        std::fabs(k.MaximumCurvature - previous->Curvature.MaximumCurvature))
    : 0.0;
  const double floor =
    precision * std::max(std::fabs(k.MinimumCurvature), std::fabs(k.MaximumCurvature));
  // Where the normals follow the surface (a fit of the fourth order, or of
  // the third beside it: both have the combined covariance) the combined
  // fit's own error, inflated, stands for both the positions-only fit's and
  // the normals' pull: with exact normals the combined fit is far more
  // precise than the positions alone (of 15 unknowns, or of 10 at the wide
  // radii noise calls for).
  const bool combined =
    !chosen.EstimatedNormals && (chosen.Order == 4 || chosen.CombinedCovariance);
  const double parts[] = { combined ? CombinedErrorFactor * chosen.CombinedStandardError
                                    : chosen.StandardError,
    combined ? 0.0 : chosen.PositionsDiscrepancy,
    chosen.TiltBias,
    chosen.OrderDiscrepancy,
    grown,
    floor };
  double sum = 0.0;
  for (const double part : parts)
  {
    sum += part * part;
  }
  return ReportedErrorFactor * std::sqrt(sum);
}

void OrientedCircleEstimator::Begin(const Vector3& unitNormal, double scale)
{
  this->Frame = MakeTangentFrame(unitNormal);
  this->InverseScale = 1.0 / scale;
  this->Sums.Begin(this->Frame);
}

void OrientedCircleEstimator::AddNeighbor(const double offset[3], const double normal[3])
{
  const double d[3] = {
    offset[0] * this->InverseScale, offset[1] * this->InverseScale, offset[2] * this->InverseScale
  };
  this->Sums.Add(d, normal);
}

template<int Lower, int Higher>
OrientedCircleSumsOf<Lower> LowerOrderPart(const OrientedCircleSumsOf<Higher>& sums)
{
  constexpr int Low = OrientedCircleSumsOf<Lower>::PositionUnknowns;
  constexpr int High = OrientedCircleSumsOf<Higher>::PositionUnknowns;
  // The leading unknowns the same, then the height (last of both).
  auto positionOf = [](int i) { return i < Low - 1 ? i : High - 1; };
  auto upperIndex = [](int a, int b, int n) { return a * n - a * (a - 1) / 2 + (b - a); };
  OrientedCircleSumsOf<Lower> part;
  for (int a = 0, k = 0; a < Low; ++a)
  {
    part.PositionRight[a] = sums.PositionRight[positionOf(a)];
    for (int b = a; b < Low; ++b)
    {
      part.PositionMatrix[k++] =
        sums.PositionMatrix[upperIndex(positionOf(a), positionOf(b), High)];
    }
  }
  constexpr int Normals = OrientedCircleSumsOf<Lower>::NormalUnknowns;
  for (int a = 0, k = 0; a < Normals; ++a)
  {
    part.NormalRight[a] = sums.NormalRight[a];
    for (int b = a; b < Normals; ++b)
    {
      part.NormalMatrix[k++] = sums.NormalMatrix[upperIndex(a, b, High - 1)];
    }
  }
  static_cast<OrientedCircleTallies&>(part) = sums;
  return part;
}

template class OrientedCircleAccumulatorOf<3>;
template class OrientedCircleAccumulatorOf<4>;
template OrientedCircleSumsOf<2> LowerOrderPart<2, 3>(const OrientedCircleSumsOf<3>&);
template OrientedCircleSumsOf<2> LowerOrderPart<2, 4>(const OrientedCircleSumsOf<4>&);
template OrientedCircleSumsOf<3> LowerOrderPart<3, 4>(const OrientedCircleSumsOf<4>&);
template OrientedCircleResult FitOrientedCircles<2>(const QuadraticCircleSums&,
  const TangentFrame&,
  double,
  double,
  int,
  double,
  bool);
template OrientedCircleResult FitOrientedCircles<3>(const OrientedCircleSums&,
  const TangentFrame&,
  double,
  double,
  int,
  double,
  bool);
template OrientedCircleResult FitOrientedCircles<4>(const QuarticCircleSums&,
  const TangentFrame&,
  double,
  double,
  int,
  double,
  bool);
} // namespace pcurv
