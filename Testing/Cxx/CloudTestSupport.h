/**
 * @file CloudTestSupport.h
 * @brief What the core's cloud-level tests share: owned output arrays,
 * clouds from analytic samples, monitors, runs and error measures.
 */
#ifndef CloudTestSupport_h
#define CloudTestSupport_h

#include "AnalyticSurfaces.h"
#include "Cloud/CloudStatistics.h"
#include "Estimation/CloudEstimation.h"
#include "Fits/HeightJet.h"
#include "Neighbors/PointGrid.h"
#include "Normals/OrientationGraph.h"
#include "ThreadRunner.h"
#include "TestChecks.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace cloudtest
{
using namespace pcurv;

/// Every output array of an estimation, owned.
struct Results
{
  explicit Results(std::size_t n, bool adjusted)
    : Minimum(n)
    , Maximum(n)
    , Mean(n)
    , Gauss(n)
    , MinimumDirection(3 * n)
    , MaximumDirection(3 * n)
    , SineFitRms(n)
    , Surroundings(n)
    , PlaneDistance(n)
    , Valid(n)
    , NeighborCount(n)
    , ValidDirections(n)
    , TargetCount(adjusted ? n : 0)
    , Outlier(n)
    , SurfaceDistance(n)
  {
  }

  CurvatureBuffers Buffers()
  {
    CurvatureBuffers buffers{ Minimum.data(),
      Maximum.data(),
      Mean.data(),
      Gauss.data(),
      MinimumDirection.data(),
      MaximumDirection.data(),
      SineFitRms.data(),
      Surroundings.data(),
      PlaneDistance.data(),
      Valid.data(),
      NeighborCount.data(),
      ValidDirections.data(),
      TargetCount.empty() ? nullptr : TargetCount.data() };
    buffers.Outlier = Outlier.data();
    buffers.SurfaceDistance = SurfaceDistance.data();
    return buffers;
  }

  bool BitIdentical(const Results& other) const
  {
    auto same = [](const auto& a, const auto& b)
    {
      // Bits, so that NaN equals NaN; an empty vector's data() may be null.
      return a.size() == b.size() &&
        (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0);
    };
    return same(Minimum, other.Minimum) && same(Maximum, other.Maximum) && same(Mean, other.Mean) &&
      same(Gauss, other.Gauss) && same(MinimumDirection, other.MinimumDirection) &&
      same(MaximumDirection, other.MaximumDirection) && same(SineFitRms, other.SineFitRms) &&
      same(Surroundings, other.Surroundings) && same(PlaneDistance, other.PlaneDistance) &&
      same(Valid, other.Valid) && same(NeighborCount, other.NeighborCount) &&
      same(ValidDirections, other.ValidDirections) && same(TargetCount, other.TargetCount) &&
      same(Outlier, other.Outlier) && same(SurfaceDistance, other.SurfaceDistance);
  }

  std::vector<double> Minimum, Maximum, Mean, Gauss, MinimumDirection, MaximumDirection, SineFitRms,
    Surroundings, PlaneDistance;
  std::vector<unsigned char> Valid;
  std::vector<int> NeighborCount, ValidDirections, TargetCount;
  std::vector<unsigned char> Outlier;
  std::vector<double> SurfaceDistance;
};

inline CloudPoints MakeCloud(const std::vector<testing::SurfaceSample>& samples, double scale = 1.0)
{
  CloudPoints cloud;
  cloud.Reset(static_cast<std::int64_t>(samples.size()));
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    const double x[3] = {
      scale * samples[i].Point[0], scale * samples[i].Point[1], scale * samples[i].Point[2]
    };
    cloud.AddInputPoint(static_cast<std::int64_t>(i), x, samples[i].Normal.data());
  }
  return cloud;
}

using testing::ThreadRunner;

/// Stops at the first report.
class StopAtOnce : public ProgressMonitor
{
public:
  bool Continue(double) override { return false; }
};

/// Records the reports, from any thread; stops once past `stopAt`.
class RecordingMonitor : public ProgressMonitor
{
public:
  explicit RecordingMonitor(double stopAt = 2.0)
    : StopAt(stopAt)
  {
  }
  bool Continue(double fraction) override
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    ++this->Reports;
    this->Largest = std::max(this->Largest, fraction);
    this->InRange = this->InRange && fraction >= 0.0 && fraction <= 1.0;
    return fraction <= this->StopAt;
  }
  double StopAt;
  std::mutex Mutex;
  int Reports = 0;
  double Largest = 0.0;
  bool InRange = true;
};

inline EstimationSummary Estimate(const std::vector<testing::SurfaceSample>& samples,
  const EstimationSettings& settings,
  Results& results,
  WorkRunner& runner,
  double scale = 1.0,
  ProgressMonitor* monitor = nullptr)
{
  return EstimateCloud(
    MakeCloud(samples, scale), settings, Collectives{}, runner, monitor, results.Buffers());
}

/// Mean |k - exact| over the points away from the border, both curvatures.
inline double MeanError(const std::vector<testing::SurfaceSample>& samples, const Results& r)
{
  double sum = 0.0;
  int count = 0;
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    if (r.Valid[i])
    {
      sum += std::fabs(r.Minimum[i] - samples[i].MinimumCurvature) +
        std::fabs(r.Maximum[i] - samples[i].MaximumCurvature);
      count += 2;
    }
  }
  return count ? sum / count : HUGE_VAL;
}

/// How the reported standard errors cover the errors max(|dk_min|, |dk_max|)
/// of the valid points: how many are valid, within twice their error and
/// off by more than a fifth of `largest`, and the median error / error.
/// A point's error: the larger of its two principal curvatures' errors.
inline double PointError(const Results& r,
  const std::vector<testing::SurfaceSample>& samples,
  std::size_t i)
{
  return std::max(std::fabs(r.Minimum[i] - samples[i].MinimumCurvature),
    std::fabs(r.Maximum[i] - samples[i].MaximumCurvature));
}

struct ErrorCover
{
  int Valid = 0, Covered = 0, Far = 0;
  double MedianRatio = 0.0;

  double Share() const
  {
    return this->Valid ? static_cast<double>(this->Covered) / this->Valid : 0.0;
  }
};

inline ErrorCover CoverOf(const std::vector<testing::SurfaceSample>& samples,
  const Results& r,
  const std::vector<double>& standardError,
  double largest)
{
  ErrorCover cover;
  std::vector<double> ratios;
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    if (r.Valid[i])
    {
      const double pointError = PointError(r, samples, i);
      ++cover.Valid;
      cover.Covered += pointError <= 2.0 * standardError[i];
      cover.Far += pointError > 0.2 * largest;
      ratios.push_back(pointError / standardError[i]);
    }
  }
  if (!ratios.empty())
  {
    std::nth_element(ratios.begin(), ratios.begin() + ratios.size() / 2, ratios.end());
    cover.MedianRatio = ratios[ratios.size() / 2];
  }
  return cover;
}

/// A cloud estimated with its given normals and the default settings:
/// serially (with the reported standard errors) and on 3 threads.
struct GivenNormalsRun
{
  explicit GivenNormalsRun(const std::vector<testing::SurfaceSample>& samples)
    : Serial(samples.size(), false)
    , Threaded(samples.size(), false)
    , StandardError(samples.size())
  {
    SerialRunner serial;
    ThreadRunner threads(3);
    CurvatureBuffers buffers = this->Serial.Buffers();
    buffers.StandardError = this->StandardError.data();
    this->Summary = EstimateCloud(
      MakeCloud(samples), EstimationSettings{}, Collectives{}, serial, nullptr, buffers);
    Estimate(samples, EstimationSettings{}, this->Threaded, threads);
  }

  Results Serial, Threaded;
  std::vector<double> StandardError;
  EstimationSummary Summary;
};

/// A cloud estimated serially with `settings`, with the reported standard
/// errors, the trust flags and the shape classes.
struct ReportedRun
{
  ReportedRun(const std::vector<testing::SurfaceSample>& samples,
    const EstimationSettings& settings)
    : Out(samples.size(), false)
    , StandardError(samples.size())
    , Trusted(samples.size())
    , ShapeClass(samples.size())
  {
    SerialRunner serial;
    CurvatureBuffers buffers = this->Out.Buffers();
    buffers.StandardError = this->StandardError.data();
    buffers.Trusted = this->Trusted.data();
    buffers.ShapeClass = this->ShapeClass.data();
    this->Summary =
      EstimateCloud(MakeCloud(samples), settings, Collectives{}, serial, nullptr, buffers);
  }

  Results Out;
  std::vector<double> StandardError;
  std::vector<unsigned char> Trusted, ShapeClass;
  EstimationSummary Summary;
};

/// The largest neighbour count among the valid points.
inline int LargestNeighborCount(const Results& r)
{
  int largest = 0;
  for (std::size_t i = 0; i < r.Valid.size(); ++i)
  {
    largest = r.Valid[i] ? std::max(largest, r.NeighborCount[i]) : largest;
  }
  return largest;
}

/// CoordinateSteps of the samples' positions, over a grid of cells about
/// two spacings wide (as the estimation's).
inline std::array<double, 3> StepsOf(const std::vector<testing::SurfaceSample>& samples)
{
  const CloudPoints cloud = MakeCloud(samples);
  double lower[3], upper[3];
  cloud.OwnBounds(lower, upper);
  double area = 1.0;
  for (int k = 0; k < 3; ++k)
  {
    area = std::max(area, upper[k] - lower[k]);
  }
  PointGrid grid;
  const std::int64_t n = cloud.GetNumberOfPoints();
  grid.Build(cloud.Coordinates.data(),
    n,
    GridLattice::Make(lower, upper, n, 2.0 * area / std::sqrt(static_cast<double>(n))));
  return CoordinateSteps(cloud, grid, Collectives{});
}

/// A sphere of radius `radius` sampled along circles x = const, `gap` apart,
/// twelve times denser along them (as a lidar's scan lines), each circle
/// with its own phase; exact normals and curvatures.
inline std::vector<testing::SurfaceSample> ScanLineSphere(double radius,
  double gap,
  std::uint64_t seed)
{
  testing::Random random(seed);
  std::vector<testing::SurfaceSample> samples;
  const double pi = 3.141592653589793;
  const int lines = static_cast<int>(std::round(2.0 * radius / gap));
  const double offset = random.Uniform();
  for (int line = 0; line < lines; ++line)
  {
    const double x = -radius + (line + offset) * (2.0 * radius / lines);
    const double ring = std::sqrt(radius * radius - x * x);
    const int count = std::max(1, static_cast<int>(std::round(2.0 * pi * ring / (gap / 12.0))));
    const double phase = 2.0 * pi * random.Uniform();
    for (int j = 0; j < count; ++j)
    {
      const double angle = phase + 2.0 * pi * j / count;
      testing::SurfaceSample s{};
      s.Point = { { x, ring * std::cos(angle), ring * std::sin(angle) } };
      s.Normal = { { x / radius, s.Point[1] / radius, s.Point[2] / radius } };
      s.MinimumCurvature = s.MaximumCurvature = 1.0 / radius;
      samples.push_back(s);
    }
  }
  return samples;
}

/// Median angle (degrees) between the estimated and the exact maximum
/// directions, as lines, over the estimated points.
inline double MedianDirectionAngle(const std::vector<testing::SurfaceSample>& samples,
  const Results& r)
{
  std::vector<double> angles;
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    if (r.Valid[i])
    {
      const double* d = &r.MaximumDirection[3 * i];
      const double c =
        std::fabs(testing::Dot({ { d[0], d[1], d[2] } }, samples[i].MaximumDirection));
      angles.push_back(std::acos(std::min(1.0, c)) * 180.0 / 3.141592653589793);
    }
  }
  if (angles.empty())
  {
    return HUGE_VAL;
  }
  std::nth_element(angles.begin(), angles.begin() + angles.size() / 2, angles.end());
  return angles[angles.size() / 2];
}

/// Ranges of `grain` items, taken last to first on the calling thread.
class BackwardsRunner : public WorkRunner
{
public:
  void For(std::int64_t count, std::int64_t grain, const RangeWork& work) override
  {
    for (std::int64_t end = count; end > 0; end -= std::min(end, grain))
    {
      work(std::max<std::int64_t>(0, end - grain), end);
    }
  }
};

} // namespace cloudtest

#endif
