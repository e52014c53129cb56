#include "OrientedCircleFit.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace pcurv
{
namespace
{
using Vector5 = Eigen::Matrix<double, 5, 1>;
using Matrix5 = Eigen::Matrix<double, 5, 5>;

/// A variance below this (in units of the scale) is taken as this: exact
/// data would otherwise get an infinite weight.
constexpr double VarianceFloor = 1e-24;

/// The unknowns (C, A, B, tilt u, tilt v) of one fit and its normal
/// equations' inverse.
struct Solution
{
  bool Valid = false;
  Vector5 X = Vector5::Zero();
  Matrix5 Inverse = Matrix5::Zero();
};

/// Weighted least squares from normal equations; invalid when they are
/// singular to working precision.
Solution Solve(const Matrix5& normal, const Vector5& right)
{
  Solution solution;
  Eigen::LDLT<Matrix5> ldlt(normal);
  const double largest = normal.diagonal().maxCoeff();
  if (ldlt.info() != Eigen::Success || !(largest > 0.0) ||
    !(ldlt.vectorD().cwiseAbs().minCoeff() > 1e-12 * largest))
  {
    return solution;
  }
  solution.X = ldlt.solve(right);
  solution.Inverse = ldlt.solve(Matrix5::Identity());
  solution.Valid = solution.X.allFinite();
  return solution;
}
} // namespace

void OrientedCircleEstimator::Begin(const Vector3& unitNormal, double scale)
{
  this->Frame = MakeTangentFrame(unitNormal);
  this->InverseScale = 1.0 / scale;
  this->Opposing = 0;
  for (std::vector<double>* values : { &this->U, &this->V, &this->H, &this->D, &this->T })
  {
    values->clear();
  }
  this->HasNormal.clear();
}

void OrientedCircleEstimator::AddNeighbor(const double offset[3], const double normal[3])
{
  const double d[3] = {
    offset[0] * this->InverseScale, offset[1] * this->InverseScale, offset[2] * this->InverseScale
  };
  const double squared = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  if (!(squared > 0.0))
  {
    return; // at the query point: no direction, no curvature
  }
  const Vector3& n = this->Frame.Normal;
  this->U.push_back(d[0] * this->Frame.V0[0] + d[1] * this->Frame.V0[1] + d[2] * this->Frame.V0[2]);
  this->V.push_back(d[0] * this->Frame.W0[0] + d[1] * this->Frame.W0[1] + d[2] * this->Frame.W0[2]);
  this->H.push_back(d[0] * n[0] + d[1] * n[1] + d[2] * n[2]);
  this->D.push_back(squared);
  const bool hasNormal = normal[0] != 0.0 || normal[1] != 0.0 || normal[2] != 0.0;
  double t = 0.0;
  if (hasNormal)
  {
    // The paper's sign: a circle bending towards n has positive curvature.
    t = -((normal[0] - n[0]) * d[0] + (normal[1] - n[1]) * d[1] + (normal[2] - n[2]) * d[2]);
    this->Opposing += normal[0] * n[0] + normal[1] * n[1] + normal[2] * n[2] < 0.0;
  }
  this->T.push_back(t);
  this->HasNormal.push_back(hasNormal);
}

PointCurvature OrientedCircleEstimator::Estimate(int minimumNeighbors,
  double maximumOpposing,
  double& standardError) const
{
  PointCurvature out;
  standardError = std::numeric_limits<double>::quiet_NaN();
  const std::size_t count = this->U.size();
  out.NeighborCount = static_cast<int>(count);
  if (count < static_cast<std::size_t>(std::max(minimumNeighbors, 6)) ||
    this->Opposing > maximumOpposing * static_cast<double>(count))
  {
    return out;
  }
  // The angles must not all lie in a closed half-turn of 2 phi (the sine
  // fit's rule): 8 positions of 2 phi, the largest gap below 4.
  std::array<bool, NumberOfDirections> sector{};
  std::array<bool, 8> halfTurn{};
  std::vector<double> cos2(count), sin2(count);
  for (std::size_t j = 0; j < count; ++j)
  {
    const double rho2 = this->U[j] * this->U[j] + this->V[j] * this->V[j];
    if (!(rho2 > 0.0))
    {
      continue; // on the normal line: no direction (its rows carry no angle)
    }
    cos2[j] = (this->U[j] * this->U[j] - this->V[j] * this->V[j]) / rho2;
    sin2[j] = 2.0 * this->U[j] * this->V[j] / rho2;
    const double angle = std::atan2(this->V[j], this->U[j]); // (-pi, pi]
    const int s = static_cast<int>(std::floor((angle + M_PI) / (2.0 * M_PI) * NumberOfDirections));
    sector[std::min(std::max(s, 0), NumberOfDirections - 1)] = true;
    const int p =
      static_cast<int>(std::floor((std::atan2(sin2[j], cos2[j]) + M_PI) / (M_PI / 4.0)));
    halfTurn[std::min(std::max(p, 0), 7)] = true;
  }
  int occupied = 0, largestGap = 0;
  for (int i = 0; i < 8; ++i)
  {
    occupied += halfTurn[i];
    if (halfTurn[i])
    {
      int gap = 1;
      while (gap < 8 && !halfTurn[(i + gap) % 8])
      {
        ++gap;
      }
      largestGap = std::max(largestGap, gap);
    }
  }
  out.ValidDirections = static_cast<int>(std::count(sector.begin(), sector.end(), true));
  if (occupied < 3 || largestGap >= 4)
  {
    return out;
  }

  // Rows: positions [D, D cos, D sin, 2u, 2v] -> 2h; normals [D, D cos,
  // D sin, u, v] -> t. Weights: wPosition each, wNormal / D each.
  auto fit = [&](double wPosition, double wNormal)
  {
    Matrix5 normal = Matrix5::Zero();
    Vector5 right = Vector5::Zero();
    for (std::size_t j = 0; j < count; ++j)
    {
      const double dj = this->D[j];
      Vector5 row;
      row << dj, dj * cos2[j], dj * sin2[j], 2.0 * this->U[j], 2.0 * this->V[j];
      if (wPosition > 0.0)
      {
        normal.noalias() += wPosition * row * row.transpose();
        right.noalias() += wPosition * 2.0 * this->H[j] * row;
      }
      if (wNormal > 0.0 && this->HasNormal[j])
      {
        row[3] = this->U[j];
        row[4] = this->V[j];
        normal.noalias() += (wNormal / dj) * row * row.transpose();
        right.noalias() += (wNormal / dj) * this->T[j] * row;
      }
    }
    return Solve(normal, right);
  };
  // Mean squared residuals of each kind under a solution: positions in h,
  // normals per unit of D (their error grows like |d|).
  auto residuals = [&](const Solution& s, double& position, double& normal, int& normals)
  {
    position = normal = 0.0;
    normals = 0;
    for (std::size_t j = 0; j < count; ++j)
    {
      const double dj = this->D[j];
      const double curvature = s.X[0] + s.X[1] * cos2[j] + s.X[2] * sin2[j];
      const double ep =
        dj * curvature + 2.0 * (s.X[3] * this->U[j] + s.X[4] * this->V[j]) - 2.0 * this->H[j];
      position += ep * ep;
      if (this->HasNormal[j])
      {
        const double en = dj * curvature + s.X[3] * this->U[j] + s.X[4] * this->V[j] - this->T[j];
        normal += en * en / dj;
        ++normals;
      }
    }
    position /= std::max<double>(1.0, static_cast<double>(count) - 5.0);
    normal /= std::max(1.0, normals - 5.0);
  };

  const Solution positionsOnly = fit(1.0, 0.0);
  if (!positionsOnly.Valid)
  {
    return out;
  }
  double positionVariance = 0.0, normalVariance = 0.0, unused = 0.0;
  int normals = 0;
  residuals(positionsOnly, positionVariance, unused, normals);
  Solution combined = positionsOnly;
  if (normals >= 6)
  {
    const Solution normalsOnly = fit(0.0, 1.0);
    if (normalsOnly.Valid)
    {
      double unusedPosition = 0.0;
      residuals(normalsOnly, unusedPosition, normalVariance, normals);
      const Solution both = fit(1.0 / std::max(positionVariance, VarianceFloor),
        1.0 / std::max(normalVariance, VarianceFloor));
      if (both.Valid)
      {
        combined = both;
      }
    }
  }

  // The standard error of the positions-only fit: the neighbours' estimated
  // normals share their neighbourhoods, so their errors are correlated and
  // the combined fit's covariance would understate its error; the
  // positions' errors are independent, and the combined fit is at least as
  // good as the positions alone.
  const Matrix5 covariance = positionsOnly.Inverse * std::max(positionVariance, VarianceFloor);
  const double amplitude = std::hypot(combined.X[1], combined.X[2]);
  const double amplitudeVariance = amplitude > 0.0
    ? (combined.X[1] * combined.X[1] * covariance(1, 1) +
        2.0 * combined.X[1] * combined.X[2] * covariance(1, 2) +
        combined.X[2] * combined.X[2] * covariance(2, 2)) /
      (amplitude * amplitude)
    : std::max(covariance(1, 1), covariance(2, 2));
  standardError = std::sqrt(std::max(0.0, covariance(0, 0)) + std::max(0.0, amplitudeVariance)) *
    this->InverseScale;

  // RMS of the position rows' residuals as curvatures (residual / D).
  double rms = 0.0;
  for (std::size_t j = 0; j < count; ++j)
  {
    const double dj = this->D[j];
    const double curvature = combined.X[0] + combined.X[1] * cos2[j] + combined.X[2] * sin2[j];
    const double e = curvature +
      (2.0 * (combined.X[3] * this->U[j] + combined.X[4] * this->V[j]) - 2.0 * this->H[j]) / dj;
    rms += e * e;
  }
  rms = std::sqrt(rms / static_cast<double>(count));

  SineFit sine;
  sine.Valid = true;
  sine.Offset = combined.X[0] * this->InverseScale;
  sine.CosineAmplitude = combined.X[1] * this->InverseScale;
  sine.SineAmplitude = combined.X[2] * this->InverseScale;
  sine.RmsResidual = rms * this->InverseScale;
  sine.ValidDirections = out.ValidDirections;
  PrincipalCurvaturesFromSine(sine, this->Frame, out);
  out.NeighborCount = static_cast<int>(count);
  if (!out.Valid)
  {
    standardError = std::numeric_limits<double>::quiet_NaN();
  }
  return out;
}

} // namespace pcurv
