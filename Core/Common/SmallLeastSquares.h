/**
 * @file SmallLeastSquares.h
 * @brief Normal equations of a few unknowns (the oriented circles', a height
 * jet's), solved on a unit diagonal by an unrolled LDL^T. No VTK.
 */
#ifndef SmallLeastSquares_h
#define SmallLeastSquares_h

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace pcurv
{
namespace small
{
template<int N>
using Vector = Eigen::Matrix<double, N, 1>;
template<int N>
using Matrix = Eigen::Matrix<double, N, N>;

/// The unknowns and, where asked for (the covariance of the first three:
/// callers order their unknowns so that these are the curvatures'), the
/// first three columns of the inverse of the normal matrix; invalid when it
/// is singular to working precision.
template<int N>
struct Solution
{
  bool Valid = false;
  Vector<N> X = Vector<N>::Zero();
  Eigen::Matrix<double, N, 3> Inverse = Eigen::Matrix<double, N, 3>::Zero();
};

/// LDL^T of a small symmetric positive definite matrix, without pivoting:
/// on a unit diagonal no reordering is needed for stability, and the
/// fixed size lets the compiler unroll it (Eigen's pivoting LDLT cost most
/// of a fit on small neighborhoods). Fails when a pivot is not above
/// `smallest`: an unknown is then determined by the earlier ones to
/// working precision.
template<int N>
class SmallLdlt
{
public:
  bool Factor(const Matrix<N>& a, double smallest)
  {
    for (int j = 0; j < N; ++j)
    {
      double d = a(j, j);
      for (int k = 0; k < j; ++k)
      {
        d -= this->L[j][k] * this->L[j][k] * this->D[k];
      }
      if (!(d > smallest))
      {
        return false;
      }
      this->D[j] = d;
      for (int i = j + 1; i < N; ++i)
      {
        double v = a(i, j);
        for (int k = 0; k < j; ++k)
        {
          v -= this->L[i][k] * this->L[j][k] * this->D[k];
        }
        this->L[i][j] = v / d;
      }
    }
    return true;
  }

  /// The trailing K x K block of the inverse of the factored matrix: of
  /// L^-T D^-1 L^-1, only the trailing block of L (lower triangular, so
  /// its inverse's trailing block is that block's inverse) reaches it. The
  /// covariance of the last K unknowns, without solving for N columns.
  template<int K>
  Eigen::Matrix<double, K, K> TrailingInverse() const
  {
    static_assert(K <= N, "a block of the matrix");
    // Columns of the inverse of the unit lower triangular trailing block.
    Eigen::Matrix<double, K, K> inverse = Eigen::Matrix<double, K, K>::Identity();
    for (int c = 0; c < K; ++c)
    {
      for (int i = c + 1; i < K; ++i)
      {
        double v = 0.0;
        for (int k = c; k < i; ++k)
        {
          v -= this->L[N - K + i][N - K + k] * inverse(k, c);
        }
        inverse(i, c) = v;
      }
    }
    Eigen::Matrix<double, K, 1> reciprocal;
    for (int i = 0; i < K; ++i)
    {
      reciprocal[i] = 1.0 / this->D[N - K + i];
    }
    return inverse.transpose() * reciprocal.asDiagonal() * inverse;
  }

  Vector<N> Solve(const Vector<N>& right) const
  {
    double column[N][1];
    for (int i = 0; i < N; ++i)
    {
      column[i][0] = right[i];
    }
    this->SolveColumns(column);
    Vector<N> x;
    for (int i = 0; i < N; ++i)
    {
      x[i] = column[i][0];
    }
    return x;
  }

  /// Solves for K right-hand sides at once, x[i][c] the i-th entry of the
  /// c-th: each column takes one solve's operations in its order (the same
  /// bits as alone), the columns side by side keep the processor busy where
  /// one column's substitutions wait for each other.
  template<int K>
  void SolveColumns(double (&x)[N][K]) const
  {
    for (int i = 0; i < N; ++i)
    {
      for (int k = 0; k < i; ++k)
      {
        for (int c = 0; c < K; ++c)
        {
          x[i][c] -= this->L[i][k] * x[k][c];
        }
      }
    }
    for (int i = 0; i < N; ++i)
    {
      for (int c = 0; c < K; ++c)
      {
        x[i][c] /= this->D[i];
      }
    }
    for (int i = N - 1; i >= 0; --i)
    {
      for (int k = i + 1; k < N; ++k)
      {
        for (int c = 0; c < K; ++c)
        {
          x[i][c] -= this->L[k][i] * x[k][c];
        }
      }
    }
  }

private:
  // Factor writes every entry it and Solve read (L below the diagonal).
  double L[N][N];
  double D[N];
};

/// Solves the normal equations, scaled to a unit diagonal first: the
/// unknowns differ in scale by orders of magnitude (curvatures, cubic
/// coefficients, the height), and so do the two kinds of rows once weighted
/// (exact normals fit with no residual, and their weight dwarfs the
/// positions'). A singularity test against the largest diagonal entry
/// would then reject a well-posed system (the height, seen by the positions
/// only, looks negligible beside the normals' unknowns), and the fit would
/// fall back to the positions alone; on the unit diagonal the test asks
/// only whether some unknowns are determined by the others.
template<int N>
Solution<N> Solve(const Matrix<N>& normal, const Vector<N>& right, bool withInverse)
{
  Solution<N> solution;
  const Vector<N> diagonal = normal.diagonal();
  if (!(diagonal.minCoeff() > 0.0) || !diagonal.allFinite())
  {
    return solution;
  }
  const Vector<N> unscale = diagonal.cwiseSqrt().cwiseInverse();
  const Matrix<N> scaled = unscale.asDiagonal() * normal * unscale.asDiagonal();
  SmallLdlt<N> ldlt;
  if (!ldlt.Factor(scaled, 1e-12))
  {
    return solution;
  }
  if (!withInverse)
  {
    solution.X = unscale.cwiseProduct(ldlt.Solve(unscale.cwiseProduct(right)));
  }
  else
  {
    // The unknowns and C, A and B's covariance (three columns of the
    // inverse, not N) in one pass.
    double columns[N][4];
    for (int i = 0; i < N; ++i)
    {
      columns[i][0] = unscale[i] * right[i];
      for (int c = 0; c < 3; ++c)
      {
        columns[i][1 + c] = i == c ? unscale[c] : 0.0;
      }
    }
    ldlt.SolveColumns(columns);
    for (int i = 0; i < N; ++i)
    {
      solution.X[i] = unscale[i] * columns[i][0];
      for (int c = 0; c < 3; ++c)
      {
        solution.Inverse(i, c) = unscale[i] * columns[i][1 + c];
      }
    }
  }
  solution.Valid = solution.X.allFinite() && solution.Inverse.allFinite();
  return solution;
}

} // namespace small

/// The standard error of principal curvatures C +- hypot(A, B) from the
/// covariance of (C, A, B), to first order (the oriented circles' offset
/// and sine amplitudes, a jet's mean and half-difference curvatures).
inline double CurvatureStandardError(const Eigen::Matrix3d& covariance, double c, double s)
{
  const double amplitude = std::hypot(c, s);
  const double amplitudeVariance = amplitude > 0.0
    ? (c * c * covariance(1, 1) + 2.0 * c * s * covariance(1, 2) + s * s * covariance(2, 2)) /
      (amplitude * amplitude)
    : std::max(covariance(1, 1), covariance(2, 2));
  return std::sqrt(std::max(0.0, covariance(0, 0)) + std::max(0.0, amplitudeVariance));
}
} // namespace pcurv

#endif
