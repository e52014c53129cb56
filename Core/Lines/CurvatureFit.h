/**
 * @file CurvatureFit.h
 * @brief A cubic least-squares fit of both principal curvatures over a
 * neighborhood's tangent plane, and what it says of the derivatives of a
 * curvature along a direction at any point near its center. No VTK.
 *
 * The fit is of the curvatures as scalar fields, so one fit serves every
 * point near its center: each evaluates it at its own offset, along its own
 * principal direction.
 */
#ifndef CurvatureFit_h
#define CurvatureFit_h

#include "Lines/LineTypes.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace pcurv
{
class PointGrid;
struct ShellPoints;

using LineVector = std::array<double, 3>;

/// A point's tangent frame: T1 along its d_max, T2 = n x T1 (along d_min).
struct LineFrame
{
  LineVector Normal, T1, T2;
};

/// False where the point has no unit normal or its d_max is along it.
bool MakeLineFrame(const LineInput& input, std::int64_t point, LineFrame& frame);

/// Terms of the fitted polynomial: up to the cubic ones, so that the
/// slope at the center is not biased by the curvature's third derivative
/// (which would move the lines of asymmetric profiles towards their
/// flatter side).
constexpr int CurvatureFitTerms = 10;
constexpr int CurvatureFitPacked = CurvatureFitTerms * (CurvatureFitTerms + 1) / 2;

/// k(u, v) = c0 + c1 u + c2 v + c3 u^2 + c4 uv + c5 v^2 + (cubic terms)
/// for k_max (column 0) and k_min (column 1), u and v along the center's
/// T1 and T2 in units of Radius.
struct CurvatureFit
{
  LineFrame Frame;
  LineVector Center{ { 0.0, 0.0, 0.0 } };
  double Radius = 0.0;
  Eigen::Matrix<double, CurvatureFitTerms, 2> Coefficients;
  /// The inverse of the normal matrix (times a sample's variance, the
  /// coefficients' covariance): its lower triangle, row by row.
  std::array<double, CurvatureFitPacked> Inverse;
  /// The residuals' variance of each column.
  double Residual[2] = { 0.0, 0.0 };
};

/// Reusable buffers of FitCurvatures.
struct CurvatureFitScratch
{
  struct Sample
  {
    double U, V;
    std::int64_t Id;
  };
  std::vector<Sample> Samples;
};

/// Fits the curvatures of the usable points within `radius` of `point`
/// (at most about settings.FitNeighbors of them, thinned evenly in the
/// grid's fixed order) over the point's frame. False where there are too
/// few or they do not determine the terms.
bool FitCurvatures(const LineInput& input,
  const LineSettings& settings,
  const PointGrid& grid,
  std::int64_t point,
  double radius,
  const LineFrame& frame,
  ShellPoints& shell,
  CurvatureFitScratch& scratch,
  CurvatureFit& fit);

/// One curvature's derivatives along a unit tangent direction d, at a
/// point near a fit's center.
struct DirectionalDerivatives
{
  double Slope = 0.0; ///< dk/dd
  double Bend = 0.0;  ///< d^2k/dd^2
  /// The gradient of Slope (d held fixed), in space.
  LineVector SlopeGradient{ { 0.0, 0.0, 0.0 } };
  /// Per unit variance of the fitted samples.
  double SlopeVariance = 0.0, BendVariance = 0.0;
};

/// The derivatives of k_max along frame.T1 (out[0]) and of k_min along
/// frame.T2 (out[1]) at `x`, from `fit`; the directions are taken into the
/// fit's tangent plane.
void EvaluateAlongDirections(const CurvatureFit& fit,
  const double x[3],
  const LineFrame& frame,
  DirectionalDerivatives out[2]);

/// Whether x is a point whose curvatures the fits may use.
bool UsableForLines(const LineInput& input, std::int64_t point);

} // namespace pcurv

#endif
