// Benchmark of the curvature lines (a program, not a test): the numeric
// core's curvature estimation and then its line extraction on the same
// analytic cloud, on the same threads, as vtkPrincipalCurvatureEstimation
// and vtkCurvatureLines run them.
//
//   CurvatureLinesBenchmark [--points 1000000] [--threads 2] [--noise 0]
//
// --noise moves the points (Gaussian, that many spacings). Prints the wall
// time of each stage, their ratio (lines / curvatures), the same for the
// processor time of all threads, and the lines found (count, total
// length).
#include "AnalyticSurfaces.h"
#include "Cloud/CloudPoints.h"
#include "Estimation/CloudEstimation.h"
#include "Lines/CurvatureLines.h"
#include "ThreadRunner.h"

#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace
{
using namespace pcurv;

double Seconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

/// The process's processor time since `since` (all threads): steadier
/// than wall time on a shared machine.
double ProcessorSeconds(std::clock_t since)
{
  return static_cast<double>(std::clock() - since) / CLOCKS_PER_SEC;
}

} // namespace

int main(int argc, char* argv[])
{
  int points = 1000000, threads = 2;
  double noise = 0.0;
  for (int i = 1; i + 1 < argc; i += 2)
  {
    if (!std::strcmp(argv[i], "--points"))
    {
      points = std::atoi(argv[i + 1]);
    }
    else if (!std::strcmp(argv[i], "--threads"))
    {
      threads = std::atoi(argv[i + 1]);
    }
    else if (!std::strcmp(argv[i], "--noise"))
    {
      noise = std::atof(argv[i + 1]);
    }
  }
  auto samples = testing::Sample(testing::Ellipsoid(3.0, 2.0, 1.0), points, 91);
  const double spacing = std::sqrt(4.0 * testing::Pi * 4.0 / points); // about
  if (noise > 0.0)
  {
    testing::AddPositionNoise(samples, noise * spacing, 92);
  }
  const std::size_t n = samples.size();
  CloudPoints cloud;
  cloud.Reset(static_cast<std::int64_t>(n));
  std::vector<double> xyz, normals;
  for (std::size_t i = 0; i < n; ++i)
  {
    cloud.AddInputPoint(
      static_cast<std::int64_t>(i), samples[i].Point.data(), samples[i].Normal.data());
    xyz.insert(xyz.end(), samples[i].Point.begin(), samples[i].Point.end());
    normals.insert(normals.end(), samples[i].Normal.begin(), samples[i].Normal.end());
  }
  std::vector<double> kMin(n), kMax(n), mean(n), gauss(n), dMin(3 * n), dMax(3 * n), rms(n),
    radius(n), plane(n), standardError(n);
  std::vector<unsigned char> valid(n);
  std::vector<int> count(n), directions(n);
  CurvatureBuffers buffers{ kMin.data(),
    kMax.data(),
    mean.data(),
    gauss.data(),
    dMin.data(),
    dMax.data(),
    rms.data(),
    radius.data(),
    plane.data(),
    valid.data(),
    count.data(),
    directions.data(),
    nullptr };
  buffers.StandardError = standardError.data();
  testing::ThreadRunner runner(threads);
  auto start = std::chrono::steady_clock::now();
  std::clock_t processorStart = std::clock();
  EstimateCloud(std::move(cloud), EstimationSettings{}, Collectives{}, runner, nullptr, buffers);
  const double curvatureSeconds = Seconds(start);
  const double curvatureProcessor = ProcessorSeconds(processorStart);

  LineInput in;
  in.Count = static_cast<std::int64_t>(n);
  in.Points = xyz.data();
  in.Normals = normals.data();
  in.MaximumCurvature = kMax.data();
  in.MinimumCurvature = kMin.data();
  in.MaximumDirection = dMax.data();
  in.MinimumDirection = dMin.data();
  in.StandardError = standardError.data();
  in.Radius = radius.data();
  in.Valid = valid.data();
  LineSettings settings;
  settings.Kinds = AllLineKinds;
  start = std::chrono::steady_clock::now();
  processorStart = std::clock();
  const LineResult result = ExtractCurvatureLines(in, settings, &runner);
  const double lineSeconds = Seconds(start);
  const double lineProcessor = ProcessorSeconds(processorStart);
  double length = 0.0;
  for (const CurvatureLine& line : result.Lines)
  {
    length += line.Length;
  }
  std::printf("points %zu, threads %d, noise %.2f spacings\n", n, threads, noise);
  std::printf("curvatures: %.2f s\nlines: %.2f s (%.2fx the curvatures)\n",
    curvatureSeconds,
    lineSeconds,
    lineSeconds / curvatureSeconds);
  std::printf("processor time: curvatures %.2f s, lines %.2f s (%.2fx)\n",
    curvatureProcessor,
    lineProcessor,
    lineProcessor / curvatureProcessor);
  std::printf("lines: %zu, total length %.3f, crossings %lld\n",
    result.Lines.size(),
    length,
    static_cast<long long>(result.Crossings));
  return 0;
}
