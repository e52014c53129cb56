/**
 * @file HeightJet.h
 * @brief The surface as a height of the fourth order over the tangent
 * plane of the point's normal (a jet, the model of CGAL's Monge fitting),
 * fitted to the positions of its nearest neighbors alone. Where positions
 * carry no noise (points of a mesh, of a CAD model, of an analytic
 * surface), a few neighbors suffice and the model's error, of the fifth
 * order in the radius, is far below that of the oriented circles at their
 * smallest radius. No VTK.
 */
#ifndef HeightJet_h
#define HeightJet_h

#include "Fits/PrincipalCurvatureCore.h"

#include <cstddef>
#include <limits>

namespace pcurv
{

/// A jet's principal curvatures (output sign) and directions, tangent to
/// its own normal (FittedNormal), and the standard error of the curvatures
/// from its positions' residual (1/length), NaN where it has none.
struct HeightJetFit
{
  PointCurvature Curvature;
  double StandardError = std::numeric_limits<double>::quiet_NaN();
};

/// The normal of the least-squares plane of `count` neighbors at offsets
/// (dx, dy, dz) (the smallest eigenvector of their covariance), turned to
/// `side`'s side: the jet's plane. `scale` is the neighborhood's radius.
/// `side` itself where the neighbors do not determine a plane (on a line).
Vector3 NeighborhoodPlaneNormal(const double* dx,
  const double* dy,
  const double* dz,
  std::size_t count,
  double scale,
  const Vector3& side);

/// The jet's unknowns: the height, its two slopes, three second, four
/// third and five fourth derivatives' coefficients.
constexpr int HeightJetUnknowns = 15;

/// Fits the jet to `count` neighbors at offsets (dx, dy, dz) from the
/// point (the point itself among them, at offset zero, if it is one), over
/// the tangent plane of `frame` (the point's normal and its tangent axes).
/// `scale` is the neighborhood's radius: the offsets are divided by it, so
/// that the normal equations are well scaled. Invalid with fewer than
/// HeightJetUnknowns + 2 neighbors or where they do not determine the jet
/// (on a line, in a few rows of a scan). The standard error takes the
/// positions' variance along the normal as at least `heightVarianceFloor`
/// (length squared: what rounding the coordinates adds).
HeightJetFit FitHeightJet(const double* dx,
  const double* dy,
  const double* dz,
  std::size_t count,
  const TangentFrame& frame,
  double scale,
  double heightVarianceFloor);

} // namespace pcurv

#endif
