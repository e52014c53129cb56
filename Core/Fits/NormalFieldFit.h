/**
 * @file NormalFieldFit.h
 * @brief The curvatures as the first derivative of the normal field: the
 * neighbors' normals give the slope of the surface at their own positions,
 * and a least-squares fit of that slope against the tangential offsets,
 * with a free slope at the query point, gives the second derivatives. No
 * VTK.
 *
 * In the tangent frame of the query point x (unit normal n, directions v0,
 * w0; lengths in units of a scale), the surface is the height
 * h(u, v) = e + tu u + tv v + ((C + A) u^2 + 2 B u v + (C - A) v^2) / 2
 *   + c30 u^3 + c21 u^2 v + c12 u v^2 + c03 v^3
 * (FittedSurface, paper sign). A neighbor at (u, v) with unit normal m
 * (turned to agree with n) gives two rows, its normal's tangential parts,
 * which are the height's slope to first order:
 *   -m.v0 = tu + (C + A) u + B v + 3 c30 u^2 + 2 c21 u v + c12 v^2,
 *   -m.w0 = tv + B u + (C - A) v + c21 u^2 + 2 c12 u v + 3 c03 v^2,
 * equally weighted. On a sphere or a cylinder the tangential parts are
 * exactly linear in the tangential offsets, at any radius (the slope
 * -m.v0 / m.n is not). The fit never reads the heights: a query point off the
 * surface (every point of a noisy scan) moves no row, and its displacement
 * along the surface is taken up by the free slope (tu, tv); positions enter
 * only as the rows' abscissae, so their noise reaches the curvatures once,
 * not as the second derivative of noisy heights. Where the neighborhood is
 * symmetric the third order's columns are even and leave the second
 * derivatives alone; where it is one-sided (a boundary) they do not, and
 * the third order is fitted too (the automatic scale picks the simpler
 * where they agree).
 *
 * Everything is a sum over the neighbors, so a neighborhood can grow shell
 * by shell (the automatic scale) and each radius costs one small solve.
 */
#ifndef NormalFieldFit_h
#define NormalFieldFit_h

#include "Fits/FitResults.h"

#include <array>
#include <cstddef>

namespace pcurv
{

/// The normal equations of the slope rows of a neighborhood (the unknowns
/// C, A, B, tu, tv, c30, c21, c12, c03: FittedSurface's first nine), kept
/// apart for the rows of the slope along v0 (U) and along w0 (V) and their
/// cross terms, so that the rows' residual covariance (a 2x2 matrix: the
/// positions' noise along the surface moves a neighbor's two slopes by the
/// shape operator times that noise, far more along the more curved
/// direction) can be estimated and carried into the curvatures' covariance.
/// And the tallies every oriented fit keeps.
struct NormalFieldSums : OrientedCircleTallies
{
  static constexpr int Unknowns = 9;
  static constexpr int Entries = Unknowns * (Unknowns + 1) / 2;
  /// Upper triangles of sum ru ru', sum rv rv', sum (ru rv' + rv ru').
  std::array<double, Entries> MatrixU{}, MatrixV{}, MatrixCross{};
  /// sum ru yu, sum rv yv, sum ru yv, sum rv yu.
  std::array<double, Unknowns> RightU{}, RightV{}, RightUV{}, RightVU{};
  /// sum yu^2, sum yv^2, sum yu yv.
  double TargetsU = 0.0, TargetsV = 0.0, TargetsUV = 0.0;
  /// Neighbors whose normal gave rows (two each).
  int Rows = 0;
};

/// Adds neighbors to NormalFieldSums: Begin, Add per neighbor, Sums.
class NormalFieldAccumulator
{
public:
  /// Starts afresh in the tangent frame of a query point.
  void Begin(const TangentFrame& frame);

  /// Adds a neighbor: its offset (in units of the scale) and its unit
  /// normal, or null or zero (counted, no rows). At the query point:
  /// ignored. A normal opposing the query's is turned first (a normal's
  /// line is what it tells); a normal that is not finite gives no rows.
  void Add(const double d[3], const double* normal);

  const NormalFieldSums& Sums() const { return this->Totals; }

private:
  TangentFrame Frame{};
  NormalFieldSums Totals;
};

/// Fits the slope rows of `sums` by the surface's terms up to `Order` (2:
/// the second derivatives and the slope, 3: the cubic's too). Invalid with
/// fewer than `minimumNeighbors` neighbors giving rows, angles within a
/// half-turn of 2 phi, or a neighborhood reaching across the surface. The
/// standard error is the curvatures' from the rows' residual (1/length).
/// The result's Surface carries no height (e = 0) and, as its
/// NoiseVariance, the slope rows' residual variance; SetHeightOfPoints
/// completes both from the positions.
template<int Order>
OrientedCircleResult FitNormalField(const NormalFieldSums& sums,
  const TangentFrame& frame,
  double inverseScale,
  int minimumNeighbors,
  double maximumOpposing);

/// The height e of the fitted surface at the query point and the positions'
/// noise variance along the normal (in units of the scale squared), from
/// the `count` neighbors' offsets (in units of the scale, one array per
/// axis, in the frame's world coordinates): the mean and variance of their
/// heights above `surface` with e = 0. Sets both in `surface`.
void SetHeightOfPoints(const TangentFrame& frame,
  const double* dx,
  const double* dy,
  const double* dz,
  std::size_t count,
  FittedSurface& surface);

} // namespace pcurv

#endif
