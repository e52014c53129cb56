// Tests of the dynamic variable adjustment: the core state machine, and the
// filter on a torus whose density varies tenfold around it, with and
// without position noise, against a sweep of fixed radii; scale freedom and
// independence from the thread count.
#include "AnalyticClouds.h"
#include "Scale/DynamicAdjustment.h"
#include "TestChecks.h"
#include "vtkPrincipalCurvatureEstimation.h"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <vector>

namespace
{
using namespace pcurv::testing;

void TestStateMachine(Checks& checks)
{
  pcurv::DynamicAdjustment adjustment;
  checks.Near("initial s", adjustment.GetSurroundingsThreshold(), 4.0, 0.0);
  checks.Equal("initial level", adjustment.GetLevel(), 0);
  // Exactly the target: p = p_t, s unchanged.
  checks.Near("p at the target count", adjustment.Adjust(375), 0.1, 1e-15);
  checks.Near("s at the target count", adjustment.GetSurroundingsThreshold(), 4.0, 1e-15);
  // Four times too many points: s halves (area), p = 0.1 / 4.
  checks.Near("p with 4x the points", adjustment.Adjust(1500), 0.025, 1e-15);
  checks.Near("s with 4x the points", adjustment.GetSurroundingsThreshold(), 2.0, 1e-15);
  checks.Equal("s = 2 is not below 2", adjustment.GetLevel(), 0);
  adjustment.Adjust(376); // s just below 2: second combination
  checks.Equal("below 2: level 1", adjustment.GetLevel(), 1);
  checks.Near("level 1 target p", adjustment.Adjust(750), 0.05, 1e-15);
  adjustment.Adjust(4 * 750); // s halves to below 1: third combination
  checks.Equal("below 1: level 2", adjustment.GetLevel(), 2);
  adjustment.Adjust(1500 / 64); // s grows 8x to above 4: one step back
  checks.Equal("above 4: back to level 1", adjustment.GetLevel(), 1);
  adjustment.Adjust(0); // no neighbor: s grows, no division by zero
  checks.True("no neighbor: s finite", std::isfinite(adjustment.GetSurroundingsThreshold()));
  adjustment.Restart();
  checks.Near("restart s", adjustment.GetSurroundingsThreshold(), 4.0, 0.0);
  checks.Equal("restart level", adjustment.GetLevel(), 0);

  pcurv::AdjustmentSettings scaled;
  scaled.LengthUnit = 1e-3;
  pcurv::DynamicAdjustment millimetres(scaled);
  checks.Near("length unit scales s", millimetres.GetSurroundingsThreshold(), 4e-3, 1e-18);
  checks.Near("length unit scales p", millimetres.Adjust(375), 1e-4, 1e-18);
}

/// The constants' convenience setters set the three vectors.
void TestConstantSetters(Checks& checks)
{
  vtkNew<vtkPrincipalCurvatureEstimation> fresh, filter;
  filter->SetAdjustmentConstantsToBandedLadder(1000, 0.6);
  const double* counts = filter->GetTargetNeighborCounts();
  const double* planes = filter->GetTargetPlaneDistances();
  const double* switches = filter->GetSwitchLengths();
  checks.True("ladder counts 1000, 2000, 4000",
    counts[0] == 1000.0 && counts[1] == 2000.0 && counts[2] == 4000.0);
  checks.True("ladder plane distances 0.6 at every level",
    planes[0] == 0.6 && planes[1] == 0.6 && planes[2] == 0.6);
  checks.True("ladder switch lengths 4.5, 3.2, 7.2",
    switches[0] == 4.5 && switches[1] == 3.2 && switches[2] == 7.2);
  vtkNew<vtkPrincipalCurvatureEstimation> preset;
  preset->SetFitModeToNew01(); // the paper's fit
  preset->SetAdjustmentConstantsToPreset(vtkPrincipalCurvatureEstimation::NOISY_LADDER);
  bool samePreset = true;
  for (int i = 0; i < 3; ++i)
  {
    samePreset = samePreset && preset->GetTargetNeighborCounts()[i] == counts[i] &&
      preset->GetTargetPlaneDistances()[i] == planes[i] &&
      preset->GetSwitchLengths()[i] == switches[i];
  }
  checks.True("the noisy-ladder preset is BandedLadder(1000, 0.6)", samePreset);
  preset->SetAdjustmentConstantsToPreset(vtkPrincipalCurvatureEstimation::LADDER);
  checks.True("the ladder preset is BandedLadder(375, 0.2)",
    preset->GetTargetNeighborCounts()[0] == 375.0 &&
      preset->GetTargetNeighborCounts()[2] == 1500.0 &&
      preset->GetTargetPlaneDistances()[1] == 0.2 && preset->GetSwitchLengths()[0] == 4.5);
  filter->SetAdjustmentConstantsToPaper();
  bool same = true;
  for (int i = 0; i < 3; ++i)
  {
    same = same && filter->GetTargetNeighborCounts()[i] == fresh->GetTargetNeighborCounts()[i] &&
      filter->GetTargetPlaneDistances()[i] == fresh->GetTargetPlaneDistances()[i] &&
      filter->GetSwitchLengths()[i] == fresh->GetSwitchLengths()[i];
  }
  checks.True("the paper's constants are the defaults", same);
}

/// Whether to compare with sweeps of fixed radii: a study as well as a
/// test, run once (not under the sanitizers, which make it several times
/// slower, nor where PCURV_SKIP_SWEEPS is set: the second registration, on
/// the portable kernels, whose results the other tests compare already).
bool RunSweeps()
{
  return !UnderSanitizers && std::getenv("PCURV_SKIP_SWEEPS") == nullptr;
}

/// A torus whose density falls tenfold from the +x side to the -x side.
vtkSmartPointer<vtkPolyData> VaryingDensityTorus(double noiseInSpacings)
{
  std::vector<SurfaceSample> all = Sample(Torus(3.0, 1.0), 120000, 3);
  Random random(10);
  std::vector<SurfaceSample> kept;
  for (const SurfaceSample& s : all)
  {
    const double phi = std::atan2(s.Point[1], s.Point[0]);
    if (random.Uniform() < 0.1 + 0.9 * 0.5 * (1.0 + std::cos(phi)))
    {
      kept.push_back(s);
    }
  }
  if (noiseInSpacings > 0.0)
  {
    const double area = 4.0 * Pi * Pi * 3.0 * 1.0;
    AddPositionNoise(kept, noiseInSpacings * std::sqrt(area / kept.size()), 11);
  }
  return MakeCloud(kept);
}

struct Result
{
  double Error;             // mean of the k_min and k_max errors
  double CountP5, CountP95; // of Neighbor_Count / Target_Neighbor_Count, worst quarter
  double Unestimated;       // fraction of the evaluated points
};

double Percentile(std::vector<double> values, double fraction)
{
  std::sort(values.begin(), values.end());
  return values[static_cast<size_t>(fraction * (values.size() - 1))];
}

Result Run(vtkPrincipalCurvatureEstimation* filter, vtkPolyData* cloud, const char* label)
{
  filter->SetInputData(cloud);
  filter->Update();
  const CurvatureErrors e = MeasureErrors(filter->GetOutput());
  vtkPointData* pd = filter->GetOutput()->GetPointData();
  vtkDataArray* counts = pd->GetArray("Neighbor_Count");
  vtkDataArray* targets = pd->GetArray("Target_Neighbor_Count");
  Result r{ 0.5 * (e.MeanMinimumError + e.MeanMaximumError), 0.0, 0.0, e.UnestimatedFraction };
  std::printf("  %-44s error %.4f (k_min %.4f, k_max %.4f) unestimated %.4f",
    label,
    r.Error,
    e.MeanMinimumError,
    e.MeanMaximumError,
    e.UnestimatedFraction);
  if (targets)
  {
    // The band in each quarter of the torus (by the angle around its axis,
    // densest first), so that it holds on the dense and the sparse side.
    std::vector<double> ratios[4], t(targets->GetNumberOfTuples());
    vtkPolyData* output = filter->GetOutput();
    for (vtkIdType i = 0; i < counts->GetNumberOfTuples(); ++i)
    {
      double x[3];
      output->GetPoint(i, x);
      const double c = std::cos(std::atan2(x[1], x[0]));
      const int quarter = c > 0.5 ? 0 : c > 0.0 ? 1 : c > -0.5 ? 2 : 3;
      ratios[quarter].push_back(counts->GetTuple1(i) / targets->GetTuple1(i));
      t[i] = targets->GetTuple1(i);
    }
    r.CountP5 = 1e300;
    std::printf(" count/target p5-p95 by quarter");
    for (const std::vector<double>& quarter : ratios)
    {
      const double p5 = Percentile(quarter, 0.05), p95 = Percentile(quarter, 0.95);
      r.CountP5 = std::min(r.CountP5, p5);
      r.CountP95 = std::max(r.CountP95, p95);
      std::printf(" %.2f-%.2f", p5, p95);
    }
    std::printf(" (targets %.0f..%.0f)", Percentile(t, 0.0), Percentile(t, 1.0));
  }
  std::printf("\n");
  return r;
}

/// The smallest error of a sweep of fixed radii and plane distances. The
/// best radius must lie inside the sweep, else the sweep did not find it.
double BestFixedRadius(Checks& checks,
  vtkPolyData* cloud,
  std::initializer_list<double> radii,
  std::initializer_list<double> ratios,
  const char* what)
{
  double best = 1e300, bestRadius = 0.0;
  for (const double s : radii)
  {
    for (const double ratio : ratios)
    {
      vtkNew<vtkPrincipalCurvatureEstimation> fixed;
      fixed->SetFitModeToNew01(); // the paper's fit
      fixed->AutomaticThresholdsOff();
      fixed->SetSurroundingsThreshold(s);
      fixed->SetPlaneDistanceThreshold(ratio * s);
      char label[64];
      std::snprintf(label, sizeof(label), "fixed s = %.2f, p = %.3f s", s, ratio);
      const double error = Run(fixed, cloud, label).Error;
      if (error < best)
      {
        best = error;
        bestRadius = s;
      }
    }
  }
  std::printf("  best fixed radius: s = %.2f, error %.4f\n", bestRadius, best);
  char label[96];
  std::snprintf(label, sizeof(label), "the best fixed radius lies inside the sweep (%s)", what);
  checks.True(label, bestRadius > *radii.begin() && bestRadius < *(radii.end() - 1));
  return best;
}

/// The documented band: in every quarter of the torus, 90% of the points
/// within -20% / +25% of the target count of their combination.
void CheckCountBand(Checks& checks, const Result& r, const char* what)
{
  char label[128];
  std::snprintf(label, sizeof(label), "%s: neighbor count p5 >= 0.8 x target", what);
  checks.True(label, r.CountP5 >= 0.8);
  std::snprintf(label, sizeof(label), "%s: neighbor count p95 <= 1.25 x target", what);
  checks.True(label, r.CountP95 <= 1.25);
}

void TestVaryingDensity(Checks& checks)
{
  std::printf("noise-free torus, density varying 10x:\n");
  auto clean = VaryingDensityTorus(0.0);
  vtkNew<vtkPrincipalCurvatureEstimation> byDefault;
  byDefault->SetFitModeToNew01(); // the paper's fit
  const double defaultError = Run(byDefault, clean, "filter default (fixed, automatic)").Error;
  vtkNew<vtkPrincipalCurvatureEstimation> paper;
  paper->SetFitModeToNew01(); // the paper's fit
  paper->DynamicAdjustmentOn();
  const Result paperResult = Run(paper, clean, "DVA, paper's targets");
  vtkNew<vtkPrincipalCurvatureEstimation> ladder;
  ladder->SetFitModeToNew01(); // the paper's fit
  ladder->DynamicAdjustmentOn();
  ladder->SetAdjustmentConstantsToPreset(vtkPrincipalCurvatureEstimation::LADDER);
  const Result ladderResult = Run(ladder, clean, "DVA, banded ladder 375, p = 0.2 L");
  checks.Below(
    "DVA (paper) beats the default fixed radius (noise-free)", paperResult.Error, defaultError);
  checks.Below(
    "DVA (ladder) beats the default fixed radius (noise-free)", ladderResult.Error, defaultError);
  // Errors are means over the estimated points: the ladder's must be all.
  checks.Below(
    "DVA (ladder) leaves at most 0.1% unestimated (noise-free)", ladderResult.Unestimated, 0.001);
  CheckCountBand(checks, paperResult, "paper, noise-free");
  CheckCountBand(checks, ladderResult, "ladder, noise-free");
  if (RunSweeps())
  {
    const double best = BestFixedRadius(
      checks, clean, { 0.3, 0.4, 0.5, 0.6, 0.75 }, { 0.025, 0.1, 0.2 }, "noise-free");
    // Measured: the paper's targets 1.28x the best fixed radius (s = 0.5,
    // p = s / 40, which leaves 3.5% of the points unestimated; 0.98x the
    // best that estimates them all); the banded ladder 1.06x, every point
    // estimated. The paper's constant count takes the sparse side's radius
    // beyond what the curvature there allows; the ladder steps down to
    // fewer neighbors.
    checks.Below("DVA (ladder) within 10% of the best fixed radius (noise-free)",
      ladderResult.Error,
      1.1 * best);
    checks.Below("DVA (paper) within 1.4x of the best fixed radius (noise-free)",
      paperResult.Error,
      1.4 * best);
  }

  std::printf("torus, density varying 10x, noise 0.5 spacing:\n");
  auto noisy = VaryingDensityTorus(0.5);
  vtkNew<vtkPrincipalCurvatureEstimation> noisyDefault;
  noisyDefault->SetFitModeToNew01(); // the paper's fit
  const double noisyDefaultError =
    Run(noisyDefault, noisy, "filter default (fixed, automatic)").Error;
  vtkNew<vtkPrincipalCurvatureEstimation> thick;
  thick->SetFitModeToNew01(); // the paper's fit
  thick->DynamicAdjustmentOn();
  thick->SetTargetPlaneDistances(0.4, 0.2, 0.1); // p = s / 10 at the targets
  const Result thickResult = Run(thick, noisy, "DVA, paper's counts, p = s / 10");
  checks.Below(
    "DVA (p = s/10) beats the default fixed radius (noisy)", thickResult.Error, noisyDefaultError);
  vtkNew<vtkPrincipalCurvatureEstimation> noisyLadder;
  noisyLadder->SetFitModeToNew01(); // the paper's fit
  noisyLadder->DynamicAdjustmentOn();
  noisyLadder->SetAdjustmentConstantsToPreset(vtkPrincipalCurvatureEstimation::NOISY_LADDER);
  const Result noisyLadderResult = Run(noisyLadder, noisy, "DVA, banded ladder 1000, p = 0.6 L");
  checks.Below("DVA (ladder) beats the default fixed radius (noisy)",
    noisyLadderResult.Error,
    noisyDefaultError);
  if (RunSweeps())
  {
    const double noisyBest =
      BestFixedRadius(checks, noisy, { 0.6, 0.7, 0.8, 0.9, 1.0, 1.2 }, { 0.1, 0.15, 0.2 }, "noisy");
    // Measured: 1.05x (1.04-1.08x over seeds, densities varying 5x to 20x,
    // and noise of 1 spacing; docs/dynamic-adjustment.md).
    checks.Below("DVA (ladder) within 10% of the best fixed radius (noisy)",
      noisyLadderResult.Error,
      1.1 * noisyBest);
  }
  checks.Below(
    "DVA (ladder) leaves at most 0.1% unestimated (noisy)", noisyLadderResult.Unestimated, 0.001);
  CheckCountBand(checks, thickResult, "paper's counts, noisy");
  CheckCountBand(checks, noisyLadderResult, "ladder, noisy");
}

vtkSmartPointer<vtkPolyData> RunAdjusted(vtkPolyData* cloud, int threads, double blockLength = 8.0)
{
  vtkNew<vtkPrincipalCurvatureEstimation> filter;
  filter->SetFitModeToNew01(); // the paper's fit
  filter->DynamicAdjustmentOn();
  filter->SetNumberOfThreads(threads);
  filter->SetAdjustmentBlockLength(blockLength);
  filter->SetInputData(cloud);
  filter->Update();
  auto output = vtkSmartPointer<vtkPolyData>::New();
  output->ShallowCopy(filter->GetOutput());
  return output;
}

bool SameArray(vtkPolyData* a, vtkPolyData* b, const char* name)
{
  vtkDataArray* x = a->GetPointData()->GetArray(name);
  vtkDataArray* y = b->GetPointData()->GetArray(name);
  return x->GetNumberOfValues() == y->GetNumberOfValues() &&
    std::memcmp(x->GetVoidPointer(0),
      y->GetVoidPointer(0),
      x->GetNumberOfValues() * x->GetDataTypeSize()) == 0;
}

void TestThreadsAndScale(Checks& checks)
{
  auto cloud = MakeCloud(Sample(Torus(3.0, 1.0), 40000, 17));
  auto one = RunAdjusted(cloud, 1);
  auto two = RunAdjusted(cloud, 2);
  for (const char* name : { "Minimum_Curvature",
         "Maximum_Curvature",
         "Maximum_Curvature_Direction",
         "Surroundings_Threshold",
         "Plane_Distance_Threshold",
         "Neighbor_Count" })
  {
    char label[96];
    std::snprintf(label, sizeof(label), "DVA %s identical with 1 and 2 threads", name);
    checks.True(label, SameArray(one, two, name));
  }
  auto otherBlocks = RunAdjusted(cloud, 2, 20.0);
  checks.True("the block size, not the threads, decides",
    !SameArray(one, otherBlocks, "Surroundings_Threshold"));

  // The same cloud in millimetres: curvatures / 1000.
  auto millimetres = vtkSmartPointer<vtkPolyData>::New();
  millimetres->DeepCopy(cloud);
  vtkPoints* points = millimetres->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double x[3];
    points->GetPoint(i, x);
    points->SetPoint(i, 1000.0 * x[0], 1000.0 * x[1], 1000.0 * x[2]);
  }
  auto scaled = RunAdjusted(millimetres, 0);
  double worst = 0.0;
  vtkIdType compared = 0;
  for (const char* name : { "Minimum_Curvature", "Maximum_Curvature" })
  {
    vtkDataArray* a = one->GetPointData()->GetArray(name);
    vtkDataArray* b = scaled->GetPointData()->GetArray(name);
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    {
      const double reference = a->GetTuple1(i);
      if (std::fabs(reference) > 1e-3)
      {
        worst =
          std::max(worst, std::fabs(1000.0 * b->GetTuple1(i) - reference) / std::fabs(reference));
        ++compared;
      }
    }
  }
  std::printf("scale 1000: largest relative difference %.3g over %lld values\n",
    worst,
    static_cast<long long>(compared));
  checks.True("values compared", compared > 40000);
  checks.Below("scale-free: cloud x 1000 gives curvatures / 1000", worst, 1e-9);
}
} // namespace

int main()
{
  Checks checks;
  if (!RunSweeps())
  {
    std::printf("the sweeps of fixed radii are left out (sanitizers or PCURV_SKIP_SWEEPS)\n");
  }
  TestStateMachine(checks);
  TestConstantSetters(checks);
  TestVaryingDensity(checks);
  TestThreadsAndScale(checks);
  return checks.Summary();
}
