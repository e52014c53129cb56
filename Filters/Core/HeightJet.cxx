#include "HeightJet.h"

#include "SmallLeastSquares.h"

#include <cmath>

namespace pcurv
{
namespace
{
using JetVector = small::Vector<HeightJetUnknowns>;
using JetMatrix = small::Matrix<HeightJetUnknowns>;

/// Fewer neighbours than the unknowns and two leave no residual to weigh
/// the fit by.
constexpr std::size_t ResidualNeighbors = 2;

/// The jet's row at (u, v). The second derivatives come first (their
/// monomials u^2/2, uv, v^2/2 have them as coefficients), so that the
/// solver's covariance columns are theirs; then the height, the slopes and
/// the monomials of the third and fourth degree.
JetVector Row(double u, double v)
{
  JetVector row;
  const double uu = u * u, uv = u * v, vv = v * v;
  row << 0.5 * uu, uv, 0.5 * vv, 1.0, u, v, uu * u, uu * v, u * vv, vv * v, uu * uu, uu * uv,
    uu * vv, uv * vv, vv * vv;
  return row;
}

struct Local
{
  double U, V, H;
};

Local InFrame(double dx, double dy, double dz, const TangentFrame& frame, double inverseScale)
{
  const auto dot = [&](const Vector3& axis)
  { return (dx * axis[0] + dy * axis[1] + dz * axis[2]) * inverseScale; };
  return Local{ dot(frame.V0), dot(frame.W0), dot(frame.Normal) };
}

/// The normal equations of the rows so far.
struct JetSums
{
  JetMatrix Normal = JetMatrix::Zero();
  JetVector Right = JetVector::Zero();

  void Add(const JetVector& row, double height)
  {
    // The whole outer product: it vectorises, the triangle does not.
    this->Normal.noalias() += row * row.transpose();
    this->Right += height * row;
  }
};

/// The standard error of the principal curvatures mean +/- amplitude (in
/// units of the scale) from the covariance of the second derivatives
/// (h_uu, h_uv, h_vv).
double SecondOrderStandardError(const Eigen::Matrix3d& covariance,
  double huu,
  double huv,
  double hvv)
{
  const double half = 0.5 * (huu - hvv);
  const double amplitude = std::hypot(half, huv);
  const Eigen::Vector3d mean(0.5, 0.0, 0.5);
  const double meanVariance = mean.dot(covariance * mean);
  double amplitudeVariance = std::max(0.25 * covariance(0, 0), covariance(1, 1));
  if (amplitude > 0.0)
  {
    const Eigen::Vector3d gradient(
      0.5 * half / amplitude, huv / amplitude, -0.5 * half / amplitude);
    amplitudeVariance = gradient.dot(covariance * gradient);
  }
  return std::sqrt(std::max(0.0, meanVariance) + std::max(0.0, amplitudeVariance));
}

/// Principal curvatures (output sign) and directions of the graph of h over
/// the frame's plane at the origin, from its slopes and second derivatives
/// (1/length): the eigenproblem of the second fundamental form against the
/// first, exact for any slope.
void CurvaturesOfGraph(const TangentFrame& frame,
  double hu,
  double hv,
  double huu,
  double huv,
  double hvv,
  PointCurvature& out)
{
  Eigen::Matrix2d first;
  first << 1.0 + hu * hu, hu * hv, hu * hv, 1.0 + hv * hv;
  const double w = std::sqrt(1.0 + hu * hu + hv * hv);
  Eigen::Matrix2d second;
  second << huu / w, huv / w, huv / w, hvv / w;
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> solver(second, first);
  if (solver.info() != Eigen::Success)
  {
    out.Valid = false;
    return;
  }
  const Eigen::Vector3d n(frame.Normal.data()), v0(frame.V0.data()), w0(frame.W0.data());
  const Eigen::Vector3d alongU = v0 + hu * n, alongV = w0 + hv * n;
  const auto direction = [&](int which)
  {
    const Eigen::Vector3d t =
      (solver.eigenvectors()(0, which) * alongU + solver.eigenvectors()(1, which) * alongV)
        .normalized();
    return Vector3{ { t[0], t[1], t[2] } };
  };
  // Output sign: a surface bending away from its normal (a sphere with
  // outward normals) has positive curvature, and the height's second
  // derivative is then negative. Eigenvalues come in increasing order.
  out.MaximumCurvature = -solver.eigenvalues()[0];
  out.MinimumCurvature = -solver.eigenvalues()[1];
  out.MaximumDirection = direction(0);
  out.MinimumDirection = direction(1);
  const Eigen::Vector3d fitted = (n - hu * v0 - hv * w0).normalized();
  out.FittedNormal = Vector3{ { fitted[0], fitted[1], fitted[2] } };
  out.Valid = std::isfinite(out.MaximumCurvature) && std::isfinite(out.MinimumCurvature) &&
    fitted.allFinite();
}

} // namespace

HeightJetFit FitHeightJet(const double* dx,
  const double* dy,
  const double* dz,
  std::size_t count,
  const TangentFrame& frame,
  double scale)
{
  HeightJetFit fit;
  fit.Curvature.NeighborCount = static_cast<int>(count);
  if (count < HeightJetUnknowns + ResidualNeighbors || !(scale > 0.0) || !std::isfinite(scale))
  {
    return fit;
  }
  const double inverseScale = 1.0 / scale;
  JetSums sums;
  for (std::size_t i = 0; i < count; ++i)
  {
    const Local p = InFrame(dx[i], dy[i], dz[i], frame, inverseScale);
    sums.Add(Row(p.U, p.V), p.H);
  }
  const small::Solution<HeightJetUnknowns> solution = small::Solve(sums.Normal, sums.Right, true);
  if (!solution.Valid)
  {
    return fit;
  }
  const JetVector& x = solution.X;
  CurvaturesOfGraph(frame,
    x[4],
    x[5],
    x[0] * inverseScale,
    x[1] * inverseScale,
    x[2] * inverseScale,
    fit.Curvature);
  if (!fit.Curvature.Valid)
  {
    return fit;
  }
  // The residual row by row: from the sums it would be the difference of
  // two nearly equal numbers where the positions have no noise.
  double residual = 0.0;
  for (std::size_t i = 0; i < count; ++i)
  {
    const Local p = InFrame(dx[i], dy[i], dz[i], frame, inverseScale);
    const double r = p.H - Row(p.U, p.V).dot(x);
    residual += r * r;
  }
  const double variance = residual / static_cast<double>(count - HeightJetUnknowns);
  const Eigen::Matrix3d covariance = solution.Inverse.topRows<3>() * variance;
  fit.StandardError = SecondOrderStandardError(covariance, x[0], x[1], x[2]) * inverseScale;
  return fit;
}

} // namespace pcurv
