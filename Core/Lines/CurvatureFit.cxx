#include "Lines/CurvatureFit.h"

#include "Neighbors/PointGrid.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace pcurv
{
namespace
{
using Column = Eigen::Matrix<double, CurvatureFitTerms, 1>;
using Matrix = Eigen::Matrix<double, CurvatureFitTerms, CurvatureFitTerms>;

LineVector Load(const double* a, std::int64_t i)
{
  return { { a[3 * i], a[3 * i + 1], a[3 * i + 2] } };
}
double Dot(const LineVector& a, const LineVector& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
LineVector Combine(double a, const LineVector& u, double b, const LineVector& v)
{
  return { { a * u[0] + b * v[0], a * u[1] + b * v[1], a * u[2] + b * v[2] } };
}
bool Normalize(LineVector& v)
{
  const double length = std::sqrt(Dot(v, v));
  if (!(length > 1e-12) || !std::isfinite(length))
  {
    return false;
  }
  v = Combine(1.0 / length, v, 0.0, v);
  return true;
}

/// The derivatives of the terms 1, u, v, u^2, uv, v^2, u^3, u^2 v, u v^2,
/// v^3: first along u and v, second uu, uv, vv.
struct TermDerivatives
{
  Column U, V, UU, UV, VV;
};

TermDerivatives DerivativesOfTerms(double u, double v)
{
  TermDerivatives d;
  d.U << 0.0, 1.0, 0.0, 2.0 * u, v, 0.0, 3.0 * u * u, 2.0 * u * v, v * v, 0.0;
  d.V << 0.0, 0.0, 1.0, 0.0, u, 2.0 * v, 0.0, u * u, 2.0 * u * v, 3.0 * v * v;
  d.UU << 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 6.0 * u, 2.0 * v, 0.0, 0.0;
  d.UV << 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 2.0 * u, 2.0 * v, 0.0;
  d.VV << 0.0, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 2.0 * u, 6.0 * v;
  return d;
}

/// r^T A r for the symmetric A stored as its packed lower triangle.
double QuadraticForm(const std::array<double, CurvatureFitPacked>& a, const Column& r)
{
  double sum = 0.0;
  std::size_t packed = 0;
  for (int row = 0; row < CurvatureFitTerms; ++row)
  {
    double offDiagonal = 0.0;
    for (int column = 0; column < row; ++column)
    {
      offDiagonal += a[packed++] * r[column];
    }
    sum += r[row] * (2.0 * offDiagonal + a[packed++] * r[row]);
  }
  return sum;
}

/// The packed lower triangle of (L L^T)^-1 = L^-T L^-1, from the lower
/// triangular factor L.
std::array<double, CurvatureFitPacked> InverseFromFactor(const Matrix& lower)
{
  Matrix inverseFactor = Matrix::Zero(); // L^-1, lower triangular
  for (int column = 0; column < CurvatureFitTerms; ++column)
  {
    inverseFactor(column, column) = 1.0 / lower(column, column);
    for (int row = column + 1; row < CurvatureFitTerms; ++row)
    {
      double sum = 0.0;
      for (int k = column; k < row; ++k)
      {
        sum += lower(row, k) * inverseFactor(k, column);
      }
      inverseFactor(row, column) = -sum / lower(row, row);
    }
  }
  std::array<double, CurvatureFitPacked> inverse;
  std::size_t packed = 0;
  for (int row = 0; row < CurvatureFitTerms; ++row)
  {
    for (int column = 0; column <= row; ++column)
    {
      double sum = 0.0;
      for (int k = row; k < CurvatureFitTerms; ++k)
      {
        sum += inverseFactor(k, row) * inverseFactor(k, column);
      }
      inverse[packed++] = sum;
    }
  }
  return inverse;
}

/// Whether the samples determine every term: the condition number of the
/// normal matrix is at least the squared ratio of the factor's largest to
/// its smallest pivot (the fit's terms are scaled by the radius, so a
/// tiny ratio means the samples leave a term free, not a unit problem).
bool WellConditioned(const Eigen::LLT<Matrix>& cholesky)
{
  const auto pivots = cholesky.matrixLLT().diagonal();
  const double ratio = pivots.minCoeff() / pivots.maxCoeff();
  return ratio * ratio > 1e-10;
}

/// The coefficients of both columns, by forward and back substitution with
/// the Cholesky factor L of the normal matrix (L L^T c = right).
Eigen::Matrix<double, CurvatureFitTerms, 2> SolveWithFactor(const Matrix& lower,
  const Eigen::Matrix<double, CurvatureFitTerms, 2>& right)
{
  Eigen::Matrix<double, CurvatureFitTerms, 2> c = right;
  for (int which = 0; which < 2; ++which)
  {
    for (int row = 0; row < CurvatureFitTerms; ++row)
    {
      for (int column = 0; column < row; ++column)
      {
        c(row, which) -= lower(row, column) * c(column, which);
      }
      c(row, which) /= lower(row, row);
    }
    for (int row = CurvatureFitTerms - 1; row >= 0; --row)
    {
      for (int column = row + 1; column < CurvatureFitTerms; ++column)
      {
        c(row, which) -= lower(column, row) * c(column, which);
      }
      c(row, which) /= lower(row, row);
    }
  }
  return c;
}

/// The powers of u and v of each term.
constexpr int PowerOfU[CurvatureFitTerms] = { 0, 1, 0, 2, 1, 0, 3, 2, 1, 0 };
constexpr int PowerOfV[CurvatureFitTerms] = { 0, 0, 1, 0, 1, 2, 0, 1, 2, 3 };
constexpr int Moments = 7; // powers 0 to 6 of products of two terms

/// The normal equations of the fit. Each entry of the normal matrix is a
/// moment, the sum of u^a v^b over the samples with a + b <= 6: 28 sums
/// per sample rather than the 55 products of a rank update.
struct NormalEquations
{
  double Moment[Moments][Moments] = {};
  Eigen::Matrix<double, CurvatureFitTerms, 2> Right =
    Eigen::Matrix<double, CurvatureFitTerms, 2>::Zero();
  double Squares[2] = { 0.0, 0.0 };

  Matrix NormalMatrix() const
  {
    Matrix normal;
    for (int k = 0; k < CurvatureFitTerms; ++k)
    {
      for (int l = 0; l < CurvatureFitTerms; ++l)
      {
        normal(k, l) = this->Moment[PowerOfU[k] + PowerOfU[l]][PowerOfV[k] + PowerOfV[l]];
      }
    }
    return normal;
  }
};

NormalEquations Accumulate(const LineInput& input,
  const std::vector<CurvatureFitScratch::Sample>& samples)
{
  NormalEquations e;
  for (const CurvatureFitScratch::Sample& s : samples)
  {
    double u[Moments], v[Moments];
    u[0] = v[0] = 1.0;
    for (int p = 1; p < Moments; ++p)
    {
      u[p] = u[p - 1] * s.U;
      v[p] = v[p - 1] * s.V;
    }
    for (int a = 0; a < Moments; ++a)
    {
      for (int b = 0; a + b < Moments; ++b)
      {
        e.Moment[a][b] += u[a] * v[b];
      }
    }
    const double kMax = input.MaximumCurvature[s.Id], kMin = input.MinimumCurvature[s.Id];
    for (int k = 0; k < CurvatureFitTerms; ++k)
    {
      const double term = u[PowerOfU[k]] * v[PowerOfV[k]];
      e.Right(k, 0) += kMax * term;
      e.Right(k, 1) += kMin * term;
    }
    e.Squares[0] += kMax * kMax;
    e.Squares[1] += kMin * kMin;
  }
  return e;
}

/// The derivatives of column `which` of the fit along `direction`, at the
/// point whose terms' derivatives are `d`.
DirectionalDerivatives DerivativesAlong(const CurvatureFit& fit,
  int which,
  const TermDerivatives& d,
  const LineVector& direction)
{
  DirectionalDerivatives out;
  double a = Dot(direction, fit.Frame.T1), b = Dot(direction, fit.Frame.T2);
  const double length = std::sqrt(a * a + b * b);
  if (!(length > 1e-6))
  {
    // A direction along the fit's normal: nothing to say along it.
    out.SlopeVariance = out.BendVariance = HUGE_VAL;
    return out;
  }
  a /= length;
  b /= length;
  const double r = fit.Radius;
  const auto c = fit.Coefficients.col(which);
  const Column slopeRow = a * d.U + b * d.V;
  const Column bendRow = a * a * d.UU + 2.0 * a * b * d.UV + b * b * d.VV;
  out.Slope = slopeRow.dot(c) / r;
  out.Bend = bendRow.dot(c) / (r * r);
  const double gradientU = (a * d.UU + b * d.UV).dot(c) / (r * r);
  const double gradientV = (a * d.UV + b * d.VV).dot(c) / (r * r);
  out.SlopeGradient = Combine(gradientU, fit.Frame.T1, gradientV, fit.Frame.T2);
  out.SlopeVariance = QuadraticForm(fit.Inverse, slopeRow) / (r * r);
  out.BendVariance = QuadraticForm(fit.Inverse, bendRow) / (r * r * r * r);
  return out;
}

/// Gathers the fit's samples: the neighbors within `radius`, thinned to
/// every stride-th in the grid's fixed order where there are more than the
/// budget (a noisy cloud's neighborhoods hold thousands), which keeps them
/// spread over the whole disk. The order depends only on the grid's
/// lattice and the points, not on the input's order.
void GatherSamples(const LineInput& input,
  const LineSettings& settings,
  const PointGrid& grid,
  std::int64_t point,
  double radius,
  const LineFrame& frame,
  ShellPoints& shell,
  CurvatureFitScratch& scratch)
{
  const LineVector x = Load(input.Points, point);
  const std::size_t found = grid.GatherShell(x.data(), 0.0, radius, shell);
  const std::size_t budget = static_cast<std::size_t>(settings.FitNeighbors);
  const std::size_t stride = 1 + found / budget;
  scratch.Samples.clear();
  for (std::size_t k = 0; k < found; k += stride)
  {
    const std::int64_t id = shell.Ids[k];
    if (UsableForLines(input, id))
    {
      const LineVector d{ { shell.Dx[k], shell.Dy[k], shell.Dz[k] } };
      scratch.Samples.push_back({ Dot(d, frame.T1) / radius, Dot(d, frame.T2) / radius, id });
    }
  }
}

} // namespace

bool UsableForLines(const LineInput& input, std::int64_t point)
{
  return (!input.Valid || input.Valid[point]) && std::isfinite(input.MaximumCurvature[point]) &&
    std::isfinite(input.MinimumCurvature[point]);
}

bool MakeLineFrame(const LineInput& input, std::int64_t point, LineFrame& frame)
{
  frame.Normal = Load(input.Normals, point);
  if (!Normalize(frame.Normal))
  {
    return false;
  }
  const LineVector d = Load(input.MaximumDirection, point);
  frame.T1 = Combine(1.0, d, -Dot(d, frame.Normal), frame.Normal);
  if (!Normalize(frame.T1))
  {
    return false;
  }
  const LineVector& n = frame.Normal;
  const LineVector& t = frame.T1;
  frame.T2 = {
    { n[1] * t[2] - n[2] * t[1], n[2] * t[0] - n[0] * t[2], n[0] * t[1] - n[1] * t[0] }
  };
  return true;
}

bool FitCurvatures(const LineInput& input,
  const LineSettings& settings,
  const PointGrid& grid,
  std::int64_t point,
  double radius,
  const LineFrame& frame,
  ShellPoints& shell,
  CurvatureFitScratch& scratch,
  CurvatureFit& fit)
{
  GatherSamples(input, settings, grid, point, radius, frame, shell, scratch);
  const int count = static_cast<int>(scratch.Samples.size());
  if (count < 2 * CurvatureFitTerms)
  {
    return false;
  }
  const NormalEquations equations = Accumulate(input, scratch.Samples);
  const Eigen::LLT<Matrix> cholesky(equations.NormalMatrix());
  if (cholesky.info() != Eigen::Success || !WellConditioned(cholesky))
  {
    return false;
  }
  fit.Frame = frame;
  fit.Center = Load(input.Points, point);
  fit.Radius = radius;
  const Matrix lower = cholesky.matrixL();
  fit.Inverse = InverseFromFactor(lower);
  fit.Coefficients = SolveWithFactor(lower, equations.Right);
  const auto& right = equations.Right;
  const double* squares = equations.Squares;
  for (int which = 0; which < 2; ++which)
  {
    fit.Residual[which] =
      std::max(0.0, squares[which] - fit.Coefficients.col(which).dot(right.col(which))) /
      (count - CurvatureFitTerms);
  }
  return true;
}

void EvaluateAlongDirections(const CurvatureFit& fit,
  const double x[3],
  const LineFrame& frame,
  DirectionalDerivatives out[2])
{
  const LineVector offset{ { x[0] - fit.Center[0], x[1] - fit.Center[1], x[2] - fit.Center[2] } };
  const double r = fit.Radius;
  const TermDerivatives d =
    DerivativesOfTerms(Dot(offset, fit.Frame.T1) / r, Dot(offset, fit.Frame.T2) / r);
  for (int which = 0; which < 2; ++which)
  {
    out[which] = DerivativesAlong(fit, which, d, which == 0 ? frame.T1 : frame.T2);
  }
}

} // namespace pcurv
