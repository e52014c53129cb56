#include "Estimation/ShapeClass.h"

#include <algorithm>
#include <cmath>

namespace pcurv
{

ShapeClass ClassifyShape(bool valid,
  bool outlier,
  double minimumCurvature,
  double maximumCurvature,
  double standardError,
  double radius)
{
  if (!valid || outlier || !std::isfinite(standardError) || !std::isfinite(minimumCurvature) ||
    !std::isfinite(maximumCurvature))
  {
    return ShapeClass::Undetermined;
  }
  // One standard error covers both curvatures; since k_min <= k_max, a
  // significant positive k_min implies a significant k_max, and a
  // significant negative k_max a significant k_min.
  const double threshold = ShapeSignificance * standardError;
  const bool maximumUp = maximumCurvature > threshold;
  const bool minimumDown = minimumCurvature < -threshold;
  if (minimumCurvature > threshold)
  {
    return ShapeClass::Dome;
  }
  if (maximumCurvature < -threshold)
  {
    return ShapeClass::Cup;
  }
  if (maximumUp && minimumDown)
  {
    return ShapeClass::Saddle;
  }
  if (maximumUp)
  {
    return ShapeClass::Ridge;
  }
  if (minimumDown)
  {
    return ShapeClass::Valley;
  }
  return ShapeSignificance * standardError * radius <= FlatBending ? ShapeClass::Flat
                                                                   : ShapeClass::Undetermined;
}

bool IsTrusted(bool valid,
  bool outlier,
  double minimumCurvature,
  double maximumCurvature,
  double standardError,
  double cloudCurvatureScale)
{
  if (!valid || outlier)
  {
    return false;
  }
  // Relative to the point's own curvature, so that a crest is judged by
  // what it measures; or absolute, so that a precisely flat point (whose
  // curvatures are near zero) counts too.
  const double largest = std::max(std::fabs(minimumCurvature), std::fabs(maximumCurvature));
  return 2.0 * standardError <= TrustedRelativeError * largest ||
    2.0 * standardError <= TrustedScaleShare * cloudCurvatureScale;
}

} // namespace pcurv
