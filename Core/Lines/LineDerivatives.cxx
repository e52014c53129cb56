#include "Lines/LineDerivatives.h"

#include "Common/WorkRunner.h"
#include "Neighbors/PointGrid.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace pcurv
{
namespace
{
using Vec3 = std::array<double, 3>;

Vec3 Load(const double* a, std::int64_t i)
{
  return { { a[3 * i], a[3 * i + 1], a[3 * i + 2] } };
}
double Dot(const Vec3& a, const Vec3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec3 Cross(const Vec3& a, const Vec3& b)
{
  return { { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] } };
}
Vec3 Combine(double a, const Vec3& u, double b, const Vec3& v)
{
  return { { a * u[0] + b * v[0], a * u[1] + b * v[1], a * u[2] + b * v[2] } };
}
bool Normalize(Vec3& v)
{
  const double length = std::sqrt(Dot(v, v));
  if (!(length > 1e-12) || !std::isfinite(length))
  {
    return false;
  }
  v = Combine(1.0 / length, v, 0.0, v);
  return true;
}

bool Usable(const LineInput& input, std::int64_t i)
{
  return (!input.Valid || input.Valid[i]) && std::isfinite(input.MaximumCurvature[i]) &&
    std::isfinite(input.MinimumCurvature[i]);
}

/// The tangent frame of a point: t1 along d_max, t2 = n x t1 (along d_min).
struct Frame
{
  Vec3 Normal, T1, T2;
};

bool MakeFrame(const LineInput& input, std::int64_t i, Frame& frame)
{
  frame.Normal = Load(input.Normals, i);
  if (!Normalize(frame.Normal))
  {
    return false;
  }
  const Vec3 d = Load(input.MaximumDirection, i);
  frame.T1 = Combine(1.0, d, -Dot(d, frame.Normal), frame.Normal);
  if (!Normalize(frame.T1))
  {
    return false;
  }
  frame.T2 = Cross(frame.Normal, frame.T1);
  return true;
}

/// Terms of the fitted polynomial: up to the cubic ones, so that the
/// slope at the point is not biased by the curvature's third derivative
/// (which would move the lines of asymmetric profiles towards their
/// flatter side).
constexpr int Terms = 10;
using Matrix = Eigen::Matrix<double, Terms, Terms>;
using Coefficients = Eigen::Matrix<double, Terms, 2>;
using Column = Eigen::Matrix<double, Terms, 1>;

/// The normal equations of k(u, v) = c0 + c1 u + c2 v + c3 u^2 + c4 uv +
/// c5 v^2 + (cubic terms) over the neighbors, u and v in radii (for
/// conditioning), for both curvatures at once.
struct PolynomialFit
{
  Matrix Normal = Matrix::Zero();
  Coefficients Right = Coefficients::Zero();
  double Squares[2] = { 0.0, 0.0 };
  int Count = 0;

  void Add(double u, double v, double kMax, double kMin)
  {
    Column row;
    row << 1.0, u, v, u * u, u * v, v * v, u * u * u, u * u * v, u * v * v, v * v * v;
    this->Normal.selfadjointView<Eigen::Lower>().rankUpdate(row);
    this->Right.col(0) += kMax * row;
    this->Right.col(1) += kMin * row;
    this->Squares[0] += kMax * kMax;
    this->Squares[1] += kMin * kMin;
    ++this->Count;
  }
};

struct Neighbor
{
  double Squared;
  std::int64_t Id;
  double U, V; ///< tangent coordinates, in radii
  bool operator<(const Neighbor& other) const
  {
    return this->Squared != other.Squared ? this->Squared < other.Squared : this->Id < other.Id;
  }
};

/// The extremality of one curvature from the fit's coefficients c (in
/// radii), `along` = 1 for u (k_max), 2 for v (k_min).
Extremality Extremal(const Column& c, int along, double radius, const Frame& frame)
{
  Extremality x;
  const double r2 = radius * radius;
  x.Slope = c[along] / radius;
  x.Bend = 2.0 * c[along == 1 ? 3 : 5] / r2;
  const double gradU = (along == 1 ? 2.0 * c[3] : c[4]) / r2;
  const double gradV = (along == 1 ? c[4] : 2.0 * c[5]) / r2;
  x.Direction = along == 1 ? frame.T1 : frame.T2;
  // The zero set of e runs across its gradient.
  x.Tangent = Combine(-gradV, frame.T1, gradU, frame.T2);
  if (!Normalize(x.Tangent))
  {
    x.Tangent = along == 1 ? frame.T2 : frame.T1;
  }
  return x;
}

class PointFitter
{
public:
  PointFitter(const LineInput& input,
    const LineSettings& settings,
    const PointGrid& grid,
    PointDerivatives& out)
    : Input(input)
    , Settings(settings)
    , Grid(grid)
    , Out(out)
  {
  }

  void Fit(std::int64_t i)
  {
    const Vec3 x = Load(this->Input.Points, i);
    double radius = this->Input.Radius ? this->Input.Radius[i] : 0.0;
    if (!this->Input.Radius)
    {
      radius = std::sqrt(
        this->Grid.SquaredDistanceToKth(x.data(), this->Settings.RadiusNeighbors, this->Scratch));
    }
    this->Out.Radius[i] = radius;
    radius *= this->Settings.FitRadius;
    Frame frame;
    if (!(radius > 0.0) || !std::isfinite(radius) || !MakeFrame(this->Input, i, frame) ||
      !Usable(this->Input, i))
    {
      this->GraphOf(i, x, radius);
      return;
    }
    this->Neighbors.clear();
    const std::size_t found = this->Grid.GatherShell(x.data(), 0.0, radius, this->Shell);
    for (std::size_t k = 0; k < found; ++k)
    {
      const Vec3 d{ { this->Shell.Dx[k], this->Shell.Dy[k], this->Shell.Dz[k] } };
      this->Neighbors.push_back(
        { Dot(d, d), this->Shell.Ids[k], Dot(d, frame.T1) / radius, Dot(d, frame.T2) / radius });
    }
    // A wide neighborhood (the estimator's on a noisy cloud holds
    // thousands) is thinned to every stride-th neighbor in the grid's fixed
    // order: enough for ten coefficients, at a bounded cost per point.
    const std::size_t budget = static_cast<std::size_t>(this->Settings.FitNeighbors);
    const std::size_t stride = 1 + this->Neighbors.size() / budget;
    PolynomialFit fit;
    for (std::size_t k = 0; k < this->Neighbors.size(); k += stride)
    {
      const Neighbor& q = this->Neighbors[k];
      if (Usable(this->Input, q.Id))
      {
        fit.Add(q.U, q.V, this->Input.MaximumCurvature[q.Id], this->Input.MinimumCurvature[q.Id]);
      }
    }
    this->KeepNearest(i);
    this->Solve(i, fit, radius, frame);
  }

private:
  /// The graph's edges of a point without a fit of its own.
  void GraphOf(std::int64_t i, const Vec3& x, double radius)
  {
    this->Neighbors.clear();
    if (radius > 0.0 && std::isfinite(radius))
    {
      this->Grid.ForEachWithinRadius(x.data(),
        radius,
        [&](const double* q, std::int64_t id)
        {
          const Vec3 d{ { q[0] - x[0], q[1] - x[1], q[2] - x[2] } };
          this->Neighbors.push_back({ Dot(d, d), id, 0.0, 0.0 });
        });
    }
    this->KeepNearest(i);
  }

  void KeepNearest(std::int64_t i)
  {
    const int width = this->Out.GraphWidth;
    const std::size_t wanted = std::min<std::size_t>(this->Neighbors.size(), width + 1);
    std::partial_sort(
      this->Neighbors.begin(), this->Neighbors.begin() + wanted, this->Neighbors.end());
    std::int64_t* row = &this->Out.Graph[i * width];
    int filled = 0;
    for (std::size_t k = 0; k < wanted && filled < width; ++k)
    {
      if (this->Neighbors[k].Id != i)
      {
        row[filled++] = this->Neighbors[k].Id;
      }
    }
    std::fill(row + filled, row + width, -1);
  }

  void Solve(std::int64_t i, const PolynomialFit& fit, double radius, const Frame& frame)
  {
    if (fit.Count < 2 * Terms)
    {
      return;
    }
    const Matrix normal = fit.Normal.selfadjointView<Eigen::Lower>();
    const Eigen::LDLT<Matrix> ldlt(normal);
    if (ldlt.info() != Eigen::Success || !(ldlt.rcond() > 1e-10))
    {
      return;
    }
    const Coefficients c = ldlt.solve(fit.Right);
    const Matrix inverse = ldlt.solve(Matrix::Identity());
    const double given = this->Input.StandardError ? this->Input.StandardError[i] : 0.0;
    const double kMax = this->Input.MaximumCurvature[i], kMin = this->Input.MinimumCurvature[i];
    const double spread = kMax - kMin;
    const double scale = std::max(std::fabs(kMax), std::fabs(kMin));
    // Directions are noise where the curvatures are about equal (umbilics).
    const bool anisotropic = spread > this->Settings.Significance * given &&
      spread > 1e-9 * (std::fabs(kMax) + std::fabs(kMin)) && spread > 0.0;
    for (int which = 0; which < 2; ++which)
    {
      const double residual =
        std::max(0.0, fit.Squares[which] - c.col(which).dot(fit.Right.col(which))) /
        (fit.Count - Terms);
      const double noise = std::max(residual, given * given);
      const int along = which == 0 ? 1 : 2;
      const int bendIndex = which == 0 ? 3 : 5;
      Extremality x = Extremal(c.col(which), along, radius, frame);
      const double bendError =
        2.0 * std::sqrt(noise * inverse(bendIndex, bendIndex)) / (radius * radius);
      x.SlopeError = std::sqrt(noise * inverse(along, along)) / radius;
      x.BendFloor = this->Settings.RelativeBend * spread * scale * scale;
      x.Significant = anisotropic && std::fabs(x.Bend) > this->Settings.Significance * bendError;
      (which == 0 ? this->Out.Maximum : this->Out.Minimum)[i] = x;
    }
    this->Out.Fitted[i] = 1;
  }

  const LineInput& Input;
  const LineSettings& Settings;
  const PointGrid& Grid;
  PointDerivatives& Out;
  std::vector<Neighbor> Neighbors;
  ShellPoints Shell;
  std::vector<double> Scratch;
};

} // namespace

PointDerivatives FitDerivatives(const LineInput& input,
  const LineSettings& settings,
  const PointGrid& grid,
  WorkRunner* runner)
{
  PointDerivatives out;
  const std::size_t n = static_cast<std::size_t>(input.Count);
  out.Maximum.resize(n);
  out.Minimum.resize(n);
  out.Fitted.assign(n, 0);
  out.Radius.assign(n, 0.0);
  out.GraphWidth = std::max(1, settings.GraphNeighbors);
  out.Graph.assign(n * out.GraphWidth, -1);
  RunRanges(runner,
    input.Count,
    2048,
    [&](std::int64_t begin, std::int64_t end)
    {
      PointFitter fitter(input, settings, grid, out);
      // In the grid's order: consecutive points share their neighbors,
      // whose curvatures then stay in cache.
      for (std::int64_t j = begin; j < end; ++j)
      {
        fitter.Fit(grid.GetSortedId(j));
      }
    });
  return out;
}

} // namespace pcurv
