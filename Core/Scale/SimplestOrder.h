/**
 * @file SimplestOrder.h
 * @brief Of the fits of a neighborhood's sums by the surface's terms up to
 * the second, third or fourth order, the simplest that the richer ones
 * agree with. No VTK.
 */
#ifndef SimplestOrder_h
#define SimplestOrder_h

#include "Fits/OrientedCircleFit.h"

namespace pcurv
{

/// The fit of the sums so far by the simplest order that agrees with the
/// richer ones: the second, third and fourth of the fourth order's sums,
/// the second and third of the third's; the simplest whose curvatures the
/// richer fits of the same neighbors agree with within what their extra
/// unknowns add to the error. False (no fit) where the neighborhood reaches
/// across the surface. The fourth order's fits carry the combined fit's
/// error, which judges the orders where the normals were given; estimated
/// normals (`estimatedNormals`) are judged by the positions' errors.
template<int Order>
bool FitSimplestOrder(OrientedCircleAccumulatorOf<Order>& accumulator,
  const TangentFrame& frame,
  double inverseUnit,
  double roundingVariance,
  const FitSettings& settings,
  bool estimatedNormals,
  OrientedCircleResult& result);

} // namespace pcurv

#endif
