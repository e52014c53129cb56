/**
 * @file OrientedCircleFit.h
 * @brief A fit beyond the paper, in its spirit: every neighbour q defines
 * the osculating circle through the query point x whose centre lies on the
 * normal line (the paper's circle, for one point), and, through its normal
 * n_q, an oriented circle (one whose normal at q agrees with n_q). Both give
 * the normal curvature in q's direction; the sine of period pi of the paper,
 * kappa(phi) = C + A cos 2 phi + B sin 2 phi, is fitted to all of them at the
 * neighbours' own angles phi instead of 16 half planes. No VTK.
 *
 * In the tangent frame of x (paper sign, lengths in units of the scale):
 * with d = q - x, D = |d|^2, h = d . n, phi the angle of d's tangential part,
 * - position: the circle through x and q centred on the normal line has
 *   kappa D = 2 h exactly;
 * - normal: for an oriented circle (or sphere) -(n_q - n) . d = kappa D.
 * A tilt delta of the query normal adds delta . d to -(n_q - n) . d and
 * 2 delta . d to 2 h: two tangential unknowns absorb it, so a noisy query
 * normal (PCA normals) does not bias the curvatures. The two kinds of rows
 * are weighted by the inverse of their own residual variance, measured in
 * a first pass: positions dominate where the normals are poor, normals where
 * the positions are noisy (normals' errors grow like |d|, positions' do
 * not, and the weights follow).
 */
#ifndef OrientedCircleFit_h
#define OrientedCircleFit_h

#include "PrincipalCurvatureCore.h"

#include <cstddef>
#include <vector>

namespace pcurv
{

class OrientedCircleEstimator
{
public:
  /// Starts a query at a point with unit normal `unitNormal`; lengths are
  /// divided by `scale` (the neighbourhood's radius, > 0).
  void Begin(const Vector3& unitNormal, double scale);

  /// Adds a neighbour by its offset q - x and its unit normal (zero: the
  /// position alone is used). Neighbours at the query point are ignored.
  void AddNeighbor(const double offset[3], const double normal[3]);

  int GetNumberOfNeighbors() const { return static_cast<int>(this->U.size()); }

  /// Neighbours whose normal points against the query's (n_q . n < 0): the
  /// neighbourhood reaches across the surface (a thin part, two sheets).
  int GetNumberOfOpposingNormals() const { return this->Opposing; }

  /// The principal curvatures and directions (output sign), or an invalid
  /// result when the neighbours do not determine them (too few, on a line,
  /// or too many opposing normals: more than `maximumOpposing` of them).
  /// `standardError` receives the standard error of the curvatures (the
  /// fit's covariance, 1/length), NaN when invalid.
  PointCurvature Estimate(int minimumNeighbors,
    double maximumOpposing,
    double& standardError) const;

private:
  TangentFrame Frame{};
  double InverseScale = 1.0;
  int Opposing = 0;
  // Per neighbour, in units of the scale: tangential coordinates, height,
  // squared distance, the normal term -(n_q - n) . d, and whether it has one.
  std::vector<double> U, V, H, D, T;
  std::vector<unsigned char> HasNormal;
};

} // namespace pcurv

#endif
