// Tests of the dynamic variable adjustment: the core state machine, and the
// filter on a torus whose density varies tenfold around it, with and
// without position noise, against a sweep of fixed radii; scale freedom and
// independence from the thread count.
#include "AnalyticClouds.h"
#include "DynamicAdjustment.h"
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
#include <cstring>
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
  adjustment.Adjust(0); // no neighbour: s grows, no division by zero
  checks.True("no neighbour: s finite", std::isfinite(adjustment.GetSurroundingsThreshold()));
  adjustment.Restart();
  checks.Near("restart s", adjustment.GetSurroundingsThreshold(), 4.0, 0.0);
  checks.Equal("restart level", adjustment.GetLevel(), 0);

  pcurv::AdjustmentSettings scaled;
  scaled.LengthUnit = 1e-3;
  pcurv::DynamicAdjustment millimetres(scaled);
  checks.Near("length unit scales s", millimetres.GetSurroundingsThreshold(), 4e-3, 1e-18);
  checks.Near("length unit scales p", millimetres.Adjust(375), 1e-4, 1e-18);
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
  double Error; // mean of the k_min and k_max errors
  double CountP5, CountP95;
};

Result Run(vtkPrincipalCurvatureEstimation* filter, vtkPolyData* cloud, const char* label)
{
  filter->SetInputData(cloud);
  filter->Update();
  const CurvatureErrors e = MeasureErrors(filter->GetOutput());
  vtkDataArray* counts = filter->GetOutput()->GetPointData()->GetArray("Neighbor_Count");
  std::vector<double> c(counts->GetNumberOfTuples());
  for (vtkIdType i = 0; i < counts->GetNumberOfTuples(); ++i)
  {
    c[i] = counts->GetTuple1(i);
  }
  std::sort(c.begin(), c.end());
  Result r{
    0.5 * (e.MeanMinimumError + e.MeanMaximumError), c[c.size() / 20], c[c.size() * 19 / 20]
  };
  std::printf(
    "  %-40s error %.4f (k_min %.4f, k_max %.4f) unestimated %.4f neighbours p5 %.0f p95 %.0f\n",
    label,
    r.Error,
    e.MeanMinimumError,
    e.MeanMaximumError,
    e.UnestimatedFraction,
    r.CountP5,
    r.CountP95);
  return r;
}

double BestFixedRadius(vtkPolyData* cloud)
{
  double best = 1e300;
  for (const double s : { 0.33, 0.4, 0.5, 0.6, 0.75, 0.9 })
  {
    vtkNew<vtkPrincipalCurvatureEstimation> fixed;
    fixed->AutomaticThresholdsOff();
    fixed->SetSurroundingsThreshold(s);
    fixed->SetPlaneDistanceThreshold(0.1 * s);
    char label[64];
    std::snprintf(label, sizeof(label), "fixed s = %.2f, p = s / 10", s);
    best = std::min(best, Run(fixed, cloud, label).Error);
  }
  return best;
}

void TestVaryingDensity(Checks& checks)
{
  std::printf("noise-free torus, density varying 10x:\n");
  auto clean = VaryingDensityTorus(0.0);
  vtkNew<vtkPrincipalCurvatureEstimation> byDefault;
  const double defaultError = Run(byDefault, clean, "filter default (fixed, automatic)").Error;
  vtkNew<vtkPrincipalCurvatureEstimation> paper;
  paper->DynamicAdjustmentOn();
  const Result adjusted = Run(paper, clean, "DVA, paper's targets");
  const double best = BestFixedRadius(clean);
  checks.Below("DVA beats the default fixed radius (noise-free)", adjusted.Error, defaultError);
  checks.Below("DVA within 10% of the best fixed radius (noise-free)", adjusted.Error, 1.1 * best);
  // The documented band: 90% of the points within -20% / +25% of the target.
  checks.True("neighbour count p5 >= 0.8 x 375", adjusted.CountP5 >= 0.8 * 375);
  checks.True("neighbour count p95 <= 1.25 x 375", adjusted.CountP95 <= 1.25 * 375);

  std::printf("torus, density varying 10x, noise 0.5 spacing:\n");
  auto noisy = VaryingDensityTorus(0.5);
  vtkNew<vtkPrincipalCurvatureEstimation> noisyDefault;
  const double noisyDefaultError =
    Run(noisyDefault, noisy, "filter default (fixed, automatic)").Error;
  vtkNew<vtkPrincipalCurvatureEstimation> thick;
  thick->DynamicAdjustmentOn();
  thick->SetTargetPlaneDistances(0.4, 0.2, 0.1); // p = s / 10 at the targets
  const Result thickResult = Run(thick, noisy, "DVA, 375 neighbours, p = s / 10");
  checks.Below(
    "DVA (p = s/10) beats the default fixed radius (noisy)", thickResult.Error, noisyDefaultError);
  vtkNew<vtkPrincipalCurvatureEstimation> large;
  large->DynamicAdjustmentOn();
  large->SetTargetNeighborCounts(1500, 3000, 6000);
  large->SetTargetPlaneDistances(0.4, 0.2, 0.1);
  const Result largeResult = Run(large, noisy, "DVA, 1500 neighbours, p = s / 10");
  const double noisyBest = BestFixedRadius(noisy);
  // With noise of a fixed absolute size, a fixed radius wins: equal counts
  // give the dense side a smaller radius, and the noise's effect on a fitted
  // curvature grows as the radius shrinks. Measured (New01, the default):
  // 0.0200 against the best fixed radius's 0.0177 (s = 0.9), 1.13x; the best
  // of a sweep of targets, plane distances and switch lengths was 1.11x.
  // Guard against it growing.
  checks.Below("DVA (1500, p = s/10) within 1.25x of the best fixed radius (noisy)",
    largeResult.Error,
    1.25 * noisyBest);
  checks.True("noisy neighbour count p5 >= 0.8 x 1500", largeResult.CountP5 >= 0.8 * 1500);
  checks.True("noisy neighbour count p95 <= 1.25 x 1500", largeResult.CountP95 <= 1.25 * 1500);
}

vtkSmartPointer<vtkPolyData> RunAdjusted(vtkPolyData* cloud, int threads, double blockLength = 8.0)
{
  vtkNew<vtkPrincipalCurvatureEstimation> filter;
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
  TestStateMachine(checks);
  TestVaryingDensity(checks);
  TestThreadsAndScale(checks);
  return checks.Summary();
}
