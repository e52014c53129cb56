/**
 * @file LineTracing.h
 * @brief Zero crossings traced into polylines: from the strongest unused
 * crossing, step by step to the next one ahead along the line's tangent,
 * in both directions. No VTK.
 *
 * The crossings of one line form a band about one edge wide (every graph
 * edge across the line has one). Each step takes up the crossings of its
 * kind within a band's width and places the line point at their centroid:
 * the band gives one line, not several side by side, and the line runs
 * through the middle of the band.
 */
#ifndef LineTracing_h
#define LineTracing_h

#include "Lines/LineCrossings.h"

#include <array>
#include <vector>

namespace pcurv
{

struct TracedLine
{
  LineKind Kind = LineKind::Ridge;
  std::vector<std::array<double, 3>> Points;
  std::vector<double> Curvature;
  bool Closed = false;
};

/// Polylines through the crossings, `step` apart at most about 3 steps;
/// `step` is the graph's typical edge length.
std::vector<TracedLine> TraceLines(const std::vector<LineCrossing>& crossings, double step);

} // namespace pcurv

#endif
