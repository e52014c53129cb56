/**
 * @file CloudNormals.h
 * @brief The normals the estimation of a cloud works with: the given ones,
 * or normals estimated from the positions (NormalEstimation.h) where asked
 * for or where the positions contradict the given ones. No VTK.
 */
#ifndef CloudNormals_h
#define CloudNormals_h

namespace pcurv
{
struct CloudPoints;
struct EstimationSettings;
struct EstimationSummary;
struct WorkingUnit;
class Collectives;
class ProgressMonitor;
class RealBuffer;
class WorkRunner;

/// The normals of the own points of `cloud` estimated where asked for, or
/// where the positions contradict the given ones (then signed as given),
/// and written to `out` too; returns the part of the progress they take.
/// summary.Normals.Aborted when stopped on some process.
double SettleNormals(CloudPoints& cloud,
  const EstimationSettings& settings,
  const WorkingUnit& unit,
  const Collectives& processes,
  WorkRunner& runner,
  ProgressMonitor* monitor,
  const RealBuffer& out,
  EstimationSummary& summary);

} // namespace pcurv

#endif
