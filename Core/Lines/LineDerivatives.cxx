#include "Lines/LineDerivatives.h"

#include "Common/WorkRunner.h"
#include "Lines/CurvatureFit.h"
#include "Neighbors/AnchorCells.h"
#include "Neighbors/PointGrid.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace pcurv
{
namespace
{
constexpr std::int64_t Grain = 2048;

LineVector Load(const double* a, std::int64_t i)
{
  return { { a[3 * i], a[3 * i + 1], a[3 * i + 2] } };
}
double Dot(const LineVector& a, const LineVector& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
LineVector Cross(const LineVector& a, const LineVector& b)
{
  return { { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] } };
}
double SquaredDistance(const LineVector& a, const LineVector& b)
{
  return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
    (a[2] - b[2]) * (a[2] - b[2]);
}
bool Normalize(LineVector& v)
{
  const double length = std::sqrt(Dot(v, v));
  if (!(length > 1e-12) || !std::isfinite(length))
  {
    return false;
  }
  for (double& c : v)
  {
    c /= length;
  }
  return true;
}

/// A point's place in the work: its fit radius, whether it may share a
/// fit, and its frame.
struct PointRole
{
  double FitRadius = 0.0;
  bool Fittable = false; ///< usable curvatures, a frame and a radius
  bool Dense = false;    ///< its neighborhood holds SharedFitPoints or more
  LineFrame Frame;
};

/// The derivatives of one curvature at a point, as a weighted mean of the
/// fits that serve it; the standard errors are averaged as variances, as
/// if the fits' errors were fully correlated (they share most samples).
struct BlendedDerivatives
{
  double Weight = 0.0, Slope = 0.0, Bend = 0.0, SlopeVariance = 0.0, BendVariance = 0.0;
  LineVector Gradient{ { 0.0, 0.0, 0.0 } };

  void Add(const DirectionalDerivatives& d, double weight, double noise)
  {
    this->Weight += weight;
    this->Slope += weight * d.Slope;
    this->Bend += weight * d.Bend;
    this->SlopeVariance += weight * noise * d.SlopeVariance;
    this->BendVariance += weight * noise * d.BendVariance;
    for (int k = 0; k < 3; ++k)
    {
      this->Gradient[k] += weight * d.SlopeGradient[k];
    }
  }
};

/// The fits of the anchors, in AnchorCells' numbering.
struct SharedCurvatureFits
{
  AnchorCells Cells;
  std::vector<CurvatureFit> Fits;
};

class DerivativeFitter
{
public:
  DerivativeFitter(const LineInput& input,
    const LineSettings& settings,
    const PointGrid& grid,
    const std::vector<PointRole>& roles,
    const SharedCurvatureFits& shared,
    PointDerivatives& out)
    : Input(input)
    , Settings(settings)
    , Grid(grid)
    , Roles(roles)
    , Shared(shared)
    , Out(out)
  {
  }

  void Derive(std::int64_t i)
  {
    const PointRole& role = this->Roles[i];
    if (!role.Fittable)
    {
      return;
    }
    BlendedDerivatives blend[2];
    if (!(role.Dense && this->BlendShared(i, blend)))
    {
      CurvatureFit fit;
      if (!FitCurvatures(this->Input,
            this->Settings,
            this->Grid,
            i,
            role.FitRadius,
            role.Frame,
            this->Shell,
            this->Scratch,
            fit))
      {
        return;
      }
      this->AddFit(i, fit, 1.0, blend);
    }
    this->Assemble(i, blend);
  }

private:
  /// The shared fits within reach of point i, weighted by a bump that
  /// falls smoothly to zero at the reach (so the derivatives vary
  /// continuously from point to point). False where none serves it.
  bool BlendShared(std::int64_t i, BlendedDerivatives blend[2])
  {
    const PointRole& role = this->Roles[i];
    const LineVector x = Load(this->Input.Points, i);
    this->Shared.Cells.AnchorsAround(x.data(), this->Around);
    const double reach = this->Settings.SharedFitReach * role.FitRadius;
    for (const std::int64_t position : this->Around.Anchors)
    {
      const CurvatureFit& fit = this->Shared.Fits[position];
      const double ratio = fit.Radius / role.FitRadius;
      const double squared = SquaredDistance(x, fit.Center) / (reach * reach);
      if (squared < 1.0 && ratio > 2.0 / 3.0 && ratio < 1.5)
      {
        this->AddFit(i, fit, (1.0 - squared) * (1.0 - squared), blend);
      }
    }
    return blend[0].Weight > 0.0;
  }

  void AddFit(std::int64_t i, const CurvatureFit& fit, double weight, BlendedDerivatives blend[2])
  {
    // The noise of the curvatures a fit sees. Its residuals measure it
    // where they are many (a dense neighborhood). The curvatures' standard
    // error bounds each one's whole error, most of it shared by
    // neighbors (the bias of a neighborhood, which moves with it and
    // leaves the derivatives): taken for independent noise it hides every
    // gentle extremum of a noisy cloud. It remains the floor where the
    // residuals of a few dozen samples say little, on clean clouds, whose
    // curvatures' small errors vary at the scale of the neighborhood.
    const double given =
      this->Roles[i].Dense || !this->Input.StandardError ? 0.0 : this->Input.StandardError[i];
    const LineFrame& frame = this->Roles[i].Frame;
    const double* x = this->Input.Points + 3 * i;
    DirectionalDerivatives derivatives[2];
    EvaluateAlongDirections(fit, x, frame, derivatives);
    for (int which = 0; which < 2; ++which)
    {
      const double noise = std::max(fit.Residual[which], given * given);
      blend[which].Add(derivatives[which], weight, noise);
    }
  }

  void Assemble(std::int64_t i, const BlendedDerivatives blend[2])
  {
    const LineFrame& frame = this->Roles[i].Frame;
    const double given = this->Input.StandardError ? this->Input.StandardError[i] : 0.0;
    const double kMax = this->Input.MaximumCurvature[i], kMin = this->Input.MinimumCurvature[i];
    const double spread = kMax - kMin;
    const double scale = std::max(std::fabs(kMax), std::fabs(kMin));
    // Directions are noise where the curvatures are about equal (umbilics).
    const bool anisotropic = spread > this->Settings.Significance * given &&
      spread > 1e-9 * (std::fabs(kMax) + std::fabs(kMin)) && spread > 0.0;
    for (int which = 0; which < 2; ++which)
    {
      const BlendedDerivatives& b = blend[which];
      Extremality x;
      x.Slope = b.Slope / b.Weight;
      x.Bend = b.Bend / b.Weight;
      x.SlopeError = std::sqrt(b.SlopeVariance / b.Weight);
      const double bendError = std::sqrt(b.BendVariance / b.Weight);
      x.BendFloor = this->Settings.RelativeBend * spread * scale * scale;
      x.Significant = anisotropic && std::fabs(x.Bend) > this->Settings.Significance * bendError;
      x.Direction = which == 0 ? frame.T1 : frame.T2;
      // The zero set of the slope runs across its gradient.
      x.Tangent = Cross(frame.Normal, b.Gradient);
      if (!Normalize(x.Tangent))
      {
        x.Tangent = which == 0 ? frame.T2 : frame.T1;
      }
      (which == 0 ? this->Out.Maximum : this->Out.Minimum)[i] = x;
    }
    this->Out.Fitted[i] = 1;
  }

  const LineInput& Input;
  const LineSettings& Settings;
  const PointGrid& Grid;
  const std::vector<PointRole>& Roles;
  const SharedCurvatureFits& Shared;
  PointDerivatives& Out;
  AnchorCells::Around Around;
  ShellPoints Shell;
  CurvatureFitScratch Scratch;
};

/// Each point's graph row (its GraphWidth nearest other points, nearest
/// first, ties by index) and its role; the radius is the input's, else
/// the distance to the RadiusNeighbors-th nearest point.
class RoleFinder
{
public:
  RoleFinder(const LineInput& input,
    const LineSettings& settings,
    const PointGrid& grid,
    PointDerivatives& out,
    std::vector<PointRole>& roles)
    : Input(input)
    , Settings(settings)
    , Grid(grid)
    , Out(out)
    , Roles(roles)
  {
  }

  void Find(std::int64_t i)
  {
    const double* x = this->Input.Points + 3 * i;
    const double radius = this->Input.Radius ? this->Input.Radius[i]
                                             : std::sqrt(this->Grid.SquaredDistanceToKth(
                                                 x, this->Settings.RadiusNeighbors, this->Scratch));
    this->Out.Radius[i] = radius;
    const double graphReach = this->FillGraphRow(i);
    PointRole& role = this->Roles[i];
    role.FitRadius = radius * this->Settings.FitRadius;
    role.Fittable = role.FitRadius > 0.0 && std::isfinite(role.FitRadius) &&
      UsableForLines(this->Input, i) && MakeLineFrame(this->Input, i, role.Frame);
    // About width points lie within graphReach, so about width (R / reach)^2
    // within the fit radius R of a surface.
    const double ratio = role.FitRadius / graphReach;
    const double within = this->Out.GraphWidth * ratio * ratio;
    role.Dense = graphReach > 0.0 && within >= this->Settings.SharedFitPoints;
    role.FitRadius = GrownFitRadius(role.FitRadius, graphReach, this->Settings);
  }

private:
  /// Returns the distance to the farthest point of the row (0 when empty).
  double FillGraphRow(std::int64_t i)
  {
    const int width = this->Out.GraphWidth;
    std::int64_t* row = &this->Out.Graph[i * width];
    std::fill(row, row + width, -1);
    this->Nearest.clear();
    if (this->Grid.GatherNearest(this->Input.Points + 3 * i, width + 1, this->Shell) > 0.0)
    {
      for (std::size_t k = 0; k < this->Shell.Count; ++k)
      {
        const double dx = this->Shell.Dx[k], dy = this->Shell.Dy[k], dz = this->Shell.Dz[k];
        if (this->Shell.Ids[k] != i)
        {
          this->Nearest.emplace_back(dx * dx + dy * dy + dz * dz, this->Shell.Ids[k]);
        }
      }
    }
    const std::size_t kept = std::min<std::size_t>(this->Nearest.size(), width);
    std::partial_sort(this->Nearest.begin(), this->Nearest.begin() + kept, this->Nearest.end());
    for (std::size_t k = 0; k < kept; ++k)
    {
      row[k] = this->Nearest[k].second;
    }
    return kept > 0 ? std::sqrt(this->Nearest[kept - 1].first) : 0.0;
  }

  const LineInput& Input;
  const LineSettings& Settings;
  const PointGrid& Grid;
  PointDerivatives& Out;
  std::vector<PointRole>& Roles;
  ShellPoints Shell;
  std::vector<std::pair<double, std::int64_t>> Nearest;
  std::vector<double> Scratch;
};

/// 0 without a typical radius: then no anchors, every point fits its own.
/// A stand-in measured here (such as a median of the points' radii) would
/// be this process's alone, and distributed runs would place different
/// anchors than a serial one.
double TypicalFitRadius(const LineInput& input, const LineSettings& settings)
{
  const double radius = input.TypicalRadius * settings.FitRadius;
  return radius > 0.0 && std::isfinite(radius) ? radius : 0.0;
}

/// Anchors among the dense points (one per cell of a lattice of
/// AnchorSpacing typical radii) and their fits; the anchors whose fit
/// failed are dropped.
void FitAnchors(const LineInput& input,
  const LineSettings& settings,
  const PointGrid& grid,
  const std::vector<PointRole>& roles,
  WorkRunner* runner,
  SharedCurvatureFits& shared)
{
  const double cell = settings.AnchorSpacing * TypicalFitRadius(input, settings);
  if (!(cell > 0.0) || !std::isfinite(cell))
  {
    return;
  }
  const double origin[3] = { 0.0, 0.0, 0.0 };
  shared.Cells.Build(
    input.Points,
    input.Normals,
    input.Count,
    [&](std::int64_t j) { return grid.GetSortedId(j); },
    origin,
    cell,
    [&](std::int64_t point) { return roles[point].Fittable && roles[point].Dense; },
    []() { return true; });
  std::vector<unsigned char> marks(static_cast<std::size_t>(input.Count), 0);
  shared.Cells.MarkEveryAnchor(marks);
  std::vector<std::int64_t> anchors;
  for (std::int64_t j = 0; j < input.Count; ++j)
  {
    if (marks[grid.GetSortedId(j)])
    {
      anchors.push_back(grid.GetSortedId(j));
    }
  }
  std::vector<CurvatureFit>& fits = shared.Fits;
  fits.resize(anchors.size());
  std::vector<unsigned char> fitted(anchors.size(), 0);
  RunRanges(runner,
    static_cast<std::int64_t>(anchors.size()),
    64,
    [&](std::int64_t begin, std::int64_t end)
    {
      ShellPoints shell;
      CurvatureFitScratch scratch;
      for (std::int64_t a = begin; a < end; ++a)
      {
        const PointRole& role = roles[anchors[a]];
        fitted[a] = FitCurvatures(
          input, settings, grid, anchors[a], role.FitRadius, role.Frame, shell, scratch, fits[a]);
      }
    });
  // The anchors whose fit held, in order, and their fits in place.
  std::vector<std::int64_t> kept;
  for (std::size_t a = 0; a < anchors.size(); ++a)
  {
    if (fitted[a])
    {
      fits[kept.size()] = fits[a];
      kept.push_back(anchors[a]);
    }
  }
  fits.resize(kept.size());
  shared.Cells.NumberAnchors(kept);
}

} // namespace

double GrownFitRadius(double fitRadius, double graphReach, const LineSettings& settings)
{
  // About GraphNeighbors points lie within graphReach, so about
  // GraphNeighbors (R / graphReach)^2 within R on a surface. A clean
  // cloud's curvatures come from a few dozen neighbors: their derivatives
  // need a wider fit than they did.
  const double least = graphReach *
    std::sqrt(
      static_cast<double>(settings.MinimumFitPoints) / std::max(1, settings.GraphNeighbors));
  return graphReach > 0.0 ? std::max(fitRadius, least) : fitRadius;
}

PointDerivatives FitDerivatives(const LineInput& input,
  const LineSettings& settings,
  const PointGrid& grid,
  WorkRunner* runner)
{
  PointDerivatives out;
  const std::size_t n = static_cast<std::size_t>(input.Count);
  out.Maximum.resize(n);
  out.Minimum.resize(n);
  out.Fitted.assign(n, 0);
  out.Radius.assign(n, 0.0);
  out.GraphWidth = std::max(1, settings.GraphNeighbors);
  out.Graph.assign(n * out.GraphWidth, -1);
  std::vector<PointRole> roles(n);
  // In the grid's order: consecutive points share their neighbors, whose
  // data then stay in cache.
  RunRanges(runner,
    input.Count,
    Grain,
    [&](std::int64_t begin, std::int64_t end)
    {
      RoleFinder finder(input, settings, grid, out, roles);
      for (std::int64_t j = begin; j < end; ++j)
      {
        finder.Find(grid.GetSortedId(j));
      }
    });
  SharedCurvatureFits shared;
  FitAnchors(input, settings, grid, roles, runner, shared);
  RunRanges(runner,
    input.Count,
    Grain,
    [&](std::int64_t begin, std::int64_t end)
    {
      DerivativeFitter fitter(input, settings, grid, roles, shared, out);
      for (std::int64_t j = begin; j < end; ++j)
      {
        fitter.Derive(grid.GetSortedId(j));
      }
    });
  return out;
}

} // namespace pcurv
