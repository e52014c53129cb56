// Benchmark of the normal estimation alone (a program, not a test): the
// numeric core's EstimateCloudNormals on an analytic cloud with exact
// normals, as vtkPointCloudNormalEstimation runs it.
//
//   NormalEstimationBenchmark [--points 1000000] [--threads 2] [--runs 3]
//                             [--surface torus|sphere|ellipsoid] [--noise 0]
//                             [--dense 0]
//
// Prints each run's wall time and processor time (all threads), their
// medians (the wall time also per million points), the accuracy against
// the exact normals (median, 95th percentile and largest angle, the share
// pointing outward), the connected parts, and a checksum of the normals'
// bits: equal checksums mean bit-identical normals, which is how a faster
// method is checked against the previous one. --noise moves the points
// along their normals (Gaussian, that standard deviation); --dense draws
// that share of them into a blob 50 times smaller (dense cells). For
// instruction counts, run it under valgrind --tool=callgrind with --runs 1.
#include "AnalyticSurfaces.h"
#include "Cloud/CloudStatistics.h"
#include "Estimation/CloudEstimation.h"
#include "ThreadRunner.h"
#include "Normals/NormalEstimation.h"

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace
{
using namespace pcurv;

using testing::ThreadRunner;

struct Options
{
  int Points = 1000000;
  int Threads = 2;
  int Runs = 3;
  std::string Surface = "torus";
  double Noise = 0.0;
  double Dense = 0.0;
};

bool Parse(int argc, char* argv[], Options& options)
{
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string name = argv[i];
    const char* value = argv[i + 1];
    if (name == "--points")
      options.Points = std::atoi(value);
    else if (name == "--threads")
      options.Threads = std::atoi(value);
    else if (name == "--runs")
      options.Runs = std::atoi(value);
    else if (name == "--surface")
      options.Surface = value;
    else if (name == "--noise")
      options.Noise = std::atof(value);
    else if (name == "--dense")
      options.Dense = std::atof(value);
    else
      return false;
  }
  return argc % 2 == 1 && options.Points > 0 && options.Threads > 0 && options.Runs > 0;
}

testing::Surface MakeSurface(const std::string& name)
{
  if (name == "sphere")
    return testing::Sphere(2.0);
  if (name == "ellipsoid")
    return testing::Ellipsoid(3.0, 2.0, 1.5);
  return testing::Torus(3.0, 1.0);
}

/// The samples moved along their normals by Gaussian noise of `sigma`; a
/// share `dense` of them drawn 50 times nearer to the first sample (a
/// dense blob, whose cells the grid searches through finer cells).
CloudPoints MakeCloud(const std::vector<testing::SurfaceSample>& samples,
  double sigma,
  double dense)
{
  const std::size_t blob = static_cast<std::size_t>(dense * samples.size());
  testing::Random random(97);
  CloudPoints cloud;
  cloud.Reset(static_cast<std::int64_t>(samples.size()));
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    const double h = sigma > 0.0 ? sigma * random.Normal() : 0.0;
    double x[3];
    for (int k = 0; k < 3; ++k)
    {
      x[k] = samples[i].Point[k] + h * samples[i].Normal[k];
      if (i < blob)
      {
        x[k] = samples[0].Point[k] + (x[k] - samples[0].Point[k]) / 50.0;
      }
    }
    const double none[3] = { 0.0, 0.0, 0.0 };
    cloud.AddInputPoint(static_cast<std::int64_t>(i), x, none);
  }
  return cloud;
}

/// Seconds of processor time the process has used (all its threads): less
/// sensitive than the wall time to other jobs on a shared machine.
double ProcessorSeconds()
{
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

/// FNV-1a over the normals' bytes.
std::uint64_t Checksum(const std::vector<double>& values)
{
  std::uint64_t hash = 1469598103934665603ull;
  const unsigned char* bytes = reinterpret_cast<const unsigned char*>(values.data());
  for (std::size_t i = 0; i < values.size() * sizeof(double); ++i)
  {
    hash = (hash ^ bytes[i]) * 1099511628211ull;
  }
  return hash;
}

double Quantile(std::vector<double> values, double q)
{
  const std::size_t i = std::min(values.size() - 1, static_cast<std::size_t>(q * values.size()));
  std::nth_element(values.begin(), values.begin() + i, values.end());
  return values[i];
}

void ReportAccuracy(const std::vector<testing::SurfaceSample>& samples,
  const std::vector<double>& normals)
{
  std::vector<double> angles;
  std::size_t outward = 0;
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    const double dot = testing::Dot(
      { { normals[3 * i], normals[3 * i + 1], normals[3 * i + 2] } }, samples[i].Normal);
    outward += dot > 0.0;
    angles.push_back(std::acos(std::min(1.0, std::fabs(dot))) * 180.0 / testing::Pi);
  }
  std::printf("angle to exact (deg): median %.6f  p95 %.6f  max %.6f;  outward %zu of %zu\n",
    Quantile(angles, 0.5),
    Quantile(angles, 0.95),
    *std::max_element(angles.begin(), angles.end()),
    outward,
    samples.size());
}
} // namespace

int main(int argc, char* argv[])
{
  Options options;
  if (!Parse(argc, argv, options))
  {
    std::fprintf(stderr,
      "usage: NormalEstimationBenchmark [--points N] [--threads T] [--runs R] "
      "[--surface torus|sphere|ellipsoid] [--noise SIGMA] [--dense SHARE]\n");
    return 2;
  }
  const auto samples = testing::Sample(MakeSurface(options.Surface), options.Points, 21);
  const CloudPoints cloud = MakeCloud(samples, options.Noise, options.Dense);
  ThreadRunner runner(options.Threads);
  std::vector<double> normals(3 * samples.size()), seconds, processor;
  NormalSummary summary;
  for (int run = 0; run < options.Runs; ++run)
  {
    const auto start = std::chrono::steady_clock::now();
    const double startProcessor = ProcessorSeconds();
    summary =
      EstimateCloudNormals(cloud, NormalSettings{}, Collectives{}, runner, normals.data(), nullptr);
    seconds.push_back(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    processor.push_back(ProcessorSeconds() - startProcessor);
    std::printf("run %d: %.3f s (processor %.3f s)\n", run + 1, seconds.back(), processor.back());
  }
  const double median = Quantile(seconds, 0.5);
  std::printf("%s, %d points, %d threads: median %.3f s (%.3f s per 1M points), processor %.3f s\n",
    options.Surface.c_str(),
    options.Points,
    options.Threads,
    median,
    median * 1e6 / options.Points,
    Quantile(processor, 0.5));
  ReportAccuracy(samples, normals);
  std::printf("components %lld, undetermined %lld, checksum %016llx\n",
    static_cast<long long>(summary.Components),
    static_cast<long long>(summary.Undetermined),
    static_cast<unsigned long long>(Checksum(normals)));
  return 0;
}
