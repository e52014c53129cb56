#include "Fits/HeightJet.h"

#include "Common/ScaledCovariance.h"
#include "Common/SmallLeastSquares.h"

#include <cmath>

namespace pcurv
{
namespace
{
using JetVector = small::Vector<HeightJetUnknowns>;
using JetMatrix = small::Matrix<HeightJetUnknowns>;

/// Fewer neighbors than the unknowns and two leave no residual to weigh
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

/// Powers 0..Degree of a value.
template<int Degree>
struct Powers
{
  double Of[Degree + 1];
  explicit Powers(double x)
  {
    this->Of[0] = 1.0;
#pragma GCC unroll 8
    for (int k = 1; k <= Degree; ++k)
    {
      this->Of[k] = this->Of[k - 1] * x;
    }
  }
};

/// The jet's height at (u, v) for unknowns x.
double JetHeight(const JetVector& x, double u, double v)
{
  const Powers<4> pu(u), pv(v);
  double height = 0.0;
#pragma GCC unroll 15
  for (int j = 0; j < HeightJetUnknowns; ++j)
  {
    height += x[j] * (Monomials[j].Coefficient * pu.Of[Monomials[j].U] * pv.Of[Monomials[j].V]);
  }
  return height;
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

/// The index of u^a v^b among the monomials of degree at most `degree`,
/// by increasing a, then b.
constexpr int TriangularIndex(int degree, int a, int b)
{
  return a * (2 * degree + 3 - a) / 2 + b;
}

/// The normal equations' sums as moments: every entry of the matrix is a
/// sum of u^a v^b with a + b <= 8 (45 of them, against the matrix's 120),
/// every entry of the right side one of h u^a v^b with a + b <= 4. Kept
/// flat and added in fully unrolled loops: the sums of one neighbor are
/// independent of each other.
struct JetMoments
{
  static constexpr int Degree = 8;
  static constexpr int HeightDegree = 4;
  double Powers[TriangularIndex(Degree, Degree, 0) + 1] = {};
  double Heights[TriangularIndex(HeightDegree, HeightDegree, 0) + 1] = {};

  void Add(double u, double v, double h)
  {
    const pcurv::Powers<Degree> pu(u), pv(v);
#pragma GCC unroll 9
    for (int a = 0; a <= Degree; ++a)
    {
#pragma GCC unroll 9
      for (int b = 0; b <= Degree - a; ++b)
      {
        this->Powers[TriangularIndex(Degree, a, b)] += pu.Of[a] * pv.Of[b];
      }
    }
#pragma GCC unroll 5
    for (int a = 0; a <= HeightDegree; ++a)
    {
      const double hu = h * pu.Of[a];
#pragma GCC unroll 5
      for (int b = 0; b <= HeightDegree - a; ++b)
      {
        this->Heights[TriangularIndex(HeightDegree, a, b)] += hu * pv.Of[b];
      }
    }
  }

  double Power(int a, int b) const
  {
    return this->Powers[TriangularIndex(Degree, a, b)];
  }

  JetMatrix Normal() const
  {
    JetMatrix normal;
#pragma GCC unroll 15
    for (int i = 0; i < HeightJetUnknowns; ++i)
    {
#pragma GCC unroll 15
      for (int j = 0; j < HeightJetUnknowns; ++j)
      {
        const Monomial &p = Monomials[i], &q = Monomials[j];
        normal(i, j) = p.Coefficient * q.Coefficient * this->Power(p.U + q.U, p.V + q.V);
      }
    }
    return normal;
  }

  JetVector Right() const
  {
    JetVector right;
#pragma GCC unroll 15
    for (int i = 0; i < HeightJetUnknowns; ++i)
    {
      right[i] = Monomials[i].Coefficient *
        this->Heights[TriangularIndex(HeightDegree, Monomials[i].U, Monomials[i].V)];
    }
    return right;
  }
};

/// The moments of the offsets in the frame, divided by the scale.
void AddMoments(const double* dx,
  const double* dy,
  const double* dz,
  std::size_t count,
  const TangentFrame& frame,
  double inverseScale,
  JetMoments& moments)
{
  for (std::size_t i = 0; i < count; ++i)
  {
    const Local p = InFrame(dx[i], dy[i], dz[i], frame, inverseScale);
    moments.Add(p.U, p.V, p.H);
  }
}

/// The standard error of the principal curvatures mean +/- amplitude (in
/// units of the scale) from the covariance of the second derivatives
/// (h_uu, h_uv, h_vv): that of the mean, the half difference and h_uv.
double SecondOrderStandardError(const Eigen::Matrix3d& covariance,
  double huu,
  double huv,
  double hvv)
{
  Eigen::Matrix3d toMeanAndHalf;
  toMeanAndHalf << 0.5, 0.0, 0.5, 0.5, 0.0, -0.5, 0.0, 1.0, 0.0;
  return CurvatureStandardError(
    toMeanAndHalf * covariance * toMeanAndHalf.transpose(), 0.5 * (huu - hvv), huv);
}

/// Principal curvatures (output sign) and directions of the graph of h over
/// the frame's plane at the origin, from its slopes and second derivatives
/// (1/length): the eigenproblem of the second fundamental form II against
/// the first, I, exact for any slope. With I = L L^T (Cholesky) it is that
/// of the symmetric C = L^-1 II L^-T, whose eigenvalues are its mean
/// diagonal plus or minus the hypotenuse of its half difference and
/// off-diagonal entry (no square root of a difference, so umbilics keep
/// their precision), and whose eigenvectors y give the problem's as
/// L^-T y.
void CurvaturesOfGraph(const TangentFrame& frame,
  double hu,
  double hv,
  double huu,
  double huv,
  double hvv,
  PointCurvature& out)
{
  const double w = std::sqrt(1.0 + hu * hu + hv * hv);
  const double s11 = huu / w, s12 = huv / w, s22 = hvv / w;
  // L^-1 = [m11 0; m21 m22].
  const double l11 = std::sqrt(1.0 + hu * hu);
  const double l21 = hu * hv / l11;
  const double l22 = std::sqrt(1.0 + hv * hv - l21 * l21);
  const double m11 = 1.0 / l11, m22 = 1.0 / l22, m21 = -l21 * m11 * m22;
  const double c11 = m11 * m11 * s11;
  const double c12 = m11 * (m21 * s11 + m22 * s12);
  const double c22 = m21 * m21 * s11 + 2.0 * m21 * m22 * s12 + m22 * m22 * s22;
  const double mean = 0.5 * (c11 + c22), half = 0.5 * (c11 - c22);
  const double amplitude = std::hypot(half, c12);
  // The eigenvector of the larger eigenvalue, in the form that does not
  // cancel; any vector at an umbilic.
  double y0 = 1.0, y1 = 0.0;
  if (amplitude > 0.0)
  {
    if (half >= 0.0)
    {
      y0 = half + amplitude;
      y1 = c12;
    }
    else
    {
      y0 = c12;
      y1 = amplitude - half;
    }
  }
  const Eigen::Vector3d n(frame.Normal.data()), v0(frame.V0.data()), w0(frame.W0.data());
  const Eigen::Vector3d alongU = v0 + hu * n, alongV = w0 + hv * n;
  // The tangent direction of C's eigenvector (a, b): L^-T (a, b) along the
  // graph's coordinate tangents.
  const auto direction = [&](double a, double b)
  {
    const Eigen::Vector3d t = ((m11 * a + m21 * b) * alongU + (m22 * b) * alongV).normalized();
    return Vector3{ { t[0], t[1], t[2] } };
  };
  // Output sign: a surface bending away from its normal (a sphere with
  // outward normals) has positive curvature, and the height's second
  // derivative is then negative.
  out.MaximumCurvature = -(mean - amplitude);
  out.MinimumCurvature = -(mean + amplitude);
  out.MinimumDirection = direction(y0, y1);
  out.MaximumDirection = direction(-y1, y0);
  const Eigen::Vector3d fitted = (n - hu * v0 - hv * w0).normalized();
  out.FittedNormal = Vector3{ { fitted[0], fitted[1], fitted[2] } };
  out.Valid = std::isfinite(out.MaximumCurvature) && std::isfinite(out.MinimumCurvature) &&
    fitted.allFinite() && std::isfinite(out.MinimumDirection[0]) &&
    std::isfinite(out.MaximumDirection[0]);
}

/// Steps of inverse iteration from the given normal: each takes the other
/// eigenvectors' parts down by the ratio of the smallest eigenvalue to
/// theirs, which the heights' small spread across a surface's
/// neighborhood makes small.
constexpr int PlaneIterations = 3;

} // namespace

Vector3 NeighborhoodPlaneNormal(const double* dx,
  const double* dy,
  const double* dz,
  std::size_t count,
  double scale,
  const Vector3& side)
{
  if (count < 3 || !(scale > 0.0) || !std::isfinite(scale))
  {
    return side;
  }
  const Eigen::Matrix3d covariance = ScaledCovariance(dx, dy, dz, count, 1.0 / scale);
  // Inverse iteration through the adjugate (the inverse times the
  // determinant; for a symmetric matrix its rows are cross products of the
  // columns): no division, and where the points lie in a plane (the
  // smallest eigenvalue 0) it maps everything onto that plane's normal.
  const Eigen::Vector3d c0 = covariance.col(0), c1 = covariance.col(1), c2 = covariance.col(2);
  Eigen::Matrix3d adjugate;
  adjugate.row(0) = c1.cross(c2);
  adjugate.row(1) = c2.cross(c0);
  adjugate.row(2) = c0.cross(c1);
  Eigen::Vector3d normal(side[0], side[1], side[2]);
  for (int step = 0; step < PlaneIterations; ++step)
  {
    const Eigen::Vector3d next = adjugate * normal;
    const double length = next.norm();
    if (!(length > 0.0) || !std::isfinite(length))
    {
      return side;
    }
    normal = next / length;
  }
  if (normal.dot(Eigen::Vector3d(side[0], side[1], side[2])) < 0.0)
  {
    normal = -normal;
  }
  return Vector3{ { normal[0], normal[1], normal[2] } };
}

HeightJetFit FitHeightJet(const double* dx,
  const double* dy,
  const double* dz,
  std::size_t count,
  const TangentFrame& frame,
  double scale,
  double heightVarianceFloor)
{
  HeightJetFit fit;
  fit.Curvature.NeighborCount = static_cast<int>(count);
  if (count < HeightJetUnknowns + ResidualNeighbors || !(scale > 0.0) || !std::isfinite(scale))
  {
    return fit;
  }
  const double inverseScale = 1.0 / scale;
  JetMoments moments;
  AddMoments(dx, dy, dz, count, frame, inverseScale, moments);
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
    const double r = p.H - JetHeight(x, p.U, p.V);
    residual += r * r;
  }
  const double variance = std::max(residual / static_cast<double>(count - HeightJetUnknowns),
    heightVarianceFloor * inverseScale * inverseScale);
  const Eigen::Vector3d last = unscale.tail<3>();
  const Eigen::Matrix3d covariance =
    last.asDiagonal() * factor.TrailingInverse<3>() * last.asDiagonal() * variance;
  fit.StandardError = SecondOrderStandardError(covariance, huu, huv, hvv) * inverseScale;
  return fit;
}

} // namespace pcurv
