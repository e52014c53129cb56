#include "Outliers/RobustSurface.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcurv
{
namespace outliers
{
namespace
{
/// Neighbors whose distance to a fit exceeds this many robust standard
/// deviations are left out of the next one.
constexpr double TrimFactor = 3.0;
/// The median absolute deviation of a Gaussian, in standard deviations.
constexpr double MadToDeviation = 1.4826;
/// Fewest neighbors for a quadratic height (six unknowns); fewer keep the
/// plane.
constexpr std::size_t FewestForHeight = 12;

/// The neighbors' distances to the surface into scratch.Residuals, and
/// their robust standard deviation (scaled median absolute value).
double RobustDeviation(const LocalSurface& surface, FitScratch& scratch)
{
  const std::size_t count = scratch.Nearest.size();
  scratch.Residuals.resize(count);
  scratch.Magnitudes.resize(count);
  for (std::size_t j = 0; j < count; ++j)
  {
    scratch.Residuals[j] = surface.Residual(scratch.Nearest[j].Offset);
    scratch.Magnitudes[j] = std::fabs(scratch.Residuals[j]);
  }
  const auto middle = scratch.Magnitudes.begin() + count / 2;
  std::nth_element(scratch.Magnitudes.begin(), middle, scratch.Magnitudes.end());
  return MadToDeviation * *middle;
}

/// Keeps the neighbors within TrimFactor robust deviations of the surface.
void KeepNearSurface(const LocalSurface& surface, FitScratch& scratch)
{
  // A floor far below any real noise: on an exact plane every distance is
  // rounding.
  const double limit = std::max(TrimFactor * RobustDeviation(surface, scratch), 1e-12);
  for (std::size_t j = 0; j < scratch.Nearest.size(); ++j)
  {
    scratch.Kept[j] = std::fabs(scratch.Residuals[j]) <= limit ? 1 : 0;
  }
}

} // namespace

/// The plane through the kept neighbors by PCA (false with fewer than 3):
/// the frame of a surface of zero height.
bool FitPlane(const std::vector<Neighbor>& nearest,
  const std::vector<unsigned char>& kept,
  LocalSurface& surface)
{
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  std::size_t count = 0;
  for (std::size_t j = 0; j < nearest.size(); ++j)
  {
    mean += kept[j] ? nearest[j].Offset : Eigen::Vector3d::Zero();
    count += kept[j];
  }
  if (count < 3)
  {
    return false;
  }
  mean /= static_cast<double>(count);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (std::size_t j = 0; j < nearest.size(); ++j)
  {
    if (kept[j])
    {
      const Eigen::Vector3d d = nearest[j].Offset - mean;
      covariance += d * d.transpose();
    }
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(covariance);
  const Eigen::Matrix3d vectors = solver.eigenvectors(); // ascending eigenvalues
  surface.Origin = mean;
  surface.Frame.col(0) = vectors.col(2);
  surface.Frame.col(1) = vectors.col(1);
  surface.Frame.col(2) = vectors.col(2).cross(vectors.col(1));
  surface.Height.setZero();
  return surface.Frame.allFinite();
}

/// The quadratic height over the surface's plane, least squares over the
/// kept neighbors; the height stays as it is with too few of them.
void FitHeight(const std::vector<Neighbor>& nearest,
  const std::vector<unsigned char>& kept,
  LocalSurface& surface)
{
  Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> right = Eigen::Matrix<double, 6, 1>::Zero();
  std::size_t count = 0;
  for (std::size_t j = 0; j < nearest.size(); ++j)
  {
    if (kept[j])
    {
      const Eigen::Vector3d p = surface.Frame.transpose() * (nearest[j].Offset - surface.Origin);
      Eigen::Matrix<double, 6, 1> row;
      row << 1.0, p.x(), p.y(), p.x() * p.x(), p.x() * p.y(), p.y() * p.y();
      normal.selfadjointView<Eigen::Lower>().rankUpdate(row);
      right += row * p.z();
      ++count;
    }
  }
  if (count < FewestForHeight)
  {
    return;
  }
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> solver(normal.selfadjointView<Eigen::Lower>());
  const Eigen::Matrix<double, 6, 1> height = solver.solve(right);
  if (solver.info() == Eigen::Success && solver.isPositive() && height.allFinite())
  {
    surface.Height = height;
  }
}

/// The surface of the neighbors: a plane through the nearer half (which an
/// outlier among them rarely reaches), refitted to the neighbors near it,
/// then a quadratic height fitted twice the same way; `deviation` gets the
/// noise's robust standard deviation. False where the neighbors span no
/// plane.
bool FitRobustSurface(FitScratch& scratch, LocalSurface& surface, double& deviation)
{
  const std::size_t count = scratch.Nearest.size();
  scratch.Kept.assign(count, 0);
  std::fill_n(scratch.Kept.begin(), (count + 1) / 2, 1);
  if (!FitPlane(scratch.Nearest, scratch.Kept, surface))
  {
    return false;
  }
  KeepNearSurface(surface, scratch);
  if (!FitPlane(scratch.Nearest, scratch.Kept, surface))
  {
    return false;
  }
  const double planeDeviation = RobustDeviation(surface, scratch);
  for (int round = 0; round < 2; ++round)
  {
    KeepNearSurface(surface, scratch);
    FitHeight(scratch.Nearest, scratch.Kept, surface);
  }
  // The noise: the height's robust deviation, made up for the six unknowns
  // it fits (a height fitted to few noisy points follows their noise), and
  // no more than the plane's.
  const double unknowns = 6.0;
  const double n = static_cast<double>(scratch.Nearest.size());
  deviation =
    std::min(planeDeviation, std::sqrt(n / (n - unknowns)) * RobustDeviation(surface, scratch));
  return true;
}

/// The spacing of the kept neighbors (in units of the radius): the median
/// of their distances to their nearest kept neighbor. Whatever the shape
/// of the patch they sample (a disc, the strip along an edge).
double SpacingAmong(FitScratch& scratch)
{
  std::vector<double>& nearest = scratch.Magnitudes;
  nearest.clear();
  const std::size_t count = scratch.Nearest.size();
  for (std::size_t j = 0; j < count; ++j)
  {
    double least = std::numeric_limits<double>::infinity();
    for (std::size_t l = 0; l < count && scratch.Kept[j]; ++l)
    {
      const double squared = (scratch.Nearest[j].Offset - scratch.Nearest[l].Offset).squaredNorm();
      least = l != j && scratch.Kept[l] && squared < least ? squared : least;
    }
    if (scratch.Kept[j] && std::isfinite(least))
    {
      nearest.push_back(least);
    }
  }
  if (nearest.empty())
  {
    return 0.0;
  }
  const auto middle = nearest.begin() + nearest.size() / 2;
  std::nth_element(nearest.begin(), middle, nearest.end());
  return std::sqrt(*middle);
}

/// The kept neighbors by distance to the surface's foot of the point
/// judged, nearest first, into scratch.ByFoot.
void RankByFoot(const LocalSurface& surface, FitScratch& scratch)
{
  const Eigen::Vector3d foot = surface.FootOf(Eigen::Vector3d::Zero());
  scratch.ByFoot.clear();
  for (std::size_t j = 0; j < scratch.Nearest.size(); ++j)
  {
    if (scratch.Kept[j])
    {
      scratch.ByFoot.emplace_back((scratch.Nearest[j].Offset - foot).squaredNorm(), j);
    }
  }
  std::sort(scratch.ByFoot.begin(), scratch.ByFoot.end());
}

} // namespace outliers
} // namespace pcurv
