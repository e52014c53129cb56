#include "Lines/CurvatureLines.h"

#include "Lines/LineTracing.h"
#include "Neighbors/PointGrid.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace pcurv
{
namespace
{

void CheckInput(const LineInput& input, const LineSettings& settings)
{
  if (input.Count < 0)
  {
    throw LineInputError("curvature lines: negative point count");
  }
  if (input.Count > 0 &&
    (!input.Points || !input.Normals || !input.MaximumCurvature || !input.MinimumCurvature ||
      !input.MaximumDirection))
  {
    throw LineInputError("curvature lines: points, normals, both principal curvatures and the "
                         "maximum curvature direction are required");
  }
  if (!(settings.MinimumLength >= 0.0) || !(settings.MinimumStrength >= 0.0) ||
    !(settings.Significance >= 0.0) || !(settings.RelativeBend >= 0.0) ||
    !(settings.FitRadius > 0.0) || settings.GraphNeighbors < 3 || settings.FitNeighbors < 20 ||
    settings.RadiusNeighbors < 6 || settings.MinimumFitPoints < 0 || settings.SharedFitPoints < 1 ||
    !(settings.SharedFitReach > 0.0) || !(settings.AnchorSpacing > 0.0))
  {
    throw LineInputError("curvature lines: settings out of range");
  }
  for (std::int64_t i = 0; i < 3 * input.Count; ++i)
  {
    if (!std::isfinite(input.Points[i]))
    {
      throw LineInputError("curvature lines: point " + std::to_string(i / 3) +
        " has a coordinate that is not a finite number");
    }
  }
}

/// The lattice of the point grid: cells about the typical neighborhood
/// radius (given, or guessed from the box and the count).
GridLattice PointLattice(const LineInput& input, const LineSettings& settings)
{
  double lower[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL },
         upper[3] = { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
  for (std::int64_t i = 0; i < input.Count; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      lower[k] = std::min(lower[k], input.Points[3 * i + k]);
      upper[k] = std::max(upper[k], input.Points[3 * i + k]);
    }
  }
  double cell = 0.0;
  if (input.Radius)
  {
    std::vector<double> radii;
    for (std::int64_t i = 0; i < input.Count; i += std::max<std::int64_t>(1, input.Count / 1000))
    {
      if (input.Radius[i] > 0.0 && std::isfinite(input.Radius[i]))
      {
        radii.push_back(input.Radius[i]);
      }
    }
    if (!radii.empty())
    {
      std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
      cell = radii[radii.size() / 2];
    }
  }
  if (!(cell > 0.0))
  {
    const double diagonal = std::sqrt((upper[0] - lower[0]) * (upper[0] - lower[0]) +
      (upper[1] - lower[1]) * (upper[1] - lower[1]) +
      (upper[2] - lower[2]) * (upper[2] - lower[2]));
    cell =
      diagonal * std::sqrt(settings.RadiusNeighbors / static_cast<double>(input.Count)) + 1e-300;
  }
  return GridLattice::Make(lower, upper, input.Count, cell);
}

double Median(std::vector<double> values)
{
  if (values.empty())
  {
    return 0.0;
  }
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

/// The lattice of the grid the lines work on: cells about the distance to
/// a point's graph neighbors (measured on a thousand of the points, on a
/// first grid of cells one neighborhood wide), so that the nearest-neighbor
/// query every point makes visits a few dozen points, not a neighborhood's
/// thousands.
GridLattice GraphLattice(const LineInput& input, const LineSettings& settings, WorkRunner* runner)
{
  const GridLattice coarse = PointLattice(input, settings);
  PointGrid grid;
  grid.Build(input.Points, input.Count, coarse, runner);
  std::vector<double> distances, scratch;
  const std::int64_t step = std::max<std::int64_t>(1, input.Count / 1024);
  for (std::int64_t i = 0; i < input.Count; i += step)
  {
    distances.push_back(
      grid.SquaredDistanceToKth(input.Points + 3 * i, settings.GraphNeighbors + 1, scratch));
  }
  const double cell = 1.5 * std::sqrt(Median(distances));
  if (!(cell > 0.0) || !(cell < coarse.CellSize))
  {
    return coarse;
  }
  double lower[3], upper[3];
  for (int k = 0; k < 3; ++k)
  {
    lower[k] = coarse.Origin[k];
    upper[k] = coarse.Origin[k] + (coarse.LastCell[k] + 1.0) * coarse.CellSize;
  }
  return GridLattice::Make(lower, upper, input.Count, cell);
}

/// A traced line with its length and strength.
CurvatureLine Measure(const TracedLine& traced)
{
  CurvatureLine line;
  line.Kind = traced.Kind;
  line.Curvature = traced.Curvature;
  for (std::size_t i = 0; i < traced.Points.size(); ++i)
  {
    line.Points.insert(line.Points.end(), traced.Points[i].begin(), traced.Points[i].end());
    if (i > 0)
    {
      const auto& a = traced.Points[i - 1];
      const auto& b = traced.Points[i];
      const double segment = std::sqrt((b[0] - a[0]) * (b[0] - a[0]) +
        (b[1] - a[1]) * (b[1] - a[1]) + (b[2] - a[2]) * (b[2] - a[2]));
      line.Length += segment;
      line.Strength +=
        0.5 * segment * (std::fabs(traced.Curvature[i - 1]) + std::fabs(traced.Curvature[i]));
    }
  }
  return line;
}

} // namespace

LineResult ExtractCurvatureLines(const LineInput& input,
  const LineSettings& settings,
  WorkRunner* runner)
{
  CheckInput(input, settings);
  LineResult result;
  if (input.Count == 0)
  {
    return result;
  }
  PointGrid grid;
  grid.Build(input.Points, input.Count, GraphLattice(input, settings, runner), runner);
  const PointDerivatives derivatives = FitDerivatives(input, settings, grid, runner);
  std::vector<double> radii;
  for (std::int64_t i = 0; i < input.Count; ++i)
  {
    if (derivatives.Fitted[i])
    {
      radii.push_back(derivatives.Radius[i]);
    }
  }
  result.MedianRadius = Median(radii);
  const std::vector<LineCrossing> crossings =
    FindCrossings(input, settings, derivatives, grid.GetSortedIds(), runner);
  result.Crossings = static_cast<std::int64_t>(crossings.size());
  std::vector<double> edges;
  for (const LineCrossing& c : crossings)
  {
    edges.push_back(c.EdgeLength);
  }
  const double shortest = settings.MinimumLength * result.MedianRadius;
  for (const TracedLine& traced : TraceLines(crossings, Median(edges)))
  {
    CurvatureLine line = Measure(traced);
    if (line.Length < shortest || line.Strength < settings.MinimumStrength ||
      line.Points.size() < 6)
    {
      ++result.ShortLines;
      continue;
    }
    result.Lines.push_back(std::move(line));
  }
  return result;
}

} // namespace pcurv
