// The core's cloud-level entry point (no VTK): accuracy and sign on analytic
// clouds, results independent of the runner's threads and of the cloud's
// unit, flags, the stop request, repeated points and the derived outputs.
#include "CloudTestSupport.h"

namespace
{
using namespace pcurv;
using namespace cloudtest;

void TestAccuracyAndSign(Checks& checks)
{
  const auto sphere = testing::Sample(testing::Sphere(2.0), 20000, 11);
  SerialRunner serial;
  Results r(sphere.size(), false);
  EstimationSettings paper;
  paper.Mode = FitMode::New01;
  paper.Neighborhood = NeighborhoodMode::Radius;
  const EstimationSummary summary = Estimate(sphere, paper, r, serial);
  checks.True("sphere: every point estimated", summary.NumberOfUnestimatedPoints == 0);
  checks.Near("sphere: k = +1/R with outward normals", MeanError(sphere, r), 0.0, 0.01);
  checks.True("sphere: automatic s reported", summary.UsedSurroundingsThreshold > 0.0);
  checks.Near("sphere: p = s / 10",
    summary.UsedPlaneDistanceThreshold,
    0.1 * summary.UsedSurroundingsThreshold,
    1e-15);

  const auto torus = testing::Sample(testing::Torus(3.0, 1.0), 30000, 12);
  for (int mode = 0; mode < 3; ++mode)
  {
    EstimationSettings settings;
    settings.Mode = static_cast<FitMode>(mode);
    Results t(torus.size(), false);
    Estimate(torus, settings, t, serial);
    checks.Near("torus: mean error per fit mode", MeanError(torus, t), 0.0, 0.02);
    // The maximum direction: a tangent (orthogonal to the exact normal,
    // which the estimator was given) and along the exact one.
    double notTangent = 0.0;
    int samples = 0, within = 0;
    for (std::size_t i = 0; i < torus.size(); i += 101, ++samples)
    {
      const double* d = &t.MaximumDirection[3 * i];
      notTangent =
        std::max(notTangent, std::fabs(testing::Dot({ { d[0], d[1], d[2] } }, torus[i].Normal)));
      within += std::fabs(testing::Dot({ { d[0], d[1], d[2] } }, torus[i].MaximumDirection)) >
        std::cos(8.0 * 3.141592653589793 / 180.0);
    }
    checks.Near("torus: maximum direction orthogonal to the normal", notTangent, 0.0, 1e-9);
    checks.True("torus: maximum direction within 8 degrees of the exact one at 99 % of points",
      within >= 0.99 * samples);
  }
}

void TestRunnerIndependence(Checks& checks)
{
  const auto torus = testing::Sample(testing::Torus(3.0, 1.0), 20000, 13);
  for (bool adjusted : { false, true })
  {
    EstimationSettings settings;
    settings.DynamicAdjustment = adjusted;
    settings.Mode = FitMode::New02;
    SerialRunner serial;
    ThreadRunner threads(3);
    Results one(torus.size(), adjusted), three(torus.size(), adjusted);
    Estimate(torus, settings, one, serial);
    Estimate(torus, settings, three, threads);
    checks.True(adjusted ? "adjustment: 3 threads bit-identical to 1"
                         : "fixed radius: 3 threads bit-identical to 1",
      one.BitIdentical(three));
    if (adjusted)
    {
      checks.True("adjustment: target counts written", one.TargetCount[0] == 375);
    }
  }
}

void TestWorkingUnit(Checks& checks)
{
  const auto sphere = testing::Sample(testing::Sphere(2.0), 5000, 14);
  SerialRunner serial;
  const double scale = std::ldexp(1.0, -600);
  Results unit(sphere.size(), false), tiny(sphere.size(), false);
  const EstimationSummary a = Estimate(sphere, EstimationSettings{}, unit, serial);
  const EstimationSummary b = Estimate(sphere, EstimationSettings{}, tiny, serial, scale);
  bool exact = true;
  for (std::size_t i = 0; i < sphere.size(); ++i)
  {
    exact = exact && tiny.Minimum[i] == unit.Minimum[i] / scale &&
      tiny.Surroundings[i] == unit.Surroundings[i] * scale;
  }
  checks.True("a cloud scaled by 2^-600: curvatures and lengths scale exactly", exact);
  checks.True("a cloud scaled by 2^-600: s reported in the input's unit",
    b.UsedSurroundingsThreshold == a.UsedSurroundingsThreshold * scale);

  // Subnormal coordinates (2^-1060: 14 bits left): the working unit cannot
  // be 2^1061, which is Inf. The curvature, 2^1059, is beyond the double
  // range itself: Inf where estimated, never NaN.
  Results subnormal(sphere.size(), false);
  Estimate(sphere, EstimationSettings{}, subnormal, serial, std::ldexp(1.0, -1060));
  bool noNaN = true;
  for (std::size_t i = 0; i < sphere.size(); ++i)
  {
    noNaN = noNaN &&
      (subnormal.Valid[i] ? !std::isnan(subnormal.Minimum[i]) && !std::isnan(subnormal.Maximum[i])
                          : std::isnan(subnormal.Minimum[i]));
  }
  checks.True("a cloud of subnormal coordinates: no NaN where estimated", noNaN);
}

void TestFlaggedAndStopped(Checks& checks)
{
  auto sphere = testing::Sample(testing::Sphere(2.0), 5000, 15);
  sphere[10].Point[0] = std::nan("");
  sphere[20].Normal = { { 0.0, 0.0, 0.0 } };
  SerialRunner serial;
  Results r(sphere.size(), false);
  const EstimationSummary summary = Estimate(sphere, EstimationSettings{}, r, serial);
  checks.True("a NaN coordinate and a zero normal: two points flagged",
    summary.NumberOfUnestimatedPoints == 2 && !r.Valid[10] && !r.Valid[20] &&
      std::isnan(r.Minimum[10]) && std::isnan(r.Mean[20]));
  checks.True("their reasons: one bad coordinate, one missing normal",
    summary.UnestimatedByReason[static_cast<int>(UnestimatedReason::BadCoordinate)] == 1 &&
      summary.UnestimatedByReason[static_cast<int>(UnestimatedReason::NoNormal)] == 1);
  StopAtOnce stop;
  Results stopped(sphere.size(), false);
  checks.True("a monitor that says stop: the summary says aborted",
    Estimate(sphere, EstimationSettings{}, stopped, serial, 1.0, &stop).Aborted);

  // Progress from two threads at once, over the normals and the curvatures.
  ThreadRunner threads(2);
  EstimationSettings withNormals;
  withNormals.EstimateNormals = true;
  RecordingMonitor all;
  Results reported(sphere.size(), false);
  checks.True("progress from two threads: many reports in [0, 1], reaching 1",
    !Estimate(sphere, withNormals, reported, threads, 1.0, &all).Aborted && all.Reports >= 20 &&
      all.InRange && all.Largest == 1.0);
  RecordingMonitor early(0.1);
  checks.True("a stop during the normals' stage ends the estimation there",
    Estimate(sphere, withNormals, reported, threads, 1.0, &early).Aborted && early.Largest < 0.45);

  EstimationSettings clamped;
  clamped.DynamicAdjustment = true;
  clamped.Adjustment.TargetNeighborCounts = { { std::nan(""), 1e300, 100.0 } };
  Results c(sphere.size(), true);
  const EstimationSummary s = Estimate(sphere, clamped, c, serial);
  checks.True("target counts clamped to [1, 1e6] and reported",
    s.TargetCountsClamped && s.TargetNeighborCounts[0] == 1.0 && s.TargetNeighborCounts[1] == 1e6);
}

/// A cloud with no typical radius (one point, or every point at one place)
/// gives the adjustment a length unit of 0: every point flagged, and no
/// undefined behavior on the way (the fuzzer found a NaN block index).
void TestAdjustmentWithoutSpacing(Checks& checks)
{
  for (int copies : { 1, 12 })
  {
    std::vector<testing::SurfaceSample> same(copies);
    for (testing::SurfaceSample& sample : same)
    {
      sample.Point = { { 1.0, 2.0, 3.0 } };
      sample.Normal = { { 0.0, 0.0, 1.0 } };
    }
    EstimationSettings settings;
    settings.DynamicAdjustment = true;
    SerialRunner serial;
    Results r(same.size(), true);
    const EstimationSummary summary = Estimate(same, settings, r, serial);
    checks.True(copies == 1 ? "adjustment on one point: flagged"
                            : "adjustment on coincident points: all flagged",
      summary.NumberOfUnestimatedPoints == copies && summary.UsedLengthUnit == 0.0);
  }
}

/// Exact copies of one point (a lidar's no-return points at the origin,
/// merged scans) are estimated once: the other points keep their results
/// bit for bit, every copy gets the copied point's, and (with the copies
/// counted once) neither the cost nor the automatic radius depends on how
/// many there are.
void TestRepeatedPoints(Checks& checks)
{
  const auto torus = testing::Sample(testing::Torus(3.0, 1.0), 20000, 23);
  std::vector<testing::SurfaceSample> withCopies = torus;
  withCopies.insert(withCopies.end(), 20000, torus[5]);
  for (bool estimateNormals : { false, true })
  {
    EstimationSettings settings;
    settings.EstimateNormals = estimateNormals;
    SerialRunner serial;
    Results alone(torus.size(), false), copied(withCopies.size(), false);
    std::vector<double> aloneNormals(3 * torus.size()), copiedNormals(3 * withCopies.size());
    CurvatureBuffers a = alone.Buffers(), c = copied.Buffers();
    a.Normals = estimateNormals ? aloneNormals.data() : nullptr;
    c.Normals = estimateNormals ? copiedNormals.data() : nullptr;
    EstimateCloud(MakeCloud(torus), settings, Collectives{}, serial, nullptr, a);
    const EstimationSummary summary =
      EstimateCloud(MakeCloud(withCopies), settings, Collectives{}, serial, nullptr, c);
    const std::string label = estimateNormals ? "estimated normals: " : "";
    checks.Equal((label + "20000 copies reported").c_str(), summary.NumberOfRepeatedPoints, 20000);
    bool same = true, copiesSame = true;
    for (std::size_t i = 0; i < torus.size(); ++i)
    {
      same = same && copied.Minimum[i] == alone.Minimum[i] &&
        copied.Maximum[i] == alone.Maximum[i] &&
        copied.NeighborCount[i] == alone.NeighborCount[i] &&
        copied.Surroundings[i] == alone.Surroundings[i];
    }
    for (std::size_t i = torus.size(); i < withCopies.size(); ++i)
    {
      copiesSame = copiesSame && copied.Minimum[i] == alone.Minimum[5] &&
        copied.MaximumDirection[3 * i] == alone.MaximumDirection[15] &&
        (!estimateNormals || copiedNormals[3 * i + 2] == aloneNormals[17]);
    }
    checks.True(
      (label + "the other points bit-identical to the cloud without copies").c_str(), same);
    checks.True((label + "every copy gets the copied point's results").c_str(), copiesSame);
  }
}

/// The robust color limit: the 95th percentile of |values| to within one
/// bin (2^(1/16)), NaN and infinity ignored; and the clipped mean curvature
/// of an estimation within it, equal to the mean curvature inside.
void TestClippedMean(Checks& checks)
{
  std::vector<double> values;
  for (int i = 1; i <= 1000; ++i)
  {
    values.push_back(i % 2 ? i : -i);
  }
  values.push_back(std::nan(""));
  values.push_back(HUGE_VAL);
  values.push_back(1e300); // an outlier moves the limit by one value only
  const double c =
    MagnitudeQuantile(values.data(), static_cast<std::int64_t>(values.size()), 0.95, Collectives{});
  checks.True("95th percentile of |1..1000|: 951 to 951 x 2^(1/16)",
    c >= 951.0 && c <= 951.0 * std::exp2(1.0 / 16.0));
  checks.True("no finite value: limit 0",
    MagnitudeQuantile(values.data() + 1000, 2, 0.95, Collectives{}) == 0.0);

  auto torus = testing::Sample(testing::Torus(3.0, 1.0), 20000, 41);
  Results r(torus.size(), false);
  std::vector<double> clipped(torus.size());
  CurvatureBuffers buffers = r.Buffers();
  buffers.ClippedMean = clipped.data();
  SerialRunner serial;
  const EstimationSummary summary =
    EstimateCloud(MakeCloud(torus), EstimationSettings{}, Collectives{}, serial, nullptr, buffers);
  const double clip = summary.MeanCurvatureClip;
  int wrong = 0, inside = 0;
  for (std::size_t i = 0; i < torus.size(); ++i)
  {
    const double expected = std::min(std::max(r.Mean[i], -clip), clip);
    wrong += !(clipped[i] == expected || (std::isnan(clipped[i]) && std::isnan(r.Mean[i])));
    inside += std::fabs(r.Mean[i]) <= clip;
  }
  checks.True("torus: the clipped mean curvature is the mean curvature clamped to [-c, c]",
    wrong == 0 && clip > 0.0);
  checks.True("torus: at least 95 % of the points inside the limit, which is within the "
              "exact range of |H| (5/8) and a bin",
    inside >= 0.95 * torus.size() && clip <= 0.625 * 1.1);
}

/// Shape index and curvedness with the output's signs: a sphere with
/// outward normals is a cap (+1), a cylinder a ridge (+1/2), and with the
/// normals turned inwards a cup (-1) and a rut (-1/2).
void TestShapeIndex(Checks& checks)
{
  SerialRunner serial;
  struct Case
  {
    const char* Name;
    testing::Surface Surface;
    double Index;
    double Curvedness;
  };
  const Case cases[] = { { "sphere R 2", testing::Sphere(2.0), 1.0, 0.5 },
    { "cylinder r 1", testing::Cylinder(1.0, 8.0), 0.5, std::sqrt(0.5) } };
  for (const Case& c : cases)
  {
    for (const double side : { 1.0, -1.0 })
    {
      auto samples = testing::Sample(c.Surface, 20000, 51);
      for (auto& sample : samples)
      {
        sample.Normal = testing::Scale(side, sample.Normal);
      }
      Results r(samples.size(), false);
      std::vector<double> index(samples.size()), curvedness(samples.size());
      CurvatureBuffers buffers = r.Buffers();
      buffers.ShapeIndex = index.data();
      buffers.Curvedness = curvedness.data();
      EstimateCloud(
        MakeCloud(samples), EstimationSettings{}, Collectives{}, serial, nullptr, buffers);
      std::vector<double> interiorIndex, interiorCurvedness;
      for (std::size_t i = 0; i < samples.size(); ++i)
      {
        if (r.Valid[i] && samples[i].BoundaryDistance > 1.0)
        {
          interiorIndex.push_back(index[i]);
          interiorCurvedness.push_back(curvedness[i]);
        }
      }
      std::nth_element(interiorIndex.begin(),
        interiorIndex.begin() + interiorIndex.size() / 2,
        interiorIndex.end());
      std::nth_element(interiorCurvedness.begin(),
        interiorCurvedness.begin() + interiorCurvedness.size() / 2,
        interiorCurvedness.end());
      const std::string label = std::string(c.Name) + (side > 0 ? ", outward" : ", inward");
      checks.Near((label + ": shape index (median)").c_str(),
        interiorIndex[interiorIndex.size() / 2],
        side * c.Index,
        0.02);
      checks.Near((label + ": curvedness (median)").c_str(),
        interiorCurvedness[interiorCurvedness.size() / 2],
        c.Curvedness,
        0.01 * c.Curvedness);
    }
  }
}

} // namespace

int main(int argc, char* argv[])
{
  return RunNamedTests(argc,
    argv,
    {
      { "AccuracyAndSign", TestAccuracyAndSign },
      { "RunnerIndependence", TestRunnerIndependence },
      { "WorkingUnit", TestWorkingUnit },
      { "FlaggedAndStopped", TestFlaggedAndStopped },
      { "AdjustmentWithoutSpacing", TestAdjustmentWithoutSpacing },
      { "RepeatedPoints", TestRepeatedPoints },
      { "ClippedMean", TestClippedMean },
      { "ShapeIndex", TestShapeIndex },
    });
}
