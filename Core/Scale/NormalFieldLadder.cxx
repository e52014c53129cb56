#include "Scale/AutomaticScale.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcurv
{
namespace
{
/// The radius times the largest |curvature| beyond which the ladder stops:
/// across a wider neighborhood the surface turns so far that its normals'
/// slopes over the query's plane leave any low-order model.
constexpr double LargestTurn = 1.0;

/// How many standard errors of their difference the second and third
/// orders' curvatures may differ by for the second to stand: the
/// difference of nested fits of the same rows has the variance of the
/// richer less that of the simpler, and at the first radii, a few
/// neighbors for nine unknowns, the third order's covariance understates
/// its error several times.
constexpr double OrderAgreement = 8.0;

/// The fewest neighbors giving rows for a fit of the third order: its nine
/// unknowns among fewer fit the noise, and its residual then understates
/// its error (at the first radius, 16 neighbors, by several times).
constexpr int ThirdOrderNeighbors = 32;

/// The fit of the normal field by the simpler order the richer agrees
/// with: the second (the normal field's first order) unless the third's
/// curvatures differ from it by more than OrderAgreement standard errors of
/// their difference (a one-sided neighborhood, where the cubic's even
/// columns reach the second derivatives). The difference is kept as the
/// model's bias (OrderDiscrepancy).
OrientedCircleResult FitSimplerField(const NormalFieldSums& sums,
  const TangentFrame& frame,
  double inverseUnit,
  const FitSettings& settings)
{
  const OrientedCircleResult second =
    FitNormalField<2>(sums, frame, inverseUnit, 0, settings.MaximumOpposingFraction);
  const OrientedCircleResult third = FitNormalField<3>(
    sums, frame, inverseUnit, ThirdOrderNeighbors, settings.MaximumOpposingFraction);
  if (!third.Curvature.Valid)
  {
    return second;
  }
  if (!second.Curvature.Valid)
  {
    return third;
  }
  const double allowed = OrderAgreement *
    std::sqrt(std::max(0.0,
      third.StandardError * third.StandardError - second.StandardError * second.StandardError));
  const double difference =
    std::max(std::fabs(second.Curvature.MinimumCurvature - third.Curvature.MinimumCurvature),
      std::fabs(second.Curvature.MaximumCurvature - third.Curvature.MaximumCurvature));
  OrientedCircleResult simpler = difference <= allowed ? second : third;
  simpler.OrderDiscrepancy = difference;
  return simpler;
}

/// The positions' noise (the RMS height of the neighbors over the fitted
/// surface) at the first radius, as a fraction of that radius, below which
/// the oriented circles' ladder estimates the point instead: there the
/// positions carry the curvature as well as the normals, and the circles'
/// fits of the fourth order and the height jets at the smallest radii
/// follow fast-varying curvature that a fit of the normal field (two orders
/// lower in the positions) needs more neighbors for.
constexpr double PreciseNoiseRatio = 0.06;

/// The fewest neighbors of a radius whose estimate judges the wider radii
/// (Lepski's rule): at fewer, a few rows per unknown, the residual
/// understates the error too often (the estimate is still a candidate).
constexpr int ReferenceNeighbors = 24;

/// The positions' noise, as a fraction of a radius, above which that
/// radius judges the wider ones only once the next radius agreed with it:
/// with noise that large against the neighborhood the errors of its
/// abscissae make chance outliers of its estimate that its residual does
/// not show, and one would stop every wider radius.
constexpr double ConfirmedNoiseRatio = 0.07;

/// The reported error over the root sum of its parts: the rows' residual
/// misses that a neighbor's noise moves the abscissae of both its rows and
/// that the query point's own displacement along the surface moves where
/// the curvature is evaluated; calibrated on the survey's clouds with
/// position noise and exact normals (Study/REPORT.md).
constexpr double NormalFieldErrorFactor = 1.3;

/// Whether the surface turns through more than LargestTurn across the
/// fit's neighborhood, beyond what noise makes of its curvatures.
bool TurnsPastModel(const OrientedCircleResult& fit, double radius, double tolerance)
{
  const PointCurvature& k = fit.Curvature;
  const double largest = std::max(std::fabs(k.MinimumCurvature), std::fabs(k.MaximumCurvature));
  return radius * (largest - tolerance * fit.StandardError) > LargestTurn;
}

/// Appends a shell's offsets (in units of the first radius).
void AppendShell(const ShellPoints& shell,
  double inverseUnit,
  std::array<std::vector<double>, 3>& gathered)
{
  const std::vector<double>* axes[3] = { &shell.Dx, &shell.Dy, &shell.Dz };
  for (int k = 0; k < 3; ++k)
  {
    std::vector<double>& to = gathered[k];
    const double* from = axes[k]->data();
    for (std::size_t i = 0; i < shell.Count; ++i)
    {
      to.push_back(from[i] * inverseUnit);
    }
  }
}

/// The positions' noise at the first radius (the RMS height of the
/// neighbors over `surface`, fitted there), in units of that radius.
double PositionsNoise(const FittedSurface& surface,
  const TangentFrame& frame,
  const std::array<std::vector<double>, 3>& gathered)
{
  FittedSurface heights = surface;
  SetHeightOfPoints(
    frame, gathered[0].data(), gathered[1].data(), gathered[2].data(), gathered[0].size(), heights);
  return std::sqrt(heights.NoiseVariance);
}

/// The estimates of the ladder's radii that judge the wider ones, and the
/// one waiting for the next radius's agreement (ConfirmedNoiseRatio).
class LadderReferences
{
public:
  /// `kept` and `waiting`: a thread's reusable buffers, emptied here.
  LadderReferences(std::vector<OrientedCircleResult>& kept,
    std::vector<OrientedCircleResult>& waiting,
    double tolerance)
    : Kept(kept)
    , Waiting(waiting)
    , Tolerance(tolerance)
  {
    this->Kept.clear();
    this->Waiting.clear();
  }

  /// Lepski's test of `candidate` against the references.
  bool Agree(const OrientedCircleResult& candidate) const
  {
    return AutomaticScaleEstimator::AgreesWithSmaller(candidate, this->Kept, this->Tolerance);
  }

  /// An accepted estimate: it confirms the waiting one if it agrees with
  /// it, and becomes a reference itself (now, or once the next confirms it
  /// where `confirm`) if it has ReferenceNeighbors.
  void Add(const OrientedCircleResult& accepted, bool confirm)
  {
    if (!this->Waiting.empty() &&
      AutomaticScaleEstimator::AgreesWithSmaller(accepted, this->Waiting, this->Tolerance))
    {
      this->Kept.push_back(this->Waiting.front());
    }
    this->Waiting.clear();
    if (accepted.Curvature.NeighborCount >= ReferenceNeighbors)
    {
      (confirm ? this->Waiting : this->Kept).push_back(accepted);
    }
  }

private:
  std::vector<OrientedCircleResult>& Kept;
  /// At most one: the estimate waiting for the next radius's agreement.
  std::vector<OrientedCircleResult>& Waiting;
  double Tolerance;
};

/// The normal field's ladder's choice at a point: the radius kept so far,
/// the one before it, and why none was kept where none was.
struct FieldChoice
{
  OrientedCircleResult Chosen, Before;
  double Radius = std::numeric_limits<double>::quiet_NaN();
  /// The offsets gathered up to the chosen radius.
  std::size_t Count = 0;
  UnestimatedReason Reason = UnestimatedReason::TooFewNeighbors;

  /// Judges the fit `result` at `r` (of `count` offsets gathered) against
  /// `references` and keeps it where it passes; false where the growth
  /// ends there. `confirm`: a reference only once the next radius agrees.
  bool Judge(const OrientedCircleResult& result,
    double r,
    bool confirm,
    std::size_t count,
    const AutomaticScaleRule& rule,
    const FitSettings& settings,
    LadderReferences& references)
  {
    this->Reason = result.Curvature.Valid
      ? UnestimatedReason::TooFewNeighbors
      : UnestimatedReasonOf(result.Curvature, settings.MinimumPointsPerDirection);
    if (result.Curvature.Valid && result.Curvature.NeighborCount >= rule.MinimumCount)
    {
      if (!references.Agree(result) ||
        (TurnsPastModel(result, r, rule.Tolerance) && this->Chosen.Curvature.Valid))
      {
        return false;
      }
      references.Add(result, confirm);
      this->Before = this->Chosen;
      this->Chosen = result;
      this->Radius = r;
      this->Count = count;
      // More neighbors would not change the estimate measurably: done. (Not
      // against the inverse of this radius, as the circles' ladder: the
      // normals' precise rows reach that early on a dense cloud, long
      // before the noise is averaged; flat parts grow to the largest.)
      const double magnitude = std::max({ std::fabs(result.Curvature.MinimumCurvature),
        std::fabs(result.Curvature.MaximumCurvature),
        1.0 / rule.LargestRadius });
      if (result.StandardError < rule.Precision * magnitude)
      {
        return false;
      }
    }
    return true;
  }

  /// The estimate of the chosen radius, its surface's height and noise
  /// from the offsets `gathered` up to it.
  ScaleEstimate Estimate(const TangentFrame& frame,
    const std::array<std::vector<double>, 3>& gathered,
    double precision)
  {
    OrientedCircleResult& chosen = this->Chosen;
    if (!chosen.Curvature.Valid)
    {
      chosen.Curvature.Reason = this->Reason;
    }
    else
    {
      // The height and the positions' noise of the surface a point near this
      // one may take (SharedFits.h).
      SetHeightOfPoints(frame,
        gathered[0].data(),
        gathered[1].data(),
        gathered[2].data(),
        this->Count,
        chosen.Surface);
    }
    const OrientedCircleResult* previous = this->Before.Curvature.Valid ? &this->Before : nullptr;
    return ScaleEstimate{ chosen,
      this->Radius,
      NormalFieldErrorFactor * ReportedStandardError(chosen, previous, precision) };
  }
};
} // namespace

bool AutomaticScaleEstimator::EstimateNormalField(std::int64_t point,
  AutomaticScaleScratch& scratch,
  ScaleEstimate& estimate) const
{
  const double* x = &this->Cloud.Coordinates[3 * point];
  const double* n = &this->Cloud.Normals[3 * point];
  const AutomaticScaleRule& rule = this->Rule;
  const double unit =
    std::nextafter(std::min(this->FirstRadius(x, scratch), rule.LargestRadius), HUGE_VAL);
  const double inverseUnit = 1.0 / unit;
  const TangentFrame frame = MakeTangentFrame({ { n[0], n[1], n[2] } });
  NormalFieldAccumulator& field = scratch.Field;
  field.Begin(frame);
  std::array<std::vector<double>, 3>& gathered = scratch.Gathered;
  for (std::vector<double>& axis : gathered)
  {
    axis.clear();
  }
  LadderReferences references(scratch.Scales, scratch.Waiting, rule.Tolerance);
  FieldChoice choice;
  double inner = 0.0, noise = 0.0;
  for (int level = 0; level < rule.Levels; ++level)
  {
    const double r = std::min(unit * std::pow(2.0, 0.5 * level), rule.LargestRadius);
    this->GatherLevel(x, inner, r, scratch);
    this->AddShell(scratch.Shell, inverseUnit, field);
    AppendShell(scratch.Shell, inverseUnit, gathered);
    inner = r;
    const NormalFieldSums& sums = field.Sums();
    if (sums.ReachesAcross(this->Settings.MaximumOpposingFraction))
    {
      choice.Reason = UnestimatedReason::ReachesAcross;
      break;
    }
    const OrientedCircleResult result = FitSimplerField(sums, frame, inverseUnit, this->Settings);
    if (!(noise > 0.0) && result.Curvature.Valid)
    {
      // At the first radius fitted.
      noise = PositionsNoise(result.Surface, frame, gathered);
      if (noise < PreciseNoiseRatio * r * inverseUnit)
      {
        return false;
      }
    }
    const bool confirm = noise > ConfirmedNoiseRatio * r * inverseUnit;
    if (!choice.Judge(result, r, confirm, gathered[0].size(), rule, this->Settings, references))
    {
      break;
    }
    if (r >= rule.LargestRadius)
    {
      break;
    }
  }
  estimate = choice.Estimate(frame, gathered, rule.Precision);
  return true;
}

} // namespace pcurv
