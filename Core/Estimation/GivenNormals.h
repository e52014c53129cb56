/**
 * @file GivenNormals.h
 * @brief Whether the normals a cloud came with disagree with its positions
 * beyond what the positions' noise explains (noisy normals, or normals of
 * another scan): the estimation then replaces them by normals estimated
 * from the positions, each signed as the given one. No VTK.
 */
#ifndef GivenNormals_h
#define GivenNormals_h

#include "Estimation/EstimationSettings.h"

#include <vector>

namespace pcurv
{
struct CloudPoints;
class Collectives;
class WorkRunner;

/// Whether the own points' given normals disagree with the positions, for
/// the default fit only (OrientedCircles, the automatic scale, normals not
/// estimated anyway; the paper's fits keep the normals they are given): at
/// the points of the cloud's spacing sample (the same points for any split
/// among processes), the tilt a cubic over the given normal's tangent
/// plane finds in it (its slopes at the point) is compared with that
/// tilt's error, at the widest of the radii 1 to 8 typical first radii
/// whose tilt agrees with every smaller one's (Lepski's rule, so that the
/// surface's bending does not pass for a tilt). The normals disagree when
/// at most tested points the tilt is beyond what a normal as precise as
/// the positions' own would show at half of them: exact normals of a noisy
/// cloud are beyond it at few points, normals noisier than a plane of the
/// positions at most. `cloud` gets a halo for the test (distributed) and
/// is returned without it.
bool GivenNormalsDisagree(const EstimationSettings& settings,
  CloudPoints& cloud,
  const Collectives& processes,
  WorkRunner& runner);

/// Turns each of `normals` (3 per point) that opposes the matching one of
/// `given`, so that the given orientation is kept; a zero one (not
/// determined from the positions) takes the given one.
void SignLikeGiven(std::vector<double>& normals, const std::vector<double>& given);

} // namespace pcurv

#endif
