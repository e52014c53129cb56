#include "Lines/CurvatureLines.h"

#include "Cloud/Collectives.h"
#include "Lines/LineCloud.h"
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

double Median(std::vector<double> values)
{
  if (values.empty())
  {
    return 0.0;
  }
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
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

/// Whether every process's input is good; throws the local error, or one
/// naming another process, when some is not. Collective.
void AgreeOnInput(const LineInput& input,
  const LineSettings& settings,
  const Collectives& processes)
{
  std::string problem;
  try
  {
    CheckInput(input, settings);
  }
  catch (const LineInputError& error)
  {
    problem = error.what();
  }
  if (processes.Min(problem.empty() ? 1 : 0) == 0)
  {
    throw LineInputError(
      problem.empty() ? "curvature lines: bad input on another process" : problem);
  }
}

/// The median neighborhood radius of the own points that were fitted.
double MedianRadius(const LineInput& local,
  const PointDerivatives& derivatives,
  const Collectives& processes)
{
  std::vector<double> radii;
  for (std::int64_t i = 0; i < local.Count; ++i)
  {
    if (derivatives.Fitted[i] && (!local.Owned || local.Owned[i]))
    {
      radii.push_back(derivatives.Radius[i]);
    }
  }
  return GlobalMedian(std::move(radii), processes);
}

} // namespace

LineResult ExtractCurvatureLines(const LineInput& input,
  const LineSettings& settings,
  WorkRunner* runner)
{
  return ExtractCurvatureLines(input, settings, Collectives(), runner);
}

LineResult ExtractCurvatureLines(const LineInput& input,
  const LineSettings& settings,
  const Collectives& processes,
  WorkRunner* runner)
{
  AgreeOnInput(input, settings, processes);
  LineResult result;
  const LineCloud cloud = GatherLineCloud(input, settings, processes);
  if (cloud.GlobalCount == 0)
  {
    return result;
  }
  LineInput local = cloud.AsInput();
  const GraphScale scale = MeasureGraphScale(cloud, settings, processes, runner);
  local.TypicalRadius = scale.TypicalRadius;
  PointDerivatives derivatives;
  std::vector<LineCrossing> own;
  if (local.Count > 0)
  {
    PointGrid grid;
    grid.Build(local.Points, local.Count, scale.Lattice, runner);
    derivatives = FitDerivatives(local, settings, grid, runner);
    own = FindCrossings(local, settings, derivatives, grid.GetSortedIds(), runner);
  }
  result.MedianRadius = MedianRadius(local, derivatives, processes);
  // Few against the points: traced on one process, in one order.
  const std::vector<LineCrossing> crossings = GatherCrossings(own, processes);
  if (processes.GetLocalProcessId() != 0)
  {
    return result;
  }
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
