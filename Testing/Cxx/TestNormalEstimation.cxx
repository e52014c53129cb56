// The normal estimation (no VTK): accuracy and orientation, scan lines,
// given normals the positions contradict, and the orientation graph's lists.
#include "CloudTestSupport.h"

namespace
{
using namespace pcurv;
using namespace cloudtest;

/// Normals estimated by the core: close to the exact ones, outward on closed
/// surfaces, the same for any threads or input order, and signed as asked.
void TestNormalEstimation(Checks& checks)
{
  struct Case
  {
    const char* Name;
    testing::Surface Surface;
  };
  const Case cases[] = { { "sphere", testing::Sphere(2.0) },
    { "torus", testing::Torus(3.0, 1.0) },
    { "ellipsoid", testing::Ellipsoid(3.0, 2.0, 1.5) } };
  for (const Case& c : cases)
  {
    const auto samples = testing::Sample(c.Surface, 20000, 21);
    SerialRunner serial;
    std::vector<double> normals(3 * samples.size());
    const NormalSummary summary = EstimateCloudNormals(
      MakeCloud(samples), NormalSettings{}, Collectives{}, serial, normals.data());
    std::vector<double> angles;
    int outward = 0;
    for (std::size_t i = 0; i < samples.size(); ++i)
    {
      const double dot = testing::Dot(
        { { normals[3 * i], normals[3 * i + 1], normals[3 * i + 2] } }, samples[i].Normal);
      outward += dot > 0.0;
      angles.push_back(std::acos(std::min(1.0, std::fabs(dot))) * 180.0 / 3.141592653589793);
    }
    std::nth_element(angles.begin(), angles.begin() + angles.size() / 2, angles.end());
    const std::string name = c.Name;
    checks.Near((name + ": median angle to the exact normal (degrees)").c_str(),
      angles[angles.size() / 2],
      0.0,
      1.0);
    checks.Equal(
      (name + ": every normal outward").c_str(), outward, static_cast<int>(samples.size()));
    checks.Equal((name + ": one connected part").c_str(), summary.Components, 1);

    // Threads and input order: the same normal for the same point.
    ThreadRunner threads(3);
    std::vector<double> threaded(normals.size());
    EstimateCloudNormals(
      MakeCloud(samples), NormalSettings{}, Collectives{}, threads, threaded.data());
    checks.True((name + ": 3 threads bit-identical to 1").c_str(), threaded == normals);
    std::vector<testing::SurfaceSample> reversed(samples.rbegin(), samples.rend());
    std::vector<double> backwards(normals.size());
    EstimateCloudNormals(
      MakeCloud(reversed), NormalSettings{}, Collectives{}, serial, backwards.data());
    bool same = true;
    for (std::size_t i = 0; i < samples.size(); ++i)
    {
      const std::size_t j = samples.size() - 1 - i;
      same = same && std::equal(&normals[3 * i], &normals[3 * i] + 3, &backwards[3 * j]);
    }
    checks.True((name + ": the same normals for the input reversed").c_str(), same);
  }

  const auto plane = testing::Sample(testing::Plane(2.0), 4000, 22);
  for (const NormalOrientation orientation : { NormalOrientation::TowardsViewpoint,
         NormalOrientation::AlongAxis,
         NormalOrientation::Outward })
  {
    NormalSettings settings;
    settings.Orientation = orientation;
    settings.Viewpoint = { { 0.5, 0.0, -10.0 } }; // below the plane z = 0
    settings.Axis = { { 0.0, 0.0, -1.0 } };
    SerialRunner serial;
    std::vector<double> normals(3 * plane.size());
    EstimateCloudNormals(MakeCloud(plane), settings, Collectives{}, serial, normals.data());
    int down = 0;
    for (std::size_t i = 0; i < plane.size(); ++i)
    {
      down += normals[3 * i + 2] < -0.999;
    }
    const int expected =
      orientation == NormalOrientation::Outward ? 0 : static_cast<int>(plane.size());
    checks.Equal(orientation == NormalOrientation::TowardsViewpoint
        ? "plane, viewpoint below: every normal down"
        : orientation == NormalOrientation::AlongAxis ? "plane, axis -z: every normal down"
                                                      : "plane, outward: an open part points up",
      down,
      expected);
  }
}

/// Normals of scan lines: where a point's nearest neighbours all lie on its
/// own line, any plane through the line fits them, and PCA turned the
/// normal at random about it (a fifth of a scan-line sphere's points, 35-41
/// degrees off at the 90th percentile, and their curvatures 50-100 % off).
/// The neighbourhood grows until it spans a plane.
void TestScanLineNormals(Checks& checks)
{
  const auto sphere = ScanLineSphere(10.0, 2.2, 111);
  SerialRunner serial;
  std::vector<double> normals(3 * sphere.size());
  EstimateCloudNormals(MakeCloud(sphere), NormalSettings{}, Collectives{}, serial, normals.data());
  std::vector<double> angles;
  for (std::size_t i = 0; i < sphere.size(); ++i)
  {
    const double dot = testing::Dot(
      { { normals[3 * i], normals[3 * i + 1], normals[3 * i + 2] } }, sphere[i].Normal);
    angles.push_back(std::acos(std::min(1.0, std::fabs(dot))) * 180.0 / 3.141592653589793);
  }
  std::sort(angles.begin(), angles.end());
  const double median = angles[angles.size() / 2];
  const double ninetieth = angles[angles.size() * 9 / 10];
  std::printf("scan-line sphere (%zu points): normals off by %.2f degrees (median), %.2f (90th "
              "percentile)\n",
    sphere.size(),
    median,
    ninetieth);
  checks.True("scan-line normals: median within 5 degrees", median < 5.0);
  checks.True("scan-line normals: 90 % within 8 degrees", ninetieth < 8.0);

  EstimationSettings own;
  own.EstimateNormals = true;
  Results estimated(sphere.size(), false), threaded(sphere.size(), false);
  Estimate(sphere, own, estimated, serial);
  ThreadRunner threads(3);
  Estimate(sphere, own, threaded, threads);
  std::vector<double> errors;
  for (std::size_t i = 0; i < sphere.size(); ++i)
  {
    if (estimated.Valid[i])
    {
      // The orientation is not what is measured: the exact curvature on
      // the side of the estimated normal.
      const double k = std::fabs(estimated.Minimum[i] + estimated.Maximum[i]) / 2.0;
      errors.push_back(std::fabs(k - sphere[i].MaximumCurvature));
    }
  }
  std::sort(errors.begin(), errors.end());
  const double medianError = errors.empty() ? HUGE_VAL : errors[errors.size() / 2] * 10.0;
  const double ninetiethError = errors.empty() ? HUGE_VAL : errors[errors.size() * 9 / 10] * 10.0;
  std::printf("scan-line sphere, estimated normals: %zu of %zu valid, |H - 1/R| R %.4f (median), "
              "%.4f (90th percentile)\n",
    errors.size(),
    sphere.size(),
    medianError,
    ninetiethError);
  checks.True(
    "scan-line normals: 95 % of the curvatures estimated", errors.size() >= 0.95 * sphere.size());
  checks.True(
    "scan-line normals: median mean-curvature error within 2 % of 1/R", medianError < 0.02);
  checks.True(
    "scan-line normals: 90 % of the mean curvatures within 5 % of 1/R", ninetiethError < 0.05);
  checks.True("scan-line normals: 3 threads bit-identical to 1", estimated.BitIdentical(threaded));
}

/// The survey's score of one point: the squared errors of the unsigned,
/// sorted principal curvatures (an unestimated point counts as 0, 0).
double SortedSquaredError(const Results& r, const testing::SurfaceSample& s, std::size_t i)
{
  const double a = r.Valid[i] ? std::fabs(r.Minimum[i]) : 0.0;
  const double b = r.Valid[i] ? std::fabs(r.Maximum[i]) : 0.0;
  const double ta = std::fabs(s.MinimumCurvature), tb = std::fabs(s.MaximumCurvature);
  const double e1 = std::min(a, b) - std::min(ta, tb), e2 = std::max(a, b) - std::max(ta, tb);
  return (e1 * e1 + e2 * e2) / 2.0;
}

/// Noise of about one spacing, no normals: the k nearest's planes are
/// turned by the noise, some nearly into the tangent plane, and where a
/// point's normal is that far off, its curvatures are off by tens of times
/// the surface's. The normals' scale, chosen from the data, averages the
/// noise out where the surface allows.
void TestHeavyNoiseNormals(Checks& checks)
{
  const testing::Surface surfaces[] = { testing::Paraboloid(1.0, 1.0), testing::Saddle(1.0, 1.0) };
  for (const testing::Surface& surface : surfaces)
  {
    auto samples = testing::Sample(surface, 12000, 71);
    const double spacing = 2.0 / std::sqrt(12000.0);
    testing::AddPositionNoise(samples, spacing, 72);
    for (auto& s : samples)
    {
      s.Normal = { { 0.0, 0.0, 0.0 } };
    }
    EstimationSettings settings;
    settings.EstimateNormals = true;
    SerialRunner serial;
    ThreadRunner threads(2);
    Results one(samples.size(), false), two(samples.size(), false);
    std::vector<double> normals(3 * samples.size()), threaded(3 * samples.size());
    CurvatureBuffers buffers = one.Buffers();
    buffers.Normals = normals.data();
    EstimateCloud(MakeCloud(samples), settings, Collectives{}, serial, nullptr, buffers);
    buffers = two.Buffers();
    buffers.Normals = threaded.data();
    EstimateCloud(MakeCloud(samples), settings, Collectives{}, threads, nullptr, buffers);
    const auto exact = testing::Sample(surface, 12000, 71); // the noise-free normals
    std::size_t within = 0;
    double squared = 0.0;
    for (std::size_t i = 0; i < samples.size(); ++i)
    {
      const double dot = testing::Dot(
        { { normals[3 * i], normals[3 * i + 1], normals[3 * i + 2] } }, exact[i].Normal);
      within += std::fabs(dot) >= std::cos(10.0 * 3.141592653589793 / 180.0);
      squared += SortedSquaredError(one, samples[i], i);
    }
    const double share = static_cast<double>(within) / samples.size();
    const double rmse = std::sqrt(squared / samples.size());
    std::printf("%s, noise of one spacing: %.1f %% of the normals within 10 degrees, k RMSE %.4f\n",
      surface.Name.c_str(),
      100.0 * share,
      rmse);
    const std::string name = surface.Name + " at one spacing's noise";
    checks.True((name + ": 90 % of the normals within 10 degrees").c_str(), share >= 0.9);
    checks.True((name + ": curvature RMSE below 0.18").c_str(), rmse < 0.18);
    checks.True((name + ": 2 threads bit-identical to 1").c_str(),
      one.BitIdentical(two) && normals == threaded);
  }
}

/// Normals perturbed by Gaussian noise of 0.1 per component (the survey's
/// noisy-normals condition) on a cloud with noise of half a spacing: the
/// positions contradict them, so they are replaced by normals estimated
/// from the positions, signed as given, and the curvatures are no worse
/// than with no normals given. The exact normals of the same cloud are
/// kept: they agree with the positions within the noise.
void TestNoisyGivenNormals(Checks& checks)
{
  const testing::Surface surfaces[] = { testing::Paraboloid(1.0, 1.0), testing::Saddle(1.0, 1.0) };
  for (const testing::Surface& surface : surfaces)
  {
    auto exact = testing::Sample(surface, 12000, 81);
    testing::AddPositionNoise(exact, 0.5 * 2.0 / std::sqrt(12000.0), 82);
    auto noisy = exact;
    testing::Random random(83);
    for (auto& s : noisy)
    {
      for (double& c : s.Normal)
      {
        c += 0.1 * random.Normal();
      }
      const double length = std::sqrt(testing::Dot(s.Normal, s.Normal));
      for (double& c : s.Normal)
      {
        c /= length;
      }
    }
    auto none = exact;
    for (auto& s : none)
    {
      s.Normal = { { 0.0, 0.0, 0.0 } };
    }
    EstimationSettings estimate;
    estimate.EstimateNormals = true;
    SerialRunner serial;
    Results withExact(exact.size(), false), withNoisy(exact.size(), false),
      estimated(exact.size(), false);
    const EstimationSummary keptSummary = Estimate(exact, EstimationSettings{}, withExact, serial);
    const EstimationSummary noisySummary = Estimate(noisy, EstimationSettings{}, withNoisy, serial);
    Estimate(none, estimate, estimated, serial);
    const auto rmse = [&exact](const Results& r)
    {
      double squared = 0.0;
      for (std::size_t i = 0; i < exact.size(); ++i)
      {
        squared += SortedSquaredError(r, exact[i], i);
      }
      return std::sqrt(squared / exact.size());
    };
    std::printf("%s: k RMSE %.4f exact normals, %.4f noisy normals given, %.4f estimated\n",
      surface.Name.c_str(),
      rmse(withExact),
      rmse(withNoisy),
      rmse(estimated));
    const std::string name = surface.Name + " with noisy given normals";
    checks.True((name + ": recognised and replaced").c_str(), noisySummary.GivenNormalsReplaced);
    checks.True((name + ": exact normals kept").c_str(), !keptSummary.GivenNormalsReplaced);
    checks.True((name + ": no worse than no normals given").c_str(),
      rmse(withNoisy) <= 1.001 * rmse(estimated));
    ThreadRunner threads(2);
    Results threaded(exact.size(), false);
    Estimate(noisy, EstimationSettings{}, threaded, threads);
    checks.True(
      (name + ": 2 threads bit-identical to 1").c_str(), withNoisy.BitIdentical(threaded));
    // The curvatures' signs follow the normals: the exact ones' where the
    // mean curvature is clearly not zero.
    std::size_t clear = 0, agreeing = 0;
    for (std::size_t i = 0; i < exact.size(); ++i)
    {
      const double mean = exact[i].MinimumCurvature + exact[i].MaximumCurvature;
      if (withNoisy.Valid[i] && std::fabs(mean) > 0.5)
      {
        ++clear;
        agreeing += (withNoisy.Minimum[i] + withNoisy.Maximum[i]) * mean > 0.0;
      }
    }
    checks.True(
      (name + ": the given orientation kept").c_str(), clear == 0 || agreeing >= 0.95 * clear);
  }
}

/// The orientation graph's lists, built by hand: every point's one edge
/// goes to point 0 (and point 0's to point 1, which the reverse edge makes
/// redundant), so point 0's list holds every other point in order: more
/// than 255 entries at 1000 points (the build's one-byte counts overflow,
/// and it counts again in 32 bits), fewer at 100. Any thread count.
void TestOrientationGraphLists(Checks& checks)
{
  for (const std::int64_t n : { 100, 1000 })
  {
    for (const int threadCount : { 1, 3 })
    {
      PlaneFits fits;
      fits.GraphNeighbors = 1;
      fits.Normals.assign(3 * n, 0.0);
      fits.Neighbors.Assign(n, n - 1);
      for (std::int64_t a = 0; a < n; ++a)
      {
        fits.Normals[3 * a + 2] = 1.0;
        fits.Neighbors.Set(a, a == 0 ? 1 : 0);
      }
      ThreadRunner runner(threadCount);
      DropRepeatedEdges(fits, runner);
      const Graph<std::int32_t> graph(fits, runner);
      bool right = graph.Start.size() == static_cast<std::size_t>(n + 1) &&
        graph.Start[1] == n - 1 && graph.Start[n] == 2 * (n - 1);
      for (std::int64_t e = 0; right && e < n - 1; ++e)
      {
        right = graph.Entries[e].Target == e + 1 &&
          edge::Propagate(graph.Entries[e].Code, 1) == 1 &&
          edge::BucketOf(graph.Entries[e].Code) == 0;
      }
      for (std::int64_t a = 1; right && a < n; ++a)
      {
        right =
          graph.Start[a + 1] - graph.Start[a] == 1 && graph.Entries[graph.Start[a]].Target == 0;
      }
      const std::string name = "orientation graph of " + std::to_string(n) + " points, " +
        std::to_string(threadCount) + " thread(s): the hub lists every other point in order";
      checks.True(name.c_str(), right);
    }
  }
}

/// An orientation graph of 300 neighbours a point: every point has more
/// than 255 entries (too many for the graph build's one-byte counts; it
/// then counts again in wider integers). The normals' signs follow the
/// graph's edges, so a misplaced entry turns some normal inward: every
/// normal of the sphere is outward, and the same for any thread count.
void TestWideOrientationGraph(Checks& checks)
{
  const auto samples = testing::Sample(testing::Sphere(2.0), 3000, 23);
  NormalSettings settings;
  settings.NumberOfNeighbors = 300;
  settings.GraphNeighbors = 300;
  SerialRunner serial;
  std::vector<double> normals(3 * samples.size());
  const NormalSummary summary =
    EstimateCloudNormals(MakeCloud(samples), settings, Collectives{}, serial, normals.data());
  int outward = 0;
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    outward += testing::Dot({ { normals[3 * i], normals[3 * i + 1], normals[3 * i + 2] } },
                 samples[i].Normal) > 0.9;
  }
  checks.Equal("wide graph: every normal outward", outward, static_cast<int>(samples.size()));
  checks.Equal("wide graph: one connected part", summary.Components, 1);
  ThreadRunner threads(3);
  std::vector<double> threaded(normals.size());
  EstimateCloudNormals(MakeCloud(samples), settings, Collectives{}, threads, threaded.data());
  checks.True("wide graph: 3 threads bit-identical to 1", threaded == normals);
}

} // namespace

int main(int argc, char* argv[])
{
  return RunNamedTests(argc,
    argv,
    {
      { "NormalEstimation", TestNormalEstimation },
      { "ScanLineNormals", TestScanLineNormals },
      { "HeavyNoiseNormals", TestHeavyNoiseNormals },
      { "NoisyGivenNormals", TestNoisyGivenNormals },
      { "OrientationGraphLists", TestOrientationGraphLists },
      { "WideOrientationGraph", TestWideOrientationGraph },
    });
}
