// Shape_Class and Curvature_Trusted (no VTK): the pointwise rules, the
// classes on noisy analytic clouds, and trust that keeps a crest.
#include "CloudTestSupport.h"
#include "Estimation/ShapeClass.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <limits>
#include <random>

namespace
{
using namespace pcurv;
using namespace cloudtest;

constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

/// The rule on chosen values: significance against the error, signs,
/// undetermined points; the names; trust relative to the curvature.
void TestClassRule(Checks& checks)
{
  const auto is = [&checks](const char* what, ShapeClass got, ShapeClass expected)
  { checks.Equal(what, static_cast<int>(got), static_cast<int>(expected)); };
  is("rule: both small, flat", ClassifyShape(true, false, -0.1, 0.1, 0.1, 0.1), ShapeClass::Flat);
  is("rule: both positive, dome", ClassifyShape(true, false, 0.5, 1.0, 0.1, 0.1), ShapeClass::Dome);
  is("rule: both negative, cup", ClassifyShape(true, false, -1.0, -0.5, 0.1, 0.1), ShapeClass::Cup);
  is("rule: k_max alone, ridge", ClassifyShape(true, false, 0.1, 1.0, 0.1, 0.1), ShapeClass::Ridge);
  is("rule: k_min alone, valley",
    ClassifyShape(true, false, -1.0, -0.1, 0.1, 0.1),
    ShapeClass::Valley);
  is("rule: opposite, saddle", ClassifyShape(true, false, -1.0, 1.0, 0.1, 0.1), ShapeClass::Saddle);
  is("rule: within 2 errors, flat",
    ClassifyShape(true, false, -0.19, 0.19, 0.1, 0.1),
    ShapeClass::Flat);
  is("rule: within 2 errors but imprecise, undetermined",
    ClassifyShape(true, false, -0.19, 0.19, 0.1, 6.0),
    ShapeClass::Undetermined);
  is("rule: a significant curvature needs no precision",
    ClassifyShape(true, false, 0.5, 1.0, 0.1, 100.0),
    ShapeClass::Dome);
  is("rule: not estimated",
    ClassifyShape(false, false, 0.5, 1.0, 0.1, 0.1),
    ShapeClass::Undetermined);
  is("rule: outlier", ClassifyShape(true, true, 0.5, 1.0, 0.1, 0.1), ShapeClass::Undetermined);
  is("rule: no error", ClassifyShape(true, false, 0.5, 1.0, NaN, 0.1), ShapeClass::Undetermined);
  checks.True("names: one per class, as documented",
    std::string(ShapeClassName(ShapeClass::Undetermined)) == "Undetermined" &&
      std::string(ShapeClassName(ShapeClass::Valley)) == "Valley" &&
      std::string(ShapeClassName(ShapeClass::Saddle)) == "Saddle" &&
      std::string(ShapeClassName(ShapeClass::Count)) == "Unknown");
  // A crest of curvature 10 known to a tenth (twice its error within a
  // third of it) in a cloud whose scale is 1: trusted; known to 40 % it is
  // not, nor is a flat point with that error; a flat point whose error is
  // within a tenth of the scale is.
  checks.True("trust: a crest known to a tenth", IsTrusted(true, false, 0.0, 10.0, 0.5, 1.0));
  checks.True("trust: not a crest known to 40 %", !IsTrusted(true, false, 0.0, 10.0, 2.0, 1.0));
  checks.True(
    "trust: not a flat point with a crest's error", !IsTrusted(true, false, 0.0, 0.0, 0.5, 1.0));
  checks.True("trust: a flat point within a tenth of the scale",
    IsTrusted(true, false, 0.0, 0.01, 0.05, 1.0));
  checks.True("trust: never an outlier", !IsTrusted(true, true, 0.0, 10.0, 0.1, 1.0));
  checks.True("trust: never without an error", !IsTrusted(true, false, 0.0, 10.0, NaN, 1.0));
}

/// The shape turned inside out: normals reversed, curvatures negated.
std::vector<testing::SurfaceSample> InsideOut(std::vector<testing::SurfaceSample> samples)
{
  for (testing::SurfaceSample& s : samples)
  {
    s.Normal = testing::Scale(-1.0, s.Normal);
    const double kMin = s.MinimumCurvature;
    s.MinimumCurvature = -s.MaximumCurvature;
    s.MaximumCurvature = -kMin;
  }
  return samples;
}

struct ClassCase
{
  const char* Name;
  std::vector<testing::SurfaceSample> Samples;
  ShapeClass Expected;
  /// Normals reversed: only with the given normals (estimated ones are
  /// oriented by the filter, whatever the input's).
  bool Reversed = false;
};

/// The share of the points away from the border in the expected class
/// (Undetermined counts as wrong): by twice their radius, or by a quarter
/// unit (an eighth of the patches' width) where the noise grew the radius
/// as wide as the patch (an exactly quadratic saddle's fourth-order fits
/// agree up to the largest radius).
double ShareRight(const ClassCase& c, const ReportedRun& run)
{
  int inner = 0, right = 0;
  for (std::size_t i = 0; i < c.Samples.size(); ++i)
  {
    if (c.Samples[i].BoundaryDistance > std::min(2.0 * run.Out.Surroundings[i], 0.25))
    {
      ++inner;
      right += run.ShapeClass[i] == static_cast<unsigned char>(c.Expected);
    }
  }
  return inner ? static_cast<double>(right) / inner : 0.0;
}

/// Noisy clouds (0.3 and 0.5 spacings; exact normals as the suite's, and
/// normals estimated from the noisy points): at least 95 % of each shape's
/// points away from the border in its class. A cylinder's zero curvature
/// and a plane's must not pass for features.
void TestNoisyShapes(Checks& checks)
{
  constexpr int Count = 20000;
  const auto sphere = testing::Sample(testing::Sphere(1.0), Count, 201);
  const auto cylinder = testing::Sample(testing::Cylinder(1.0, 8.0), Count, 202);
  std::vector<ClassCase> cases = {
    { "sphere (outward normals)", sphere, ShapeClass::Dome },
    { "sphere (inward normals)", InsideOut(sphere), ShapeClass::Cup, true },
    { "cylinder (outward normals)", cylinder, ShapeClass::Ridge },
    { "cylinder (inward normals)", InsideOut(cylinder), ShapeClass::Valley, true },
    { "saddle", testing::Sample(testing::Saddle(1.0, 1.0), Count, 203), ShapeClass::Saddle },
    { "plane", testing::Sample(testing::Plane(1.0), Count, 204), ShapeClass::Flat },
  };
  for (const auto& [noise, estimate] : { std::pair{ 0.3, false }, { 0.5, false }, { 0.5, true } })
  {
    for (ClassCase c : cases)
    {
      if (estimate && c.Reversed)
      {
        continue;
      }
      double area = 4.0; // the square patches'
      if (c.Expected == ShapeClass::Dome || c.Expected == ShapeClass::Cup)
      {
        area = 4.0 * testing::Pi;
      }
      else if (c.Expected == ShapeClass::Ridge || c.Expected == ShapeClass::Valley)
      {
        area = 16.0 * testing::Pi;
      }
      testing::AddPositionNoise(c.Samples, noise * std::sqrt(area / Count), 205);
      EstimationSettings settings;
      settings.EstimateNormals = estimate;
      const ReportedRun run(c.Samples, settings);
      const double share = ShareRight(c, run);
      const std::string what = std::string("classes: ") + c.Name + ", noise " +
        std::to_string(noise).substr(0, 3) + (estimate ? ", estimated normals" : ", given normals");
      std::printf("%s: %.4f %s\n", what.c_str(), share, ShapeClassName(c.Expected));
      checks.True((what + ": at least 95 % in its class").c_str(), share >= 0.95);
    }
  }
}

/// A straight crest on flat ground, z = h exp(-x^2 / 2 s^2) over
/// [-2, 2]^2 (up normals): k_max = h / s^2 on its line, a scan's curb or
/// crown on a road.
testing::Surface Crest(double h, double s)
{
  return testing::HeightField("crest",
    2.0,
    [h, s](double x, double)
    {
      const double z = h * std::exp(-x * x / (2.0 * s * s));
      return std::array<double, 6>{
        { z, -x / (s * s) * z, 0.0, (x * x / (s * s) - 1.0) / (s * s) * z, 0.0, 0.0 }
      };
    });
}

/// Curvature_Trusted on a noisy crest over a small share of a flat cloud,
/// with stray points. The crest's error is far above the flat ground's, so
/// an error small against the cloud's curvature scale left it out; known
/// to a third of itself, it is trusted, and so is the flat ground; no
/// outlier is; the trusted points are within their bound of the exact
/// curvatures.
void TestTrustedKeepsCrests(Checks& checks)
{
  constexpr double Height = 0.08, Width = 0.24, Peak = Height / (Width * Width);
  auto samples = testing::Sample(Crest(Height, Width), 60000, 211);
  const double spacing = std::sqrt(16.0 / samples.size());
  testing::AddPositionNoise(samples, 0.3 * spacing, 212);
  const std::vector<bool> moved = testing::AddOutliers(samples, 0.005, 10.0 * spacing, 213);
  const ReportedRun run(samples, EstimationSettings{});
  const double scale = run.Summary.TrustedCurvatureScale;
  int crest = 0, crestTrusted = 0, flat = 0, flatTrusted = 0, outliers = 0, outliersTrusted = 0,
      trusted = 0, within = 0;
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    const testing::SurfaceSample& p = samples[i];
    outliers += run.Out.Outlier[i];
    outliersTrusted += run.Out.Outlier[i] && run.Trusted[i];
    if (run.Out.Outlier[i] || moved[i] || p.BoundaryDistance < 2.0 * run.Out.Surroundings[i])
    {
      continue;
    }
    const bool onCrest = p.MaximumCurvature > 0.5 * Peak;
    const bool onFlat = std::fabs(p.Point[0]) > 4.0 * Width;
    crest += onCrest;
    crestTrusted += onCrest && run.Trusted[i];
    flat += onFlat;
    flatTrusted += onFlat && run.Trusted[i];
    const double exact = std::max(std::fabs(p.MaximumCurvature), std::fabs(p.MinimumCurvature));
    const double bound = std::max(exact * TrustedRelativeError, TrustedScaleShare * scale);
    trusted += run.Trusted[i];
    within += run.Trusted[i] && PointError(run.Out, samples, i) <= bound;
  }
  const auto share = [](int part, int whole)
  { return whole ? static_cast<double>(part) / whole : 0.0; };
  std::printf("trust: crest %d of %d (%.3f), flat %d of %d (%.3f), outliers flagged %d, trusted "
              "%d; trusted points within their bound %.4f (scale %.3f)\n",
    crestTrusted,
    crest,
    share(crestTrusted, crest),
    flatTrusted,
    flat,
    share(flatTrusted, flat),
    outliers,
    outliersTrusted,
    share(within, trusted),
    scale);
  checks.True("trust: at least 80 % of the crest trusted", share(crestTrusted, crest) >= 0.8);
  checks.True("trust: at least 80 % of the flat ground trusted", share(flatTrusted, flat) >= 0.8);
  checks.True("trust: outliers flagged, none trusted", outliers > 0 && outliersTrusted == 0);
  checks.True("trust: at least 95 % of the trusted points within their bound",
    share(within, trusted) >= 0.95);
}

/// Flat ground with tree crowns on it, as an airborne scan sees them:
/// each crown a sparse scatter through a ball a few spacings wide, no
/// normals given. Many crown points have no significant curvature, yet
/// their errors are far too large to say they are flat: they must be
/// Undetermined, not Flat, while the ground stays Flat.
void TestSparseCrowns(Checks& checks)
{
  std::mt19937_64 random(214);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<testing::SurfaceSample> samples;
  constexpr double Half = 4.0;
  constexpr int GroundPoints = 8000, Crowns = 24, CrownPoints = 120;
  constexpr double CrownRadius = 0.3;
  for (int i = 0; i < GroundPoints; ++i)
  {
    testing::SurfaceSample s{};
    s.Point = { { Half * uniform(random), Half * uniform(random), 0.0 } };
    s.Normal = { { 0.0, 0.0, 1.0 } };
    s.BoundaryDistance = HUGE_VAL;
    samples.push_back(s);
  }
  std::vector<std::array<double, 3>> centers;
  for (int c = 0; c < Crowns; ++c)
  {
    centers.push_back({ { (Half - 1.0) * uniform(random), (Half - 1.0) * uniform(random), 1.0 } });
    for (int i = 0; i < CrownPoints;)
    {
      const std::array<double, 3> d = { { uniform(random), uniform(random), uniform(random) } };
      if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] <= 1.0)
      {
        testing::SurfaceSample s{};
        for (int k = 0; k < 3; ++k)
        {
          s.Point[k] = centers.back()[k] + CrownRadius * d[k];
        }
        s.Normal = { { 0.0, 0.0, 1.0 } };
        s.BoundaryDistance = HUGE_VAL;
        samples.push_back(s);
        ++i;
      }
    }
  }
  EstimationSettings settings;
  settings.EstimateNormals = true;
  const ReportedRun run(samples, settings);
  int crown = 0, crownFlat = 0, crownInsignificant = 0, ground = 0, groundFlat = 0;
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    const bool flat = run.ShapeClass[i] == static_cast<unsigned char>(ShapeClass::Flat);
    if (i >= static_cast<std::size_t>(GroundPoints))
    {
      const double bound = ShapeSignificance * run.StandardError[i];
      ++crown;
      crownFlat += flat;
      crownInsignificant +=
        run.Out.Valid[i] && run.Out.Maximum[i] <= bound && run.Out.Minimum[i] >= -bound;
      continue;
    }
    bool nearCrown =
      std::fabs(samples[i].Point[0]) > Half - 0.5 || std::fabs(samples[i].Point[1]) > Half - 0.5;
    for (const auto& c : centers)
    {
      nearCrown =
        nearCrown || std::hypot(samples[i].Point[0] - c[0], samples[i].Point[1] - c[1]) < 1.0;
    }
    ground += !nearCrown;
    groundFlat += !nearCrown && flat;
  }
  std::printf(
    "crowns: %d points, %d not significantly curved, %d Flat; open ground: %d of %d Flat\n",
    crown,
    crownInsignificant,
    crownFlat,
    groundFlat,
    ground);
  checks.True("crowns: many points not significantly curved", crownInsignificant >= crown / 5);
  checks.True("crowns: at most 5 % Flat", crownFlat <= crown / 20);
  checks.True("open ground: at least 90 % Flat", groundFlat >= 0.9 * ground);
}

} // namespace

int main(int argc, char* argv[])
{
  return RunNamedTests(argc,
    argv,
    {
      { "ClassRule", TestClassRule },
      { "NoisyShapes", TestNoisyShapes },
      { "TrustedKeepsCrests", TestTrustedKeepsCrests },
      { "SparseCrowns", TestSparseCrowns },
    });
}
