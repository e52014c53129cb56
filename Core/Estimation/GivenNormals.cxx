#include "Estimation/GivenNormals.h"

#include "Cloud/CloudPoints.h"
#include "Cloud/CloudStatistics.h"
#include "Cloud/Collectives.h"
#include "Cloud/Halo.h"
#include "Fits/FitResults.h"
#include "Neighbors/PointGrid.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace pcurv
{
namespace
{
/// The first radius holds this many neighbors (the automatic scale's).
constexpr int BaseCount = 16;
/// Radii base 2^(i/2), i < Levels: up to 8 first radii, about 1000
/// neighbors, where a plane of the positions is precise even under noise
/// of about the spacing.
constexpr int Levels = 7;
/// Lepski's tolerance, in standard errors (as the scales' elsewhere).
constexpr double AgreementTolerance = 2.0;
/// A tilt whose square exceeds this many times its error's is counted as
/// the normal's own: ln 4, the median of that ratio for normals as precise
/// as the positions' own tilt (the ratio then about exponential with mean
/// 2), a quarter of the points being beyond it for exact normals (mean 1).
/// Where most points are, the given normals are less precise than a
/// normal of the positions, and estimated ones serve the fit better.
const double TiltRatio = std::log(4.0);
/// Fewer neighbors determine the cubic's ten unknowns poorly.
constexpr std::size_t FewestNeighbors = 20;
/// Fewer tested points decide nothing: the given normals are kept.
constexpr std::int64_t FewestTested = 16;
/// The sample's size (the spacing sample's stride is chosen for it).
constexpr std::int64_t SampleSize = 512;

constexpr int Unknowns = 10;
using Vector = Eigen::Matrix<double, Unknowns, 1>;
using Matrix = Eigen::Matrix<double, Unknowns, Unknowns>;

/// The tilt of a given normal against the positions: the slopes at the
/// point of a cubic over its tangent plane, and their standard error.
struct Tilt
{
  double U = 0.0;
  double V = 0.0;
  double Error = std::numeric_limits<double>::infinity();
};

/// The cubic h = a + b u + c v + (quadratic and cubic terms) over
/// `frame`, fitted to the shell's points within `radius` (offsets in units
/// of it, the point itself left out: its height is zero by definition):
/// its slopes (b, c), and their error. The surface's even terms do not
/// move the slopes on a neighborhood that surrounds the point, and its
/// cubic ones are unknowns, so they do not pass for a tilt. The error holds
/// the slopes' standard error (from the heights' residual variance) and
/// the tilt that the point's own displacement along the surface gives an
/// exact normal (the noise variance times the squared curvatures), as the
/// automatic scale's gate counts it. False where the neighbors do not
/// determine the cubic.
bool FitTilt(const ShellPoints& shell,
  const std::vector<double>& squared,
  double radius,
  const TangentFrame& frame,
  Tilt& tilt)
{
  Matrix normal = Matrix::Zero();
  Vector right = Vector::Zero();
  double heights = 0.0;
  std::size_t count = 0;
  const double inverse = 1.0 / radius;
  const double limit = radius * radius;
  for (std::size_t i = 0; i < shell.Count; ++i)
  {
    if (!(squared[i] > 0.0) || !(squared[i] < limit))
    {
      continue;
    }
    const double d[3] = { shell.Dx[i] * inverse, shell.Dy[i] * inverse, shell.Dz[i] * inverse };
    const auto along = [&d](const Vector3& axis)
    { return d[0] * axis[0] + d[1] * axis[1] + d[2] * axis[2]; };
    const double h = along(frame.Normal), u = along(frame.V0), v = along(frame.W0);
    Vector row;
    row << 1.0, u, v, u * u, u * v, v * v, u * u * u, u * u * v, u * v * v, v * v * v;
    normal.noalias() += row * row.transpose();
    right += h * row;
    heights += h * h;
    ++count;
  }
  if (count < FewestNeighbors)
  {
    return false;
  }
  const Eigen::LDLT<Matrix> factors(normal);
  const Vector pivots = factors.vectorD();
  if (factors.info() != Eigen::Success || !(pivots.minCoeff() > 1e-12 * pivots.maxCoeff()))
  {
    return false;
  }
  const Vector solution = factors.solve(right);
  const double noise =
    std::max(0.0, heights - solution.dot(right)) / static_cast<double>(count - Unknowns);
  const Matrix covariance = factors.solve(Matrix::Identity());
  // The squared curvatures, in units of the radius: the Hessian's trace
  // of its square.
  const double curvatures = 4.0 * solution[3] * solution[3] + 2.0 * solution[4] * solution[4] +
    4.0 * solution[5] * solution[5];
  tilt.U = solution[1];
  tilt.V = solution[2];
  tilt.Error = std::sqrt(noise * (covariance(1, 1) + covariance(2, 2) + curvatures));
  return std::isfinite(tilt.U) && std::isfinite(tilt.V) && std::isfinite(tilt.Error);
}

/// Whether the given normal of `point` is tilted against the positions
/// beyond its error (TiltRatio), at the widest radius whose tilt agrees
/// with every smaller one's: 1 it is, 0 it is not, -1 no fit.
int TiltedBeyondNoise(const CloudPoints& cloud,
  const PointGrid& grid,
  std::int64_t point,
  double base,
  ShellPoints& shell,
  std::vector<double>& squared)
{
  const double* n = &cloud.Normals[3 * point];
  if (n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0)
  {
    return -1;
  }
  const TangentFrame frame = MakeTangentFrame({ { n[0], n[1], n[2] } });
  const double largest = base * std::pow(2.0, 0.5 * (Levels - 1));
  grid.GatherShell(&cloud.Coordinates[3 * point], 0.0, largest, shell);
  squared.resize(shell.Count);
  for (std::size_t i = 0; i < shell.Count; ++i)
  {
    squared[i] = shell.Dx[i] * shell.Dx[i] + shell.Dy[i] * shell.Dy[i] + shell.Dz[i] * shell.Dz[i];
  }
  Tilt tilts[Levels];
  int chosen = -1, previous = -1;
  for (int level = 0; level < Levels; ++level)
  {
    Tilt& candidate = tilts[level];
    if (!FitTilt(shell, squared, base * std::pow(2.0, 0.5 * level), frame, candidate))
    {
      if (chosen < 0)
      {
        continue; // too few neighbors yet
      }
      break;
    }
    bool agrees = true;
    for (int smaller = 0; smaller < level; ++smaller)
    {
      const Tilt& other = tilts[smaller];
      agrees = agrees &&
        std::hypot(candidate.U - other.U, candidate.V - other.V) <=
          AgreementTolerance * (candidate.Error + other.Error);
    }
    if (!agrees)
    {
      break;
    }
    previous = chosen;
    chosen = level;
  }
  if (chosen < 0)
  {
    return -1;
  }
  // Where the positions have little noise, the residual is the surface's
  // higher terms, not noise, and the error left out the bias they give the
  // slopes: the tilt's change from the radius before counts as that bias.
  const Tilt& tilt = tilts[chosen];
  const double bias =
    previous < 0 ? 0.0 : std::hypot(tilt.U - tilts[previous].U, tilt.V - tilts[previous].V);
  const double squaredError = tilt.Error * tilt.Error + bias * bias;
  return tilt.U * tilt.U + tilt.V * tilt.V > TiltRatio * squaredError ? 1 : 0;
}
} // namespace

bool GivenNormalsDisagree(const EstimationSettings& settings,
  CloudPoints& cloud,
  const Collectives& processes,
  WorkRunner& runner)
{
  const bool automaticScale = settings.Mode == FitMode::OrientedCircles &&
    settings.Neighborhood == NeighborhoodMode::Automatic && settings.AutomaticThresholds &&
    !settings.DynamicAdjustment;
  if (settings.EstimateNormals || !automaticScale)
  {
    return false;
  }
  const CloudBoxes boxes = MeasureBoxes(cloud, processes);
  const double base = TypicalRadius(cloud, processes, boxes, BaseCount, &runner);
  const double largest = base * std::pow(2.0, 0.5 * (Levels - 1));
  if (!(base > 0.0) || !std::isfinite(largest))
  {
    return false; // the same on every process: the radius is global
  }
  if (processes.IsDistributed())
  {
    ExchangeHalo(cloud, processes, largest);
  }
  std::vector<std::int64_t> counts = { 0, 0 }; // tilted, tested
  {
    PointGrid grid;
    grid.Build(cloud.Coordinates.data(),
      cloud.GetNumberOfPoints(),
      GlobalLattice(boxes, 2.0 * base),
      &runner);
    const std::int64_t stride = std::max<std::int64_t>(1, boxes.BodyCount / SampleSize);
    ShellPoints shell;
    std::vector<double> squared;
    for (std::int64_t i = 0; i < cloud.NumberOfOwnPoints; ++i)
    {
      if (InSpacingSample(
            &cloud.Coordinates[3 * i], boxes.Lower.data(), boxes.Upper.data(), stride))
      {
        const int tilted = TiltedBeyondNoise(cloud, grid, i, base, shell, squared);
        counts[0] += tilted > 0 ? 1 : 0;
        counts[1] += tilted >= 0 ? 1 : 0;
      }
    }
  }
  cloud.DropHalo();
  processes.Sum(counts);
  return counts[1] >= FewestTested && 2 * counts[0] > counts[1];
}

void SignLikeGiven(std::vector<double>& normals, const std::vector<double>& given)
{
  const std::size_t count = std::min(normals.size(), given.size()) / 3;
  for (std::size_t p = 0; p < count; ++p)
  {
    double* n = &normals[3 * p];
    const double* g = &given[3 * p];
    if (n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0)
    {
      std::copy_n(g, 3, n);
    }
    else if (n[0] * g[0] + n[1] * g[1] + n[2] * g[2] < 0.0)
    {
      n[0] = -n[0];
      n[1] = -n[1];
      n[2] = -n[2];
    }
  }
}

} // namespace pcurv
