/**
 * @file Orientation.h
 * @brief The sign of the fitted normals: consistent over each connected part
 * by a minimum spanning tree, then per part outward, or point by point
 * towards a viewpoint or along an axis: internal to the normal estimation.
 * No VTK.
 */
#ifndef Orientation_h
#define Orientation_h

#include "Normals/NormalSettings.h"
#include "Normals/NormalSummary.h"

#include <vector>

namespace pcurv
{

struct PlaneFits;
class StageProgress;
class WorkRunner;

namespace normals
{
class OrderedCloud;
} // namespace normals

namespace normals
{

/// Each normal on the side the settings ask for, point by point.
void OrientPointwise(const NormalSettings& settings,
  const OrderedCloud& ordered,
  std::vector<double>& normals);

/// Orients every connected part of the graph (NormalOrientation::Outward),
/// a scan seen from above up (`radius`: the normals' neighborhood radius);
/// false when the progress monitor asked to stop. The fits' repeated edges
/// are dropped.
template<typename Index>
bool OrientOutward(PlaneFits& fits,
  const OrderedCloud& ordered,
  double radius,
  WorkRunner& runner,
  std::vector<double>& normals,
  NormalSummary& summary,
  StageProgress* progress);

} // namespace normals
} // namespace pcurv

#endif
