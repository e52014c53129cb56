// Outliers (no VTK): points far off the surface their neighbors sample are
// flagged, pull no neighbor's fit or normal, and get the curvatures of the
// surface nearest to them; clean and noisy clouds, steps and edges keep
// their points; the verdicts do not depend on threads or the input order.
#include "CloudTestSupport.h"

#include <numeric>
#include <random>

namespace
{
using namespace pcurv;
using namespace cloudtest;

constexpr double Radius = 2.0;
constexpr std::size_t Points = 20000;

/// The spacing of n points spread evenly on a sphere of radius Radius.
double SphereSpacing(std::size_t n)
{
  return std::sqrt(4.0 * 3.141592653589793 * Radius * Radius / static_cast<double>(n));
}

/// A sphere with 5 % of its points moved by Gaussian noise of ten spacings
/// (their normals and exact values stay those of the point they left).
std::vector<testing::SurfaceSample> StraySphere(std::vector<bool>& moved)
{
  auto sphere = testing::Sample(testing::Sphere(Radius), Points, 41);
  moved = testing::AddOutliers(sphere, 0.05, 10.0 * SphereSpacing(Points), 42);
  return sphere;
}

/// Root mean square of max(|dk_min|, |dk_max|) over the points of `which`
/// (unestimated points count as k = 0, as the survey counts them).
double RootMeanSquare(const std::vector<testing::SurfaceSample>& samples,
  const Results& r,
  const std::vector<bool>& which,
  bool wanted)
{
  double sum = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    if (which[i] == wanted)
    {
      const double error = r.Valid[i]
        ? PointError(r, samples, i)
        : std::max(std::fabs(samples[i].MinimumCurvature), std::fabs(samples[i].MaximumCurvature));
      sum += error * error;
      ++count;
    }
  }
  return count ? std::sqrt(sum / count) : 0.0;
}

/// The median of max(|dk_min|, |dk_max|) over the estimated points of
/// `which` (flagged ones only with `flaggedOnly`).
double MedianError(const std::vector<testing::SurfaceSample>& samples,
  const Results& r,
  const std::vector<bool>& which,
  bool flaggedOnly)
{
  std::vector<double> errors;
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    if (which[i] && r.Valid[i] && (!flaggedOnly || r.Outlier[i]))
    {
      errors.push_back(PointError(r, samples, i));
    }
  }
  std::sort(errors.begin(), errors.end());
  return errors.empty() ? HUGE_VAL : errors[errors.size() / 2];
}

/// The points farther than `spacings` from the sphere.
std::vector<bool> FarFromSphere(const std::vector<testing::SurfaceSample>& samples, double spacings)
{
  std::vector<bool> far(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    const double distance =
      std::fabs(std::sqrt(testing::Dot(samples[i].Point, samples[i].Point)) - Radius);
    far[i] = distance > spacings * SphereSpacing(samples.size());
  }
  return far;
}

int CountFlagged(const Results& r, const std::vector<bool>& which, bool wanted)
{
  int count = 0;
  for (std::size_t i = 0; i < which.size(); ++i)
  {
    count += which[i] == wanted && r.Outlier[i] ? 1 : 0;
  }
  return count;
}

/// The far points of a stray sphere, estimated with its outliers moved
/// (`r`) and kept in place (`kept`): how many are flagged, and how far off
/// their curvatures are, printed.
struct StrayScores
{
  int Far = 0, FarFlagged = 0, UnmovedFlagged = 0;
  double FarMedian = 0.0, KeptFarMedian = 0.0, FarRms = 0.0, KeptFarRms = 0.0;
};

StrayScores ScoreStrays(const char* label,
  const std::vector<testing::SurfaceSample>& sphere,
  const std::vector<bool>& moved,
  const Results& r,
  const Results& kept)
{
  const std::vector<bool> far = FarFromSphere(sphere, 3.0);
  StrayScores s;
  s.Far = static_cast<int>(std::count(far.begin(), far.end(), true));
  s.FarFlagged = CountFlagged(r, far, true);
  s.UnmovedFlagged = CountFlagged(r, moved, false);
  s.FarMedian = MedianError(sphere, r, far, false);
  s.KeptFarMedian = MedianError(sphere, kept, far, false);
  s.FarRms = RootMeanSquare(sphere, r, far, true);
  s.KeptFarRms = RootMeanSquare(sphere, kept, far, true);
  std::printf("%s: %d of %d far points flagged, %d unmoved; far points' median error %.4f (kept "
              "in place %.4f), rms %.4f (%.4f); unmoved points' rms %.4f (%.4f)\n",
    label,
    s.FarFlagged,
    s.Far,
    s.UnmovedFlagged,
    s.FarMedian,
    s.KeptFarMedian,
    s.FarRms,
    s.KeptFarRms,
    RootMeanSquare(sphere, r, moved, false),
    RootMeanSquare(sphere, kept, moved, false));
  return s;
}

/// Given normals: the far points are flagged and given the sphere's
/// curvature, their distance is reported; kept in place, they go wrong.
void TestStraysWithNormals(Checks& checks)
{
  std::vector<bool> moved;
  const auto sphere = StraySphere(moved);
  SerialRunner serial;
  Results r(sphere.size(), false), kept(sphere.size(), false);
  const EstimationSummary summary = Estimate(sphere, EstimationSettings{}, r, serial);
  EstimationSettings keep;
  keep.MoveOutliers = false;
  Estimate(sphere, keep, kept, serial);
  const StrayScores s = ScoreStrays("strays with normals", sphere, moved, r, kept);
  checks.True(
    "strays: 90 % of the points beyond three spacings flagged", s.FarFlagged >= 0.9 * s.Far);
  checks.True("strays: no unmoved point flagged", s.UnmovedFlagged == 0);
  checks.True("strays: the summary counts the flags",
    summary.NumberOfOutliers == std::count(r.Outlier.begin(), r.Outlier.end(), 1));
  checks.True("strays: far points get the sphere's curvature (median within 0.01 of 1/R)",
    s.FarMedian < 0.01);
  checks.True("strays: kept in place, their median error is ten times larger",
    s.KeptFarMedian > 10.0 * s.FarMedian);
  checks.True(
    "strays: kept in place, their rms error is twice as large", s.KeptFarRms > 2.0 * s.FarRms);
  checks.True("strays: kept in place, no flags",
    std::count(kept.Outlier.begin(), kept.Outlier.end(), 1) == 0);
  // The distance of a far point to the surface, as reported.
  const std::vector<bool> far = FarFromSphere(sphere, 3.0);
  std::vector<double> ratios;
  for (std::size_t i = 0; i < sphere.size(); ++i)
  {
    if (far[i] && r.Outlier[i])
    {
      const double exact =
        std::fabs(std::sqrt(testing::Dot(sphere[i].Point, sphere[i].Point)) - Radius);
      ratios.push_back(r.SurfaceDistance[i] / exact);
    }
  }
  std::sort(ratios.begin(), ratios.end());
  checks.Near(
    "strays: median reported distance / exact distance", ratios[ratios.size() / 2], 1.0, 0.05);
}

/// Positions only: the normals are estimated after the outliers are moved.
void TestStraysWithoutNormals(Checks& checks)
{
  std::vector<bool> moved;
  auto sphere = StraySphere(moved);
  for (auto& s : sphere)
  {
    s.Normal = { { 0.0, 0.0, 0.0 } };
  }
  SerialRunner serial;
  EstimationSettings estimate, keep;
  estimate.EstimateNormals = keep.EstimateNormals = true;
  keep.MoveOutliers = false;
  Results r(sphere.size(), false), kept(sphere.size(), false);
  Estimate(sphere, estimate, r, serial);
  Estimate(sphere, keep, kept, serial);
  const StrayScores s = ScoreStrays("strays without normals", sphere, moved, r, kept);
  checks.True("no normals: 90 % of the far points flagged", s.FarFlagged >= 0.9 * s.Far);
  checks.True("no normals: far points get the sphere's curvature (median within 0.02 of 1/R)",
    s.FarMedian < 0.02);
  checks.True("no normals: kept in place, their median error is ten times larger",
    s.KeptFarMedian > 10.0 * s.FarMedian);
}

/// A clean torus and a clean step (two planes three spacings apart, the
/// edge between them unsampled) have no outliers; Gaussian noise of half a
/// spacing very few.
void TestNoFalseOutliers(Checks& checks)
{
  SerialRunner serial;
  const auto torus = testing::Sample(testing::Torus(3.0, 1.0), 30000, 43);
  Results clean(torus.size(), false);
  const EstimationSummary cleanSummary = Estimate(torus, EstimationSettings{}, clean, serial);
  checks.True("clean torus: no outlier", cleanSummary.NumberOfOutliers == 0);

  auto noisy = torus;
  const double spacing =
    std::sqrt(4.0 * 3.141592653589793 * 3.141592653589793 * 3.0 / torus.size());
  testing::AddPositionNoise(noisy, 0.5 * spacing, 44);
  Results rough(noisy.size(), false);
  const EstimationSummary noisySummary = Estimate(noisy, EstimationSettings{}, rough, serial);
  std::printf("noisy torus: %lld outliers of %zu\n",
    static_cast<long long>(noisySummary.NumberOfOutliers),
    noisy.size());
  checks.True("noisy torus: at most 0.1 % outliers", noisySummary.NumberOfOutliers <= 30);

  std::vector<testing::SurfaceSample> step;
  constexpr int Side = 120;
  const double h = 0.01;
  for (int a = 0; a < Side; ++a)
  {
    for (int b = 0; b < Side; ++b)
    {
      testing::SurfaceSample s{};
      const double x = (a - Side / 2 + 0.5) * h, y = (b - Side / 2 + 0.5) * h;
      s.Point = { { x, y, x > 0.0 ? 3.0 * h : 0.0 } };
      s.Normal = { { 0.0, 0.0, 1.0 } };
      step.push_back(s);
    }
  }
  Results stepped(step.size(), false);
  const EstimationSummary stepSummary = Estimate(step, EstimationSettings{}, stepped, serial);
  checks.True("step: no outlier on its edges", stepSummary.NumberOfOutliers == 0);
}

/// The same verdicts and results on one thread and on two, and for the
/// points in another order.
void TestThreadsAndOrder(Checks& checks)
{
  std::vector<bool> moved;
  const auto sphere = StraySphere(moved);
  SerialRunner serial;
  ThreadRunner two(2);
  Results one(sphere.size(), false), both(sphere.size(), false), shuffled(sphere.size(), false);
  Estimate(sphere, EstimationSettings{}, one, serial);
  Estimate(sphere, EstimationSettings{}, both, two);
  checks.True("strays: one thread and two bit-identical", one.BitIdentical(both));
  std::vector<std::size_t> order(sphere.size());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937_64(45));
  std::vector<testing::SurfaceSample> reordered(sphere.size());
  for (std::size_t i = 0; i < order.size(); ++i)
  {
    reordered[i] = sphere[order[i]];
  }
  Estimate(reordered, EstimationSettings{}, shuffled, two);
  bool same = true;
  for (std::size_t i = 0; i < order.size(); ++i)
  {
    const std::size_t j = order[i];
    same = same && shuffled.Outlier[i] == one.Outlier[j] && shuffled.Valid[i] == one.Valid[j] &&
      (shuffled.Minimum[i] == one.Minimum[j] ||
        (std::isnan(shuffled.Minimum[i]) && std::isnan(one.Minimum[j])));
  }
  checks.True("strays: the same verdicts and curvatures in any input order", same);
}

/// A sphere with a patch a thousand times denser (as near a scanner) and
/// strays twenty of the patch's spacings above it: the patch's points are
/// judged by their nearest neighbors, not by the thousands within the
/// cloud's typical radius, and must come out the same: none flagged, every
/// stray flagged, the same on one thread and two.
void TestDensePatch(Checks& checks)
{
  auto cloud = testing::Sample(testing::Sphere(Radius), Points, 46);
  constexpr int PatchPoints = 20000;
  constexpr int Strays = 10;
  // About a thousand times the sphere's density: the sphere's spacing over
  // a square sqrt(1000) times narrower than PatchPoints of its spacings.
  const double half = 0.5 * SphereSpacing(Points) * std::sqrt(PatchPoints / 1000.0);
  const double patchSpacing = 2.0 * half / std::sqrt(static_cast<double>(PatchPoints));
  std::mt19937_64 random(47);
  std::uniform_real_distribution<double> across(-half, half);
  const std::size_t sphereCount = cloud.size();
  for (int i = 0; i < PatchPoints + Strays; ++i)
  {
    const double a = across(random), b = across(random);
    const double length = std::sqrt(a * a + b * b + Radius * Radius);
    testing::SurfaceSample s{};
    s.Normal = { { a / length, b / length, Radius / length } };
    const double height = i < PatchPoints ? Radius : Radius + 20.0 * patchSpacing;
    s.Point = { { height * s.Normal[0], height * s.Normal[1], height * s.Normal[2] } };
    s.MinimumCurvature = s.MaximumCurvature = 1.0 / Radius;
    s.BoundaryDistance = HUGE_VAL;
    cloud.push_back(s);
  }
  SerialRunner serial;
  ThreadRunner two(2);
  Results one(cloud.size(), false), both(cloud.size(), false);
  Estimate(cloud, EstimationSettings{}, one, serial);
  Estimate(cloud, EstimationSettings{}, both, two);
  int patchFlagged = 0, straysFlagged = 0;
  for (std::size_t i = sphereCount; i < cloud.size(); ++i)
  {
    const bool stray = i >= sphereCount + PatchPoints;
    (stray ? straysFlagged : patchFlagged) += one.Outlier[i] ? 1 : 0;
  }
  std::printf("dense patch: %d of %d patch points flagged, %d of %d strays\n",
    patchFlagged,
    PatchPoints,
    straysFlagged,
    Strays);
  checks.True(
    "dense patch: at most 0.1 % of its points flagged", patchFlagged <= PatchPoints / 1000);
  checks.True("dense patch: every stray above it flagged", straysFlagged == Strays);
  checks.True("dense patch: one thread and two bit-identical", one.BitIdentical(both));
}

/// The paper's fits take the cloud as it is: no verdicts.
void TestPaperFitsUntouched(Checks& checks)
{
  std::vector<bool> moved;
  const auto sphere = StraySphere(moved);
  SerialRunner serial;
  EstimationSettings paper, paperKept;
  paper.Mode = paperKept.Mode = FitMode::New01;
  paperKept.MoveOutliers = false;
  Results r(sphere.size(), false), kept(sphere.size(), false);
  const EstimationSummary summary = Estimate(sphere, paper, r, serial);
  Estimate(sphere, paperKept, kept, serial);
  checks.True("paper fit: no outliers looked for", summary.NumberOfOutliers == 0);
  checks.True("paper fit: results as without", r.BitIdentical(kept));
}
} // namespace

int main(int argc, char* argv[])
{
  return RunNamedTests(argc,
    argv,
    {
      { "StraysWithNormals", TestStraysWithNormals },
      { "StraysWithoutNormals", TestStraysWithoutNormals },
      { "NoFalseOutliers", TestNoFalseOutliers },
      { "ThreadsAndOrder", TestThreadsAndOrder },
      { "DensePatch", TestDensePatch },
      { "PaperFitsUntouched", TestPaperFitsUntouched },
    });
}
