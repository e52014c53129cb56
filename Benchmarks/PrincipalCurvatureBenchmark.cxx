// Benchmark of vtkPrincipalCurvatureEstimation: whole filter per fit mode,
// size and thread count; phases measured in-process with the core on
// identical neighbourhoods; the paper's fit-time claim; peak memory;
// accuracy; and CGAL's jet fitting (Monge_via_jet_fitting, degree 2) on the
// same neighbourhoods as a peer. A program, not a test: medians of several
// runs, ratios, printed as tables (and CSV with --csv FILE).
//
//   PrincipalCurvatureBenchmark [--sizes 10000,100000,1000000] [--runs 5]
//     [--threads 1,2] [--peer-points 20000] [--no-peer] [--csv FILE]
#include "AnalyticClouds.h"
#include "PointGrid.h"
#include "PrincipalCurvatureCore.h"
#include "vtkPrincipalCurvatureEstimation.h"

#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#ifdef PCURV_WITH_CGAL
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Simple_cartesian.h>
#endif

#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;
const char* ModeNames[] = { "Previous", "New01", "New02" };

double Seconds(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  return values.empty() ? 0.0 : values[values.size() / 2];
}

std::vector<long> ParseList(const char* text)
{
  std::vector<long> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ','))
  {
    values.push_back(std::atol(item.c_str()));
  }
  return values;
}

/// A memory figure (kB) from /proc/self/status: "VmHWM" (peak resident
/// since the last reset) or "VmRSS" (resident now).
long StatusKilobytes(const char* field)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  const std::string prefix = std::string(field) + ":";
  while (std::getline(status, line))
  {
    if (line.rfind(prefix, 0) == 0)
    {
      return std::atol(line.c_str() + prefix.size());
    }
  }
  return -1;
}

void ResetPeak()
{
  malloc_trim(0); // give freed memory back, so that the peak counts new allocations
  std::ofstream("/proc/self/clear_refs") << "5"; // resets VmHWM to the current RSS
}

long ArrayBytes(vtkPolyData* data)
{
  long bytes = data->GetPoints()->GetData()->GetActualMemorySize() * 1024L;
  for (int i = 0; i < data->GetPointData()->GetNumberOfArrays(); ++i)
  {
    bytes += data->GetPointData()->GetArray(i)->GetActualMemorySize() * 1024L;
  }
  return bytes;
}

struct Options
{
  std::vector<long> Sizes{ 10000, 100000, 1000000 };
  std::vector<long> Threads{ 1, 2 };
  int Runs = 5;
  long PeerPoints = 20000;
  bool Peer = true;
  std::string Csv;
};

Options Parse(int argc, char* argv[])
{
  Options o;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() { return i + 1 < argc ? argv[++i] : ""; };
    if (a == "--sizes")
      o.Sizes = ParseList(next());
    else if (a == "--threads")
      o.Threads = ParseList(next());
    else if (a == "--runs")
      o.Runs = std::max(1, std::atoi(next()));
    else if (a == "--peer-points")
      o.PeerPoints = std::atol(next());
    else if (a == "--no-peer")
      o.Peer = false;
    else if (a == "--csv")
      o.Csv = next();
    else
    {
      std::fprintf(stderr, "unknown option %s\n", a.c_str());
      std::exit(2);
    }
  }
  return o;
}

/// Coordinates and normals of a cloud as flat arrays (for the core).
struct Flat
{
  std::vector<double> Points, Normals;
  explicit Flat(vtkPolyData* cloud)
  {
    const vtkIdType n = cloud->GetNumberOfPoints();
    this->Points.resize(3 * n);
    this->Normals.resize(3 * n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      cloud->GetPoint(i, &this->Points[3 * i]);
      cloud->GetPointData()->GetNormals()->GetTuple(i, &this->Normals[3 * i]);
    }
  }
};

/// Phases on one thread with the core: neighbour search alone; search +
/// binning + sums; + fits and sine fit per mode. Differences give phases.
void MeasurePhases(vtkPolyData* cloud, double s, double p, int runs, std::FILE* csv, long n)
{
  Flat flat(cloud);
  const vtkIdType count = cloud->GetNumberOfPoints();
  const double lower[3] = { -4.1, -4.1, -1.1 }, upper[3] = { 4.1, 4.1, 1.1 };
  pcurv::PointGrid grid;
  grid.Build(flat.Points.data(), count, pcurv::GridLattice::Make(lower, upper, count, 0.5 * s));
  std::vector<double> neighbors;
  pcurv::PointCurvatureEstimator estimator;
  double checksum = 0.0;
  std::vector<double> search, binning, full[3];
  for (int run = 0; run < runs; ++run)
  {
    auto start = Clock::now();
    for (vtkIdType j = 0; j < count; ++j)
    {
      const double* x = &flat.Points[3 * grid.GetSortedId(j)];
      grid.GatherWithinRadius(x, s, neighbors);
      checksum += neighbors.size();
    }
    search.push_back(Seconds(start));
    // Search, then binning and sums, of the j-th point in grid order.
    auto accumulate = [&](vtkIdType j)
    {
      const vtkIdType i = grid.GetSortedId(j);
      const double* x = &flat.Points[3 * i];
      const double* nn = &flat.Normals[3 * i];
      grid.GatherWithinRadius(x, s, neighbors);
      estimator.Begin({ { x[0], x[1], x[2] } }, { { nn[0], nn[1], nn[2] } }, p, s);
      estimator.AddNeighbors(neighbors.data(), neighbors.size() / 3);
    };
    start = Clock::now();
    for (vtkIdType j = 0; j < count; ++j)
    {
      accumulate(j);
    }
    binning.push_back(Seconds(start));
    for (int mode = 0; mode < 3; ++mode)
    {
      pcurv::FitSettings settings;
      settings.Mode = static_cast<pcurv::FitMode>(mode);
      start = Clock::now();
      for (vtkIdType j = 0; j < count; ++j)
      {
        accumulate(j);
        checksum += estimator.Estimate(settings).MaximumCurvature;
      }
      full[mode].push_back(Seconds(start));
    }
  }
  const double tSearch = Median(search), tBinning = Median(binning) - tSearch;
  std::printf("  phases, 1 thread, %ld points (medians of %d): search %.3f s, binning+sums %.3f s",
    n,
    runs,
    tSearch,
    tBinning);
  for (int mode = 0; mode < 3; ++mode)
  {
    const double fits = Median(full[mode]) - Median(binning);
    std::printf(", %s fits+sine %.3f s", ModeNames[mode], fits);
    if (csv)
      std::fprintf(
        csv, "phase,%ld,%s,1,%.6f,%.6f,%.6f\n", n, ModeNames[mode], tSearch, tBinning, fits);
  }
  std::printf("   (checksum %.3g)\n", checksum);
}

/// The paper's claim, on identical CGA sums: time of the fits alone.
void MeasureFitsAlone(vtkPolyData* cloud, double s, double p)
{
  Flat flat(cloud);
  const vtkIdType count = std::min<vtkIdType>(cloud->GetNumberOfPoints(), 20000);
  std::vector<pcurv::CgaSums> sums;
  const double lower[3] = { -4.1, -4.1, -1.1 }, upper[3] = { 4.1, 4.1, 1.1 };
  pcurv::PointGrid grid;
  grid.Build(flat.Points.data(),
    cloud->GetNumberOfPoints(),
    pcurv::GridLattice::Make(lower, upper, cloud->GetNumberOfPoints(), 0.5 * s));
  std::vector<double> neighbors;
  for (vtkIdType i = 0; i < count; ++i)
  {
    const double* x = &flat.Points[3 * i];
    grid.GatherWithinRadius(x, s, neighbors);
    const pcurv::TangentFrame frame = pcurv::MakeTangentFrame(
      { { flat.Normals[3 * i], flat.Normals[3 * i + 1], flat.Normals[3 * i + 2] } });
    std::array<pcurv::CgaSums, 16> direction{};
    for (std::size_t k = 0; k < neighbors.size(); k += 3)
    {
      double d[3];
      for (int c = 0; c < 3; ++c)
        d[c] = (neighbors[k + c] - x[c]) / s;
      const double h = d[0] * frame.Normal[0] + d[1] * frame.Normal[1] + d[2] * frame.Normal[2];
      const double tx = d[0] * frame.V0[0] + d[1] * frame.V0[1] + d[2] * frame.V0[2];
      const double ty = d[0] * frame.W0[0] + d[1] * frame.W0[1] + d[2] * frame.W0[2];
      std::uint32_t mask = pcurv::PointCurvatureEstimator::DirectionMask(tx, ty, p / s);
      for (; mask; mask &= mask - 1)
        direction[__builtin_ctz(mask)].Add(h, d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    }
    sums.insert(sums.end(), direction.begin(), direction.end());
  }
  double checksum = 0.0;
  std::vector<double> times[3];
  for (int run = 0; run < 7; ++run)
  {
    auto start = Clock::now();
    for (const auto& b : sums)
      checksum += pcurv::FitPrevious(b).Curvature;
    times[0].push_back(Seconds(start));
    start = Clock::now();
    for (const auto& b : sums)
      checksum += pcurv::FitEquations23(b).Curvature;
    times[1].push_back(Seconds(start));
    start = Clock::now();
    for (const auto& b : sums) // both closed forms (New02's choice needs the points too)
      checksum += pcurv::FitEquations12(b).Curvature + pcurv::FitEquations23(b).Curvature;
    times[2].push_back(Seconds(start));
  }
  const double previous = Median(times[0]);
  std::printf(
    "fits alone on %zu identical CGA matrices (medians of 7): Previous %.1f ns, New01 %.1f ns "
    "(%.3fx), New02's two closed forms %.1f ns (%.3fx)   (checksum %.3g)\n",
    sums.size(),
    1e9 * previous / sums.size(),
    1e9 * Median(times[1]) / sums.size(),
    Median(times[1]) / previous,
    1e9 * Median(times[2]) / sums.size(),
    Median(times[2]) / previous,
    checksum);
}

#ifdef PCURV_WITH_CGAL
/// CGAL jet fitting (degree 2, Monge degree 2) on the same neighbourhoods.
void MeasurePeer(vtkPolyData* cloud, double s, long queries, std::FILE* csv, long n)
{
  using Kernel = CGAL::Simple_cartesian<double>;
  using Fitting = CGAL::Monge_via_jet_fitting<Kernel>;
  Flat flat(cloud);
  const vtkIdType count = cloud->GetNumberOfPoints();
  const double lower[3] = { -4.1, -4.1, -1.1 }, upper[3] = { 4.1, 4.1, 1.1 };
  pcurv::PointGrid grid;
  grid.Build(flat.Points.data(), count, pcurv::GridLattice::Make(lower, upper, count, 0.5 * s));
  vtkDataArray* exactMin = cloud->GetPointData()->GetArray("Exact_Minimum_Curvature");
  vtkDataArray* exactMax = cloud->GetPointData()->GetArray("Exact_Maximum_Curvature");
  const vtkIdType stride = std::max<vtkIdType>(1, count / queries);
  std::vector<double> neighbors;
  std::vector<Kernel::Point_3> points;
  double errorMin = 0.0, errorMax = 0.0, largest = 0.0;
  long measured = 0;
  auto start = Clock::now();
  for (vtkIdType i = 0; i < count; i += stride)
  {
    const double* x = &flat.Points[3 * i];
    grid.GatherWithinRadius(x, s, neighbors);
    points.clear();
    points.emplace_back(x[0], x[1], x[2]); // the origin of the fit: the query point
    for (std::size_t k = 0; k < neighbors.size(); k += 3)
    {
      if (neighbors[k] != x[0] || neighbors[k + 1] != x[1] || neighbors[k + 2] != x[2])
        points.emplace_back(neighbors[k], neighbors[k + 1], neighbors[k + 2]);
    }
    Fitting fitting;
    Fitting::Monge_form form = fitting(points.begin(), points.end(), 2, 2);
    const double* nn = &flat.Normals[3 * i];
    form.comply_wrt_given_normal(Kernel::Vector_3(nn[0], nn[1], nn[2]));
    // CGAL: z = (k1 x^2 + k2 y^2) / 2 along the normal, k1 >= k2: positive
    // bends towards the normal. Ours is the opposite sign.
    const double kMax = -form.principal_curvatures(1), kMin = -form.principal_curvatures(0);
    if (measured < 5 && std::getenv("PCURV_DEBUG_PEER"))
      std::printf("    peer point %lld: %zu points, k %g %g exact %g %g\n",
        (long long)i,
        points.size(),
        kMin,
        kMax,
        exactMin->GetTuple1(i),
        exactMax->GetTuple1(i));
    errorMin += std::fabs(kMin - exactMin->GetTuple1(i));
    errorMax += std::fabs(kMax - exactMax->GetTuple1(i));
    largest =
      std::max({ largest, std::fabs(exactMin->GetTuple1(i)), std::fabs(exactMax->GetTuple1(i)) });
    ++measured;
  }
  const double seconds = Seconds(start);
  std::printf(
    "  CGAL jet fitting, 1 thread, %ld query points: %.3f s = %.2f us/point (extrapolated to "
    "%ld points: %.2f s); errors k_min %.5f k_max %.5f\n",
    measured,
    seconds,
    1e6 * seconds / measured,
    n,
    seconds / measured * n,
    errorMin / measured / largest,
    errorMax / measured / largest);
  if (csv)
    std::fprintf(csv,
      "peer,%ld,CGAL,1,%.6f,%.6f,%.6f\n",
      n,
      seconds / measured * n,
      errorMin / measured / largest,
      errorMax / measured / largest);
}
#endif
} // namespace

int main(int argc, char* argv[])
{
  const Options options = Parse(argc, argv);
  std::FILE* csv = options.Csv.empty() ? nullptr : std::fopen(options.Csv.c_str(), "w");
  if (csv)
    std::fprintf(csv, "kind,points,mode,threads,seconds,error_min,error_max\n");
  for (const long n : options.Sizes)
  {
    std::printf("torus R=3 r=1, %ld points, exact normals\n", n);
    auto cloud =
      pcurv::testing::MakeCloud(pcurv::testing::Sample(pcurv::testing::Torus(3.0, 1.0), n, 1));
    double s = 0.0, p = 0.0, singleNew01 = 0.0;
    for (const long threads : options.Threads)
    {
      for (int mode = 0; mode < 3; ++mode)
      {
        std::vector<double> times;
        pcurv::testing::CurvatureErrors errors;
        long peak = 0, before = 0, bytes = 0;
        for (int run = 0; run < options.Runs; ++run)
        {
          vtkNew<vtkPrincipalCurvatureEstimation> filter;
          filter->SetInputData(cloud);
          filter->SetFitMode(mode);
          filter->SetNumberOfThreads(static_cast<int>(threads));
          before = StatusKilobytes("VmRSS");
          ResetPeak();
          const auto start = Clock::now();
          filter->Update();
          times.push_back(Seconds(start));
          peak = StatusKilobytes("VmHWM") - before;
          errors = pcurv::testing::MeasureErrors(filter->GetOutput());
          bytes = ArrayBytes(filter->GetOutput()) + 2 * 24L * n; // + the input's points and normals
          s = filter->GetUsedSurroundingsThreshold();
          p = filter->GetUsedPlaneDistanceThreshold();
        }
        const double t = Median(times);
        if (threads == 1 && mode == 1)
          singleNew01 = t;
        std::printf(
          "  %-8s %ld thread(s): %.3f s (median of %d), %.0f points/s, peak +%.0f MB = %.2fx "
          "input+output arrays (%.0f MB), errors k_min %.5f k_max %.5f, angle %.2f deg\n",
          ModeNames[mode],
          threads,
          t,
          options.Runs,
          n / t,
          peak / 1024.0,
          peak * 1024.0 / bytes,
          bytes / 1048576.0,
          errors.MeanMinimumError,
          errors.MeanMaximumError,
          errors.MedianAngleDegrees);
        if (csv)
          std::fprintf(csv,
            "filter,%ld,%s,%ld,%.6f,%.6f,%.6f\n",
            n,
            ModeNames[mode],
            threads,
            t,
            errors.MeanMinimumError,
            errors.MeanMaximumError);
        if (threads > 1 && mode == 1 && singleNew01 > 0.0)
          std::printf("  New01 speed-up 1 -> %ld threads: %.2fx\n", threads, singleNew01 / t);
      }
    }
    if (n <= 200000) // phases are proportions: measured where they are quick
      MeasurePhases(cloud, s, p, options.Runs, csv, n);
    if (n == options.Sizes.front())
      MeasureFitsAlone(cloud, s, p);
#ifdef PCURV_WITH_CGAL
    if (options.Peer)
      MeasurePeer(cloud, s, std::min(options.PeerPoints, n), csv, n);
#endif
  }
  if (csv)
    std::fclose(csv);
  return 0;
}
