// The fit of the normal field (no VTK): exact where the normals' tangential
// part is linear in the offsets (spheres, cylinders, at any radius and on
// one side), the third order where a one-sided neighborhood needs it, a
// standard error that covers noisy positions' error, and, in the automatic
// scale (NormalFieldFit), more accurate than the oriented circles on a
// noisy cloud with exact normals, deterministic, with no wild point.
#include "CloudTestSupport.h"
#include "Fits/NormalFieldFit.h"

namespace
{
using namespace pcurv;
using namespace cloudtest;

/// The fit of order `Order` at sample `at` over the samples within `radius`
/// of it (offsets over the radius) that `keep` accepts.
template<int Order, typename Keep>
OrientedCircleResult FitAround(const std::vector<testing::SurfaceSample>& samples,
  std::size_t at,
  double radius,
  const Keep& keep)
{
  const testing::SurfaceSample& query = samples[at];
  const TangentFrame frame = MakeTangentFrame(query.Normal);
  NormalFieldAccumulator sums;
  sums.Begin(frame);
  for (const testing::SurfaceSample& s : samples)
  {
    const double d[3] = { (s.Point[0] - query.Point[0]) / radius,
      (s.Point[1] - query.Point[1]) / radius,
      (s.Point[2] - query.Point[2]) / radius };
    if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < 1.0 && keep(d))
    {
      sums.Add(d, s.Normal.data());
    }
  }
  return FitNormalField<Order>(sums.Sums(), frame, 1.0 / radius, 12, 0.05);
}

template<int Order>
OrientedCircleResult FitAround(const std::vector<testing::SurfaceSample>& samples,
  std::size_t at,
  double radius)
{
  return FitAround<Order>(samples, at, radius, [](const double*) { return true; });
}

double AbsoluteDot(const Vector3& a, const testing::Vec& b)
{
  return std::fabs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
}

/// A sphere's and a cylinder's normals are linear in the offsets: both
/// orders are exact at any radius (here the surface turns through 0.4 and
/// 0.8 radians), on every side and on one side only, with the output sign
/// (outward normals: positive) and the cylinder's directions.
void TestExactShapes(Checks& checks)
{
  const auto sphere = testing::Sample(testing::Sphere(2.0), 20000, 301);
  const auto cylinder = testing::Sample(testing::Cylinder(0.5, 4.0), 20000, 302);
  const auto oneSide = [](const double* d) { return d[0] + 0.3 * d[1] > 0.0; };
  for (std::size_t at : { std::size_t{ 0 }, std::size_t{ 777 } })
  {
    for (const OrientedCircleResult& fit : { FitAround<2>(sphere, at, 0.8),
           FitAround<3>(sphere, at, 0.8),
           FitAround<2>(sphere, at, 0.8, oneSide) })
    {
      checks.Near("exact shapes: sphere, k_min", fit.Curvature.MinimumCurvature, 0.5, 1e-9);
      checks.Near("exact shapes: sphere, k_max", fit.Curvature.MaximumCurvature, 0.5, 1e-9);
    }
  }
  // A point away from the cylinder's ends (its samples are in parameter
  // order: angle first).
  std::size_t at = 0;
  while (std::fabs(cylinder[at].Point[2]) > 0.5)
  {
    ++at;
  }
  for (const OrientedCircleResult& fit : { FitAround<2>(cylinder, at, 0.4),
         FitAround<3>(cylinder, at, 0.4),
         FitAround<3>(cylinder, at, 0.4, oneSide) })
  {
    const PointCurvature& k = fit.Curvature;
    checks.True("exact shapes: cylinder, valid", k.Valid);
    checks.Near("exact shapes: cylinder, k_min", k.MinimumCurvature, 0.0, 1e-9);
    checks.Near("exact shapes: cylinder, k_max", k.MaximumCurvature, 2.0, 1e-9);
    checks.Near("exact shapes: cylinder, k_max's direction around the axis",
      AbsoluteDot(k.MaximumDirection, cylinder[at].MaximumDirection),
      1.0,
      1e-9);
    checks.Near("exact shapes: cylinder, k_min's direction along the axis",
      std::fabs(k.MinimumDirection[2]),
      1.0,
      1e-9);
  }
  // Inward normals: the opposite sign.
  auto inward = sphere;
  for (testing::SurfaceSample& s : inward)
  {
    s.Normal = testing::Scale(-1.0, s.Normal);
  }
  checks.Near("exact shapes: sphere with inward normals, k_max",
    FitAround<2>(inward, 0, 0.8).Curvature.MaximumCurvature,
    -0.5,
    1e-9);
}

/// z = c x^3 sampled on one side of the origin only (x in [0, r]): the
/// second order takes the cubic's slope 3 c x^2 for curvature, the third
/// order does not; the curvature there is 0.
void TestOneSidedCubic(Checks& checks)
{
  const double c = 0.5;
  std::vector<testing::SurfaceSample> patch;
  for (int i = 0; i <= 30; ++i)
  {
    for (int j = -30; j <= 30; ++j)
    {
      testing::SurfaceSample s{};
      const double x = 0.01 * i, y = 0.01 * j;
      s.Point = { { x, y, c * x * x * x } };
      s.Normal = testing::Unit({ { -3.0 * c * x * x, 0.0, 1.0 } });
      patch.push_back(s);
    }
  }
  const std::size_t origin = 30; // i = 0, j = 0
  const OrientedCircleResult second = FitAround<2>(patch, origin, 0.3);
  const OrientedCircleResult third = FitAround<3>(patch, origin, 0.3);
  const auto largest = [](const OrientedCircleResult& fit)
  {
    return std::max(
      std::fabs(fit.Curvature.MinimumCurvature), std::fabs(fit.Curvature.MaximumCurvature));
  };
  std::printf("one-sided cubic: largest |k| %.5f (second order), %.5f (third)\n",
    largest(second),
    largest(third));
  checks.True("one-sided cubic: both fitted", second.Curvature.Valid && third.Curvature.Valid);
  checks.True("one-sided cubic: the second order is biased", largest(second) > 0.2);
  checks.True("one-sided cubic: the third order is not", largest(third) < 0.02);
  checks.True("one-sided cubic: the third's error covers the second's bias",
    third.StandardError < largest(second));
}

/// Noisy positions with exact normals: the errors of a cylinder's
/// curvature over many points within twice the standard error at least
/// 85 % of the time, and the standard error no more than about twice the
/// errors' scale (the rows' residual differs between the curved and the
/// flat direction: a pooled variance would understate it).
void TestStandardError(Checks& checks)
{
  auto cylinder = testing::Sample(testing::Cylinder(1.0, 4.0), 20000, 303);
  const double spacing = std::sqrt(2.0 * 3.141592653589793 * 4.0 / cylinder.size());
  testing::AddPositionNoise(cylinder, 0.5 * spacing, 304);
  int fitted = 0, covered = 0;
  std::vector<double> ratios;
  for (std::size_t at = 0; at < cylinder.size() && fitted < 400; at += 37)
  {
    if (std::fabs(cylinder[at].Point[2]) > 1.5)
    {
      continue;
    }
    const OrientedCircleResult fit = FitAround<2>(cylinder, at, 6.0 * spacing);
    if (!fit.Curvature.Valid)
    {
      continue;
    }
    ++fitted;
    const double error = std::max(
      std::fabs(fit.Curvature.MinimumCurvature), std::fabs(fit.Curvature.MaximumCurvature - 1.0));
    covered += error <= 2.0 * fit.StandardError;
    ratios.push_back(error / fit.StandardError);
  }
  std::nth_element(ratios.begin(), ratios.begin() + ratios.size() / 2, ratios.end());
  const double median = ratios[ratios.size() / 2];
  std::printf(
    "standard error: %d of %d within 2 SE, median error / SE %.3f\n", covered, fitted, median);
  checks.True("standard error: 400 points fitted", fitted == 400);
  checks.True("standard error: at least 85 % within 2 SE", covered >= 0.85 * fitted);
  checks.True("standard error: median error / SE at least 0.3", median >= 0.3);
}

/// The automatic scale with NormalFieldFit: on a noisy torus with exact
/// normals, more accurate than the oriented circles (RMS error), with no
/// wild point, errors covered, the same bits on 3 threads; on the clean
/// torus (precise positions) and with estimated normals it is not used.
void TestNormalFieldLadder(Checks& checks)
{
  const auto clean = testing::Sample(testing::Torus(3.0, 1.0), 40000, 305);
  const double spacing =
    std::sqrt(4.0 * 3.141592653589793 * 3.141592653589793 * 3.0 / clean.size());
  auto noisy = clean;
  testing::AddPositionNoise(noisy, 0.5 * spacing, 306);
  EstimationSettings circles, field;
  field.NormalFieldFit = true;
  const ReportedRun before(noisy, circles), after(noisy, field);
  const auto rms = [&](const Results& r)
  {
    double sum = 0.0;
    for (std::size_t i = 0; i < noisy.size(); ++i)
    {
      const double e = PointError(r, noisy, i);
      sum += r.Valid[i] ? e * e : 1.0;
    }
    return std::sqrt(sum / noisy.size());
  };
  const ErrorCover cover = CoverOf(noisy, after.Out, after.StandardError, 1.0);
  std::printf("normal field ladder: noisy torus, RMS error %.5f (circles %.5f); within 2 SE "
              "%.3f, median error / SE %.3f, off by > 20 %% %d\n",
    rms(after.Out),
    rms(before.Out),
    cover.Share(),
    cover.MedianRatio,
    cover.Far);
  checks.True("normal field ladder: noisy torus, RMS error below 0.9 times the circles'",
    rms(after.Out) < 0.9 * rms(before.Out));
  checks.True(
    "normal field ladder: every point estimated", after.Summary.NumberOfUnestimatedPoints == 0);
  checks.True("normal field ladder: no valid point off by 20 % of max |k|", cover.Far == 0);
  checks.True("normal field ladder: at least 85 % within 2 standard errors", cover.Share() >= 0.85);
  checks.True("normal field ladder: median error / SE at least 0.3", cover.MedianRatio >= 0.3);
  Results threaded(noisy.size(), false);
  ThreadRunner threads(3);
  Estimate(noisy, field, threaded, threads);
  checks.True(
    "normal field ladder: 3 threads bit-identical to 1", after.Out.BitIdentical(threaded));

  SerialRunner serial;
  Results cleanCircles(clean.size(), false), cleanField(clean.size(), false);
  Estimate(clean, circles, cleanCircles, serial);
  Estimate(clean, field, cleanField, serial);
  int differ = 0;
  double largest = 0.0;
  for (std::size_t i = 0; i < clean.size(); ++i)
  {
    if (cleanField.Maximum[i] != cleanCircles.Maximum[i] ||
      cleanField.Minimum[i] != cleanCircles.Minimum[i])
    {
      ++differ;
      largest = std::max(largest, PointError(cleanField, clean, i));
    }
  }
  std::printf("normal field ladder: clean torus, %d points differ from the circles' (largest "
              "error %.2g)\n",
    differ,
    largest);
  checks.True("normal field ladder: clean torus, the circles' results bit for bit",
    cleanField.BitIdentical(cleanCircles));
  circles.EstimateNormals = field.EstimateNormals = true;
  Results estimatedCircles(noisy.size(), false), estimatedField(noisy.size(), false);
  Estimate(noisy, circles, estimatedCircles, serial);
  Estimate(noisy, field, estimatedField, serial);
  checks.True("normal field ladder: estimated normals, the circles' results bit for bit",
    estimatedField.BitIdentical(estimatedCircles));
}

} // namespace

int main(int argc, char* argv[])
{
  return RunNamedTests(argc,
    argv,
    {
      { "ExactShapes", TestExactShapes },
      { "OneSidedCubic", TestOneSidedCubic },
      { "StandardError", TestStandardError },
      { "NormalFieldLadder", TestNormalFieldLadder },
    });
}
