/**
 * @file CurvatureLines.h
 * @brief Extremal lines of the principal curvatures of a point cloud, as
 * polylines, from the curvatures and directions estimated at its points.
 * No VTK.
 *
 * An extremal line of k_max (in Porteous' sense) is where k_max is extremal
 * along its own direction d_max: where e_max = d k_max / d d_max crosses
 * zero. Likewise for k_min along d_min. The crests a user means are two of
 * the six kinds below: ridges (k_max maximal and dominant, k_max > |k_min|)
 * and valleys (k_min minimal and dominant, k_min < -|k_max|); signs follow
 * the curvature filter's (positive where the surface bends away from the
 * normal, so a crest of a surface with outward normals is a ridge).
 */
#ifndef CurvatureLines_h
#define CurvatureLines_h

#include "Common/WorkRunner.h"
#include "Lines/LineTypes.h"

#include <cstdint>
#include <vector>

namespace pcurv
{
class Collectives;

struct CurvatureLine
{
  LineKind Kind = LineKind::Ridge;
  double Length = 0.0;
  double Strength = 0.0;         ///< integral of |k| along the line (radians)
  std::vector<double> Points;    ///< xyz triplets
  std::vector<double> Curvature; ///< the extremal curvature at each point
};

struct LineResult
{
  std::vector<CurvatureLine> Lines;
  std::int64_t Crossings = 0;  ///< zero crossings kept before tracing
  std::int64_t ShortLines = 0; ///< traced, then dropped by the limits
  double MedianRadius = 0.0;   ///< of the points' neighborhoods
};

/// The extremal lines of the selected kinds, in a deterministic order that
/// does not depend on `runner` (which runs the per-point fits).
LineResult ExtractCurvatureLines(const LineInput& input,
  const LineSettings& settings,
  WorkRunner* runner = nullptr);

/// The same, in a distributed run where `input` is this process's part
/// of the cloud (any part: a spatial piece, every n-th point, none): the
/// lines of the whole cloud, the same to the last bit as a serial run's,
/// returned on process 0 (the others get none, and Crossings and
/// ShortLines 0). Every process must call it. Collective.
LineResult ExtractCurvatureLines(const LineInput& input,
  const LineSettings& settings,
  const Collectives& processes,
  WorkRunner* runner = nullptr);

} // namespace pcurv

#endif
