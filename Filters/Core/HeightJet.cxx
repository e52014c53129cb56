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

/// The jet's unknowns as monomials c u^a v^b: the height, the slopes, the
/// four cubic and five quartic monomials, and last the second derivatives
/// (their monomials u^2/2, uv, v^2/2 have them as coefficients), whose
/// covariance is then the inverse's trailing block.
struct Monomial
{
  double Coefficient;
  int U, V;
};
constexpr Monomial Monomials[HeightJetUnknowns] = { { 1.0, 0, 0 },
  { 1.0, 1, 0 },
  { 1.0, 0, 1 },
  { 1.0, 3, 0 },
  { 1.0, 2, 1 },
  { 1.0, 1, 2 },
  { 1.0, 0, 3 },
  { 1.0, 4, 0 },
  { 1.0, 3, 1 },
  { 1.0, 2, 2 },
  { 1.0, 1, 3 },
  { 1.0, 0, 4 },
  { 0.5, 2, 0 },
  { 1.0, 1, 1 },
  { 0.5, 0, 2 } };
constexpr int SecondDerivatives = HeightJetUnknowns - 3;
constexpr int Slopes = 1;

/// The jet's row at (u, v).
JetVector Row(double u, double v)
{
  double pu[5], pv[5];
  pu[0] = pv[0] = 1.0;
  for (int k = 1; k < 5; ++k)
  {
    pu[k] = pu[k - 1] * u;
    pv[k] = pv[k - 1] * v;
  }
  JetVector row;
  for (int j = 0; j < HeightJetUnknowns; ++j)
  {
    row[j] = Monomials[j].Coefficient * pu[Monomials[j].U] * pv[Monomials[j].V];
  }
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

/// The normal equations' sums as moments: every entry of the matrix is a
/// sum of u^a v^b with a + b <= 8 (45 of them, against the matrix's 120),
/// every entry of the right side one of h u^a v^b with a + b <= 4.
struct JetMoments
{
  static constexpr int Degree = 8;
  double Powers[Degree + 1][Degree + 1] = {};
  double Heights[5][5] = {};

  void Add(double u, double v, double h)
  {
    double pu[Degree + 1], pv[Degree + 1];
    pu[0] = pv[0] = 1.0;
    for (int k = 1; k <= Degree; ++k)
    {
      pu[k] = pu[k - 1] * u;
      pv[k] = pv[k - 1] * v;
    }
    for (int a = 0; a <= Degree; ++a)
    {
      for (int b = 0; a + b <= Degree; ++b)
      {
        this->Powers[a][b] += pu[a] * pv[b];
      }
    }
    for (int a = 0; a <= 4; ++a)
    {
      for (int b = 0; a + b <= 4; ++b)
      {
        this->Heights[a][b] += h * pu[a] * pv[b];
      }
    }
  }

  JetMatrix Normal() const
  {
    JetMatrix normal;
    for (int i = 0; i < HeightJetUnknowns; ++i)
    {
      for (int j = 0; j < HeightJetUnknowns; ++j)
      {
        const Monomial &p = Monomials[i], &q = Monomials[j];
        normal(i, j) = p.Coefficient * q.Coefficient * this->Powers[p.U + q.U][p.V + q.V];
      }
    }
    return normal;
  }

  JetVector Right() const
  {
    JetVector right;
    for (int i = 0; i < HeightJetUnknowns; ++i)
    {
      right[i] = Monomials[i].Coefficient * this->Heights[Monomials[i].U][Monomials[i].V];
    }
    return right;
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
  JetMoments moments;
  for (std::size_t i = 0; i < count; ++i)
  {
    const Local p = InFrame(dx[i], dy[i], dz[i], frame, inverseScale);
    moments.Add(p.U, p.V, p.H);
  }
  // Solved on a unit diagonal (SmallLeastSquares.h): the monomials' scales
  // (up to the fourth power of the offsets) neither hide a singular
  // system nor fake one.
  const JetMatrix normal = moments.Normal();
  const JetVector diagonal = normal.diagonal();
  if (!(diagonal.minCoeff() > 0.0) || !diagonal.allFinite())
  {
    return fit;
  }
  const JetVector unscale = diagonal.cwiseSqrt().cwiseInverse();
  small::SmallLdlt<HeightJetUnknowns> factor;
  if (!factor.Factor(unscale.asDiagonal() * normal * unscale.asDiagonal(), 1e-12))
  {
    return fit;
  }
  const JetVector x = unscale.cwiseProduct(factor.Solve(unscale.cwiseProduct(moments.Right())));
  if (!x.allFinite())
  {
    return fit;
  }
  const double huu = x[SecondDerivatives], huv = x[SecondDerivatives + 1],
               hvv = x[SecondDerivatives + 2];
  CurvaturesOfGraph(frame,
    x[Slopes],
    x[Slopes + 1],
    huu * inverseScale,
    huv * inverseScale,
    hvv * inverseScale,
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
  const Eigen::Vector3d last = unscale.tail<3>();
  const Eigen::Matrix3d covariance =
    last.asDiagonal() * factor.TrailingInverse<3>() * last.asDiagonal() * variance;
  fit.StandardError = SecondOrderStandardError(covariance, huu, huv, hvv) * inverseScale;
  return fit;
}

} // namespace pcurv
