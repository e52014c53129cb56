/**
 * @file PlaneQuadric.h
 * @brief The quadric over a PCA plane that the normals' scale reads: the
 * heights' noise about it (the plane's own residual also holds the
 * surface's bending) and its slopes at the point; and a PCA normal's
 * standard error. No VTK.
 */
#ifndef PlaneQuadric_h
#define PlaneQuadric_h

#include "Neighbors/PointGrid.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace pcurv
{
namespace normals
{

/// The normal equations of a quadric h = a + b u + c v + d u^2 + e u v +
/// f v^2 fitted to the neighbors' heights h over a plane (axes: its normal
/// and two tangent axes; offsets in units of the radius, the point at
/// their origin), and the sum of the squared heights. The matrix holds
/// only the 15 moments of (u, v) up to the fourth order, so those are what
/// the neighbors' loop sums.
struct QuadricSystem
{
  using Vector6 = Eigen::Matrix<double, 6, 1>;
  using Matrix6 = Eigen::Matrix<double, 6, 6>;
  Matrix6 Normal;
  Vector6 Right;
  double Heights = 0.0;

  QuadricSystem(const NeighborOffsets& offsets, double inverseRadius, const Eigen::Matrix3d& axes)
  {
    // Moments u^i v^j, in the order 1; u v; u^2 uv v^2; u^3 u^2v uv^2 v^3;
    // u^4 u^3v u^2v^2 uv^3 v^4; and the heights' h, hu, hv, hu^2, huv, hv^2.
    double m[15] = {}, r[6] = {};
    double heights = 0.0;
    const Eigen::Vector3d n = axes.col(0) * inverseRadius;
    const Eigen::Vector3d a = axes.col(1) * inverseRadius;
    const Eigen::Vector3d b = axes.col(2) * inverseRadius;
    for (std::size_t i = 0; i < offsets.Count; ++i)
    {
      const double dx = offsets.Dx[i], dy = offsets.Dy[i], dz = offsets.Dz[i];
      const double h = dx * n[0] + dy * n[1] + dz * n[2];
      const double u = dx * a[0] + dy * a[1] + dz * a[2];
      const double v = dx * b[0] + dy * b[1] + dz * b[2];
      const double uu = u * u, uv = u * v, vv = v * v;
      const double terms[15] = { 1.0,
        u,
        v,
        uu,
        uv,
        vv,
        uu * u,
        uu * v,
        u * vv,
        vv * v,
        uu * uu,
        uu * uv,
        uu * vv,
        uv * vv,
        vv * vv };
      for (int k = 0; k < 15; ++k)
      {
        m[k] += terms[k];
      }
      for (int k = 0; k < 6; ++k)
      {
        r[k] += h * terms[k];
      }
      heights += h * h;
    }
    // Entry (i, j) of the matrix is the moment of the product of the
    // basis functions i and j (1, u, v, u^2, uv, v^2).
    constexpr int Moment[6][6] = { { 0, 1, 2, 3, 4, 5 },
      { 1, 3, 4, 6, 7, 8 },
      { 2, 4, 5, 7, 8, 9 },
      { 3, 6, 7, 10, 11, 12 },
      { 4, 7, 8, 11, 12, 13 },
      { 5, 8, 9, 12, 13, 14 } };
    for (int i = 0; i < 6; ++i)
    {
      for (int j = 0; j < 6; ++j)
      {
        this->Normal(i, j) = m[Moment[i][j]];
      }
      this->Right[i] = r[i];
    }
    this->Heights = heights;
  }

  /// The heights' variance about the quadric with coefficients `solution`.
  double ResidualVariance(const Vector6& solution, std::size_t count) const
  {
    return std::max(0.0, this->Heights - solution.dot(this->Right)) /
      static_cast<double>(count - 6);
  }
};

/// How far, in radians, a PCA normal of `count` points is expected to be
/// turned by their noise (first-order perturbation of the eigenvector: a
/// turn towards tangent axis j has variance noise lj / (count (lj -
/// l0)^2), l the covariance's eigenvalues per point, ascending, `noise`
/// the heights' variance about the surface); infinite where the smallest
/// eigenvalue is not separated from the others (the normal undetermined).
inline double NormalStandardError(const Eigen::Vector3d& variances, double noise, std::size_t count)
{
  double variance = 0.0;
  for (int j = 1; j < 3; ++j)
  {
    const double gap = variances[j] - std::max(0.0, variances[0]);
    if (!(gap > 0.0) || !std::isfinite(noise))
    {
      return std::numeric_limits<double>::infinity();
    }
    variance += noise * variances[j] / (gap * gap);
  }
  return std::sqrt(variance / static_cast<double>(count));
}

} // namespace normals
} // namespace pcurv

#endif
