// Benchmark of vtkPrincipalCurvatureEstimation (a program, not a test).
//
// On analytic clouds with exact normals and curvatures (a torus by default),
// for each fit mode (Previous, New01, New02), size and thread count:
//  - the wall time of the whole filter's Update(), points per second,
//    accuracy (MeasureErrors), peak memory (in a fresh child process:
//    VmHWM over the resident size before the update) against the size of
//    the input and output arrays;
//  - phases measured in-process with the numeric core on the filter's own
//    neighborhoods (same radius, same grid lattice, same order): grid
//    build, neighbor search, binning and sums, circle fits, sine fit;
//  - the paper's timing claim: the three fits timed alone on identical
//    per-direction CGA sums collected once;
//  - the peer: CGAL's Monge_via_jet_fitting (degree 2, Monge degree 2) on
//    the same neighborhoods, one core, scored the same way.
// Medians of several runs and ratios are printed as tables on stdout
// (BenchmarkReport.cxx; progress goes to stderr) and, with --csv FILE, as
// CSV (one measurement a line) for plot_benchmark.py.
#include "AnalyticClouds.h"
#include "BenchmarkReport.h"
#include "Neighbors/PointGrid.h"
#include "Fits/PrincipalCurvatureCore.h"
#include "vtkPrincipalCurvatureEstimation.h"
#ifdef PCURV_WITH_CGAL
#include "CgalJetPeer.h"
#endif

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <malloc.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace
{
using namespace pcurv::benchmark;
using Clock = std::chrono::steady_clock;
constexpr double Pi = 3.14159265358979323846;

const char* const Usage =
  "usage: PrincipalCurvatureBenchmark [options]\n"
  "  --sizes 10000,100000,1000000  cloud sizes (points)\n"
  "  --runs 5                      runs per measurement (medians are reported)\n"
  "  --modes 0,1,2                 fit modes: 0 Previous, 1 New01, 2 New02 (or names)\n"
  "  --threads 1,2                 thread counts of the whole-filter runs\n"
  "  --surface torus               torus (R 3, r 1), sphere (r 1) or ellipsoid (3, 2, 1)\n"
  "  --phase-points 200000         query points of the phase timing; larger clouds: that\n"
  "                                many points in 16 spread blocks of the grid order,\n"
  "                                times extrapolated per point\n"
  "  --fit-points 20000            points whose direction sums are collected for the\n"
  "                                fits-alone timing (the paper's claim)\n"
  "  --peer-points 20000           query points of the CGAL peer (extrapolated per point)\n"
  "  --no-peer                     skip CGAL's jet fitting\n"
  "  --no-phases                   skip the phase, fits-alone and peer timings\n"
  "  --no-memory                   skip the peak-memory child processes\n"
  "  --dynamic-adjustment C        whole-filter runs with the dynamic adjustment and the\n"
  "                                constants C: paper, ladder (375, 0.2) or noisy-ladder\n"
  "                                (1000, 0.6); implies --no-phases (they model a fixed\n"
  "                                radius)\n"
  "  --csv FILE                    also write every measurement as CSV\n";

double Seconds(Clock::time_point start, Clock::time_point end)
{
  return std::chrono::duration<double>(end - start).count();
}

/// User + system CPU time of the whole process (all threads), seconds.
double ProcessCpuSeconds()
{
  struct rusage usage
  {
  };
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec +
    1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

/// The first three fields of /proc/loadavg: how busy the shared machine was.
std::string LoadAverage()
{
  std::ifstream file("/proc/loadavg");
  std::string one, five, fifteen;
  file >> one >> five >> fifteen;
  return one + " " + five + " " + fifteen;
}

std::vector<std::string> Split(const std::string& text)
{
  std::vector<std::string> items;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ','))
  {
    if (!item.empty())
    {
      items.push_back(item);
    }
  }
  return items;
}

/// The filter as the options ask: the dynamic adjustment, if chosen.
void ConfigureAdjustment(vtkPrincipalCurvatureEstimation* filter, const Options& options)
{
  if (options.Adjustment.empty())
  {
    return;
  }
  filter->DynamicAdjustmentOn();
  if (options.Adjustment == "ladder")
  {
    filter->SetAdjustmentConstantsToBandedLadder(375, 0.2);
  }
  else if (options.Adjustment == "noisy-ladder")
  {
    filter->SetAdjustmentConstantsToBandedLadder(1000, 0.6);
  }
}

[[noreturn]] void Fail(const std::string& message)
{
  std::fprintf(stderr, "%s\n%s", message.c_str(), Usage);
  std::exit(2);
}

long ParsePositive(const std::string& text, const std::string& option)
{
  char* end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || value <= 0)
  {
    Fail("bad value '" + text + "' for " + option);
  }
  return value;
}

Options Parse(int argc, char* argv[])
{
  Options o;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() -> std::string
    {
      if (i + 1 >= argc)
      {
        Fail("missing value after " + a);
      }
      return argv[++i];
    };
    auto list = [&]()
    {
      std::vector<long> values;
      for (const std::string& item : Split(next()))
      {
        values.push_back(ParsePositive(item, a));
      }
      if (values.empty())
      {
        Fail("empty list after " + a);
      }
      return values;
    };
    if (a == "--sizes")
      o.Sizes = list();
    else if (a == "--threads")
      o.Threads = list();
    else if (a == "--modes")
    {
      o.Modes.clear();
      for (const std::string& item : Split(next()))
      {
        int mode = -1;
        for (int m = 0; m < 3; ++m)
        {
          if (item == ModeNames[m] || item == std::to_string(m))
          {
            mode = m;
          }
        }
        if (mode < 0)
        {
          Fail("unknown fit mode '" + item + "'");
        }
        if (std::find(o.Modes.begin(), o.Modes.end(), mode) == o.Modes.end())
        {
          o.Modes.push_back(mode);
        }
      }
      if (o.Modes.empty())
      {
        Fail("no fit mode given");
      }
      std::sort(o.Modes.begin(), o.Modes.end());
    }
    else if (a == "--runs")
      o.Runs = static_cast<int>(ParsePositive(next(), a));
    else if (a == "--surface")
      o.Surface = next();
    else if (a == "--phase-points")
      o.PhasePoints = ParsePositive(next(), a);
    else if (a == "--fit-points")
      o.FitPoints = ParsePositive(next(), a);
    else if (a == "--peer-points")
      o.PeerPoints = ParsePositive(next(), a);
    else if (a == "--no-peer")
      o.Peer = false;
    else if (a == "--no-phases")
      o.Phases = false;
    else if (a == "--no-memory")
      o.Memory = false;
    else if (a == "--memory-probe")
      o.MemoryProbe = true;
    else if (a == "--csv")
      o.Csv = next();
    else if (a == "--dynamic-adjustment")
    {
      o.Adjustment = next();
      if (o.Adjustment != "paper" && o.Adjustment != "ladder" && o.Adjustment != "noisy-ladder")
      {
        Fail("unknown adjustment constants '" + o.Adjustment + "'");
      }
      o.Phases = false;
    }
    else if (a == "--help" || a == "-h")
    {
      std::printf("%s", Usage);
      std::exit(0);
    }
    else
      Fail("unknown option " + a);
  }
  if (o.Surface != "torus" && o.Surface != "sphere" && o.Surface != "ellipsoid")
  {
    Fail("unknown surface " + o.Surface);
  }
  std::sort(o.Sizes.begin(), o.Sizes.end());
  std::sort(o.Threads.begin(), o.Threads.end());
  return o;
}

pcurv::testing::Surface MakeSurface(const std::string& name)
{
  if (name == "sphere")
    return pcurv::testing::Sphere(1.0);
  if (name == "ellipsoid")
    return pcurv::testing::Ellipsoid(3.0, 2.0, 1.0);
  return pcurv::testing::Torus(3.0, 1.0);
}

vtkSmartPointer<vtkPolyData> MakeBenchmarkCloud(const std::string& surface, long n)
{
  return pcurv::testing::MakeCloud(
    pcurv::testing::Sample(MakeSurface(surface), static_cast<int>(n), 1));
}

// ---------------------------------------------------------------------------
// Memory

/// A figure (kB) from /proc/self/status: VmHWM (peak resident since the
/// last reset) or VmRSS (resident now); -1 when unavailable.
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

double ArrayBytes(vtkDataArray* array)
{
  return array ? 1024.0 * static_cast<double>(array->GetActualMemorySize()) : 0.0;
}

/// The child process: one cloud, one Update(), VmHWM against VmRSS just
/// before it. A fresh process, because in a long-running one the allocator
/// keeps freed memory resident and a later run reuses it unseen.
int RunMemoryProbe(const Options& options)
{
  vtkSmartPointer<vtkPolyData> cloud = MakeBenchmarkCloud(options.Surface, options.Sizes[0]);
  vtkNew<vtkPrincipalCurvatureEstimation> filter;
  filter->SetInputData(cloud);
  filter->SetFitMode(options.Modes[0]);
  filter->SetNumberOfThreads(static_cast<int>(options.Threads[0]));
  ConfigureAdjustment(filter, options);
  malloc_trim(0);
  bool reset = false;
  {
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5"; // resets VmHWM to the current resident size
    clear.flush();
    reset = clear.good();
  }
  const long baseline = StatusKilobytes("VmRSS");
  filter->Update();
  const long peak = StatusKilobytes("VmHWM");
  struct rusage usage
  {
  };
  getrusage(RUSAGE_SELF, &usage);
  // Input: what the filter reads (points, normals). Output: the arrays it
  // creates (the input's arrays and points are passed through, shared).
  vtkPolyData* output = filter->GetOutput();
  const double input =
    ArrayBytes(cloud->GetPoints()->GetData()) + ArrayBytes(cloud->GetPointData()->GetNormals());
  double created = 0.0;
  for (int a = 0; a < output->GetPointData()->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = output->GetPointData()->GetArray(a);
    bool passed = false;
    for (int b = 0; b < cloud->GetPointData()->GetNumberOfArrays(); ++b)
    {
      passed = passed || cloud->GetPointData()->GetArray(b) == array;
    }
    created += passed ? 0.0 : ArrayBytes(array);
  }
  std::printf("PCURV_MEMORY %ld %ld %ld %.0f %.0f %d\n",
    baseline,
    peak,
    static_cast<long>(usage.ru_maxrss),
    input,
    created,
    reset ? 1 : 0);
  return 0;
}

std::string ExecutablePath()
{
  char path[4096];
  const ssize_t length = readlink("/proc/self/exe", path, sizeof(path) - 1);
  if (length <= 0)
  {
    return "";
  }
  path[length] = '\0';
  return path;
}

MemoryRecord ProbeMemory(const Options& options, long n, int mode, long threads)
{
  MemoryRecord record;
  const std::string executable = ExecutablePath();
  if (executable.empty())
  {
    return record;
  }
  const std::string command = "'" + executable + "' --memory-probe --surface " + options.Surface +
    " --sizes " + std::to_string(n) + " --modes " + std::to_string(mode) + " --threads " +
    std::to_string(threads) +
    (options.Adjustment.empty() ? "" : " --dynamic-adjustment " + options.Adjustment) +
    " 2>/dev/null";
  std::FILE* pipe = popen(command.c_str(), "r");
  if (!pipe)
  {
    return record;
  }
  char line[512];
  while (std::fgets(line, sizeof(line), pipe))
  {
    long baseline = 0, peak = 0, maxrss = 0;
    double input = 0.0, created = 0.0;
    int reset = 0;
    if (std::sscanf(line,
          "PCURV_MEMORY %ld %ld %ld %lf %lf %d",
          &baseline,
          &peak,
          &maxrss,
          &input,
          &created,
          &reset) == 6 &&
      reset == 1 && baseline > 0 && peak > 0)
    {
      record.Valid = true;
      record.BaselineMB = baseline / 1024.0;
      record.ExtraMB = (peak - baseline) / 1024.0;
      record.ProcessPeakMB = maxrss / 1024.0;
      record.InputMB = input / 1048576.0;
      record.OutputMB = created / 1048576.0;
    }
  }
  pclose(pipe);
  return record;
}

// ---------------------------------------------------------------------------
// The whole filter

/// The filter's thresholds and its results, kept to check that the core
/// measured below sees the same neighborhoods.
struct FilterReference
{
  double S = NaN;
  double P = NaN;
  std::vector<double> Minimum[3];
  std::vector<double> Maximum[3];
};

double RunFilter(vtkPolyData* cloud,
  int mode,
  long threads,
  const Options& options,
  FilterRecord& record,
  FilterReference* reference)
{
  vtkNew<vtkPrincipalCurvatureEstimation> filter;
  filter->SetInputData(cloud);
  filter->SetFitMode(mode);
  filter->SetNumberOfThreads(static_cast<int>(threads));
  ConfigureAdjustment(filter, options);
  const double cpu = ProcessCpuSeconds();
  const auto start = Clock::now();
  filter->Update();
  const double seconds = Seconds(start, Clock::now());
  record.Utilization.push_back((ProcessCpuSeconds() - cpu) / (seconds * threads));
  if (reference) // the first run: accuracy and the reference values
  {
    vtkPolyData* output = filter->GetOutput();
    record.Errors = pcurv::testing::MeasureErrors(output);
    record.Unestimated = filter->GetNumberOfUnestimatedPoints();
    vtkDataArray* counts = output->GetPointData()->GetArray("Neighbor_Count");
    double sum = 0.0;
    for (vtkIdType i = 0; counts && i < counts->GetNumberOfTuples(); ++i)
    {
      sum += counts->GetTuple1(i);
    }
    record.MeanNeighbors = counts ? sum / std::max<vtkIdType>(1, counts->GetNumberOfTuples()) : NaN;
    reference->S = filter->GetUsedSurroundingsThreshold();
    reference->P = filter->GetUsedPlaneDistanceThreshold();
    vtkDataArray* kMin = output->GetPointData()->GetArray("Minimum_Curvature");
    vtkDataArray* kMax = output->GetPointData()->GetArray("Maximum_Curvature");
    const vtkIdType n = output->GetNumberOfPoints();
    reference->Minimum[mode].resize(n);
    reference->Maximum[mode].resize(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      reference->Minimum[mode][i] = kMin->GetTuple1(i);
      reference->Maximum[mode][i] = kMax->GetTuple1(i);
    }
  }
  return seconds;
}

// ---------------------------------------------------------------------------
// The numeric core on the filter's neighborhoods

/// Flat arrays and the grid as the filter builds them: the same lattice
/// (bounds of the cloud, cells of half the radius), hence the same
/// neighbors in the same order.
struct CoreCloud
{
  long N = 0;
  double S = NaN, P = NaN;
  std::vector<double> Points, Normals, ExactMinimum, ExactMaximum, Boundary;
  double LargestExact = 0.0;
  pcurv::GridLattice Lattice;
  pcurv::PointGrid Grid;

  CoreCloud(vtkPolyData* cloud, double s, double p)
    : N(cloud->GetNumberOfPoints())
    , S(s)
    , P(p)
  {
    this->Points.resize(3 * this->N);
    this->Normals.resize(3 * this->N);
    this->ExactMinimum.resize(this->N);
    this->ExactMaximum.resize(this->N);
    this->Boundary.resize(this->N);
    vtkPointData* pd = cloud->GetPointData();
    vtkDataArray* normals = pd->GetNormals();
    vtkDataArray* kMin = pd->GetArray("Exact_Minimum_Curvature");
    vtkDataArray* kMax = pd->GetArray("Exact_Maximum_Curvature");
    vtkDataArray* boundary = pd->GetArray("Boundary_Distance");
    for (vtkIdType i = 0; i < this->N; ++i)
    {
      cloud->GetPoint(i, &this->Points[3 * i]);
      double* n = &this->Normals[3 * i];
      normals->GetTuple(i, n);
      // As the filter normalizes (CloudPoints::Read): bit for bit.
      const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      const double inverse = length > 0.0 ? 1.0 / length : 0.0;
      for (int k = 0; k < 3; ++k)
      {
        n[k] *= inverse;
      }
      this->ExactMinimum[i] = kMin->GetTuple1(i);
      this->ExactMaximum[i] = kMax->GetTuple1(i);
      this->Boundary[i] = boundary->GetTuple1(i);
      this->LargestExact = std::max(
        { this->LargestExact, std::fabs(this->ExactMinimum[i]), std::fabs(this->ExactMaximum[i]) });
    }
    double bounds[6];
    cloud->GetBounds(bounds);
    const double lower[3] = { bounds[0], bounds[2], bounds[4] };
    const double upper[3] = { bounds[1], bounds[3], bounds[5] };
    this->Lattice = pcurv::GridLattice::Make(lower, upper, this->N, 0.5 * s);
  }

  double BuildGrid()
  {
    const auto start = Clock::now();
    this->Grid.Build(this->Points.data(), this->N, this->Lattice);
    return Seconds(start, Clock::now());
  }

  pcurv::Vector3 Point(std::int64_t i) const
  {
    return { { this->Points[3 * i], this->Points[3 * i + 1], this->Points[3 * i + 2] } };
  }
  pcurv::Vector3 Normal(std::int64_t i) const
  {
    return { { this->Normals[3 * i], this->Normals[3 * i + 1], this->Normals[3 * i + 2] } };
  }
};

/// Query points of the phase timing, in the filter's processing order (the
/// grid's): all of them, or `count` in 16 blocks spread over the order.
std::vector<std::int64_t> PhaseQueries(const CoreCloud& core, long count)
{
  std::vector<std::int64_t> ids;
  if (core.N <= count)
  {
    for (std::int64_t j = 0; j < core.N; ++j)
    {
      ids.push_back(core.Grid.GetSortedId(j));
    }
    return ids;
  }
  constexpr int Blocks = 16;
  const std::int64_t length = count / Blocks;
  for (int b = 0; b < Blocks; ++b)
  {
    const std::int64_t first = static_cast<std::int64_t>(b) * core.N / Blocks;
    for (std::int64_t j = first; j < first + length; ++j)
    {
      ids.push_back(core.Grid.GetSortedId(j));
    }
  }
  return ids;
}

/// Query points spread at random over the surface (the samples are in
/// random order): every stride-th input point.
std::vector<std::int64_t> SpreadQueries(const CoreCloud& core, long count)
{
  std::vector<std::int64_t> ids;
  const std::int64_t stride = std::max<std::int64_t>(1, core.N / std::max(1L, count));
  for (std::int64_t i = 0; i < core.N && static_cast<long>(ids.size()) < count; i += stride)
  {
    ids.push_back(i);
  }
  return ids;
}

bool SameValue(double a, double b)
{
  return (std::isnan(a) && std::isnan(b)) || a == b;
}

/// Grid build, neighbor search, binning + sums, and Estimate() (circle fits
/// and sine fit) per mode, one thread, each point timed piece by piece (the
/// clock costs about 20 ns a read, under 0.5 % of a point). The modes'
/// Estimate() calls share one accumulation: identical sums.
PhaseRecord MeasurePhases(CoreCloud& core, const Options& options, const FilterReference& reference)
{
  PhaseRecord record;
  const std::vector<std::int64_t> queries = PhaseQueries(core, options.PhasePoints);
  record.Queries = static_cast<long>(queries.size());
  record.Scale = static_cast<double>(core.N) / record.Queries;
  pcurv::PointCurvatureEstimator estimator;
  pcurv::NeighborOffsets neighbors;
  pcurv::FitSettings settings[3];
  for (int mode = 0; mode < 3; ++mode)
  {
    settings[mode].Mode = static_cast<pcurv::FitMode>(mode);
  }
  double checksum = 0.0;
  for (int run = 0; run < options.Runs; ++run)
  {
    record.GridBuild.push_back(core.BuildGrid());
    double search = 0.0, accumulate = 0.0, estimate[3] = { 0.0, 0.0, 0.0 }, count = 0.0;
    for (const std::int64_t i : queries)
    {
      const pcurv::Vector3 x = core.Point(i);
      const auto t0 = Clock::now();
      core.Grid.GatherOffsetsWithinRadius(x.data(), core.S, neighbors);
      const auto t1 = Clock::now();
      estimator.Begin(x, core.Normal(i), core.P, core.S);
      estimator.AddNeighborOffsets(
        neighbors.Dx.data(), neighbors.Dy.data(), neighbors.Dz.data(), neighbors.Count);
      auto t2 = Clock::now();
      search += Seconds(t0, t1);
      accumulate += Seconds(t1, t2);
      count += estimator.GetNumberOfNeighbors();
      for (const int mode : options.Modes)
      {
        const pcurv::PointCurvature result = estimator.Estimate(settings[mode]);
        const auto t3 = Clock::now();
        estimate[mode] += Seconds(t2, t3);
        t2 = t3;
        checksum += result.Valid ? result.MaximumCurvature : 0.0;
        if (run == 0 && !reference.Minimum[mode].empty())
        {
          const double kMin = result.Valid ? result.MinimumCurvature : NaN;
          const double kMax = result.Valid ? result.MaximumCurvature : NaN;
          const double wantMin = reference.Minimum[mode][i], wantMax = reference.Maximum[mode][i];
          if (!SameValue(kMin, wantMin) || !SameValue(kMax, wantMax))
          {
            ++record.Mismatches[mode];
            record.LargestDifference[mode] = std::max({ record.LargestDifference[mode],
              std::fabs(kMin - wantMin),
              std::fabs(kMax - wantMax) });
          }
        }
      }
    }
    record.Search.push_back(search);
    record.Accumulate.push_back(accumulate);
    for (const int mode : options.Modes)
    {
      record.Estimate[mode].push_back(estimate[mode]);
    }
    record.Neighbors = count;
  }
  std::fprintf(stderr, "    (phase checksum %.6g)\n", checksum);
  return record;
}

/// The paper's claim on identical CGA matrices: the per-direction sums of
/// many points, collected once as the core does (lengths over s, the same
/// half planes, the same rule for a usable direction), then each fit timed
/// alone over all of them; and the sine fit per point over New01's
/// direction curvatures.
FitsRecord MeasureFitsAlone(const CoreCloud& core, const Options& options)
{
  FitsRecord record;
  const std::vector<std::int64_t> ids = SpreadQueries(core, options.FitPoints);
  std::array<double, pcurv::NumberOfDirections> cosine, sine;
  for (int d = 0; d < pcurv::NumberOfDirections; ++d)
  {
    cosine[d] = std::cos(d * Pi / 8.0);
    sine[d] = std::sin(d * Pi / 8.0);
  }
  const pcurv::FitSettings settings; // the usable-direction rule of the defaults
  std::vector<pcurv::CgaSums> sums;
  struct PointDirections
  {
    pcurv::TangentFrame Frame;
    std::array<double, pcurv::NumberOfDirections> Curvature;
    std::array<bool, pcurv::NumberOfDirections> Valid;
  };
  std::vector<PointDirections> points;
  std::vector<double> neighbors;
  pcurv::PointCurvatureEstimator estimator;
  pcurv::FitSettings new01;
  new01.Mode = pcurv::FitMode::New01;
  const double inverse = 1.0 / core.S, p = core.P / core.S;
  for (const std::int64_t i : ids)
  {
    const pcurv::Vector3 x = core.Point(i);
    core.Grid.GatherWithinRadius(x.data(), core.S, neighbors);
    PointDirections point{};
    point.Frame = pcurv::MakeTangentFrame(core.Normal(i));
    const pcurv::TangentFrame& f = point.Frame;
    std::array<pcurv::CgaSums, pcurv::NumberOfDirections> direction{};
    for (std::size_t k = 0; k < neighbors.size(); k += 3)
    {
      const double d[3] = { (neighbors[k] - x[0]) * inverse,
        (neighbors[k + 1] - x[1]) * inverse,
        (neighbors[k + 2] - x[2]) * inverse };
      const double squared = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      if (squared == 0.0)
      {
        continue;
      }
      const double h = d[0] * f.Normal[0] + d[1] * f.Normal[1] + d[2] * f.Normal[2];
      const double tx = d[0] * f.V0[0] + d[1] * f.V0[1] + d[2] * f.V0[2];
      const double ty = d[0] * f.W0[0] + d[1] * f.W0[1] + d[2] * f.W0[2];
      for (std::uint32_t mask = pcurv::PointCurvatureEstimator::DirectionMask(tx, ty, p); mask;
           mask &= mask - 1)
      {
        const int b = __builtin_ctz(mask);
        direction[b].Add(h, squared, tx * cosine[b] + ty * sine[b]);
      }
    }
    for (int b = 0; b < pcurv::NumberOfDirections; ++b)
    {
      const bool usable = direction[b].Count >= settings.MinimumPointsPerDirection &&
        direction[b].Extent >= settings.MinimumDirectionExtent;
      const pcurv::CircleFit fit =
        usable ? pcurv::FitEquations23(direction[b]) : pcurv::CircleFit{};
      point.Valid[b] = fit.Valid;
      point.Curvature[b] = fit.Valid ? fit.Curvature * inverse : 0.0;
      if (usable)
      {
        sums.push_back(direction[b]);
      }
    }
    // Check: the same New01 estimate as the core's.
    pcurv::PointCurvature rebuilt;
    pcurv::PrincipalCurvaturesFromSine(
      pcurv::FitSine(point.Curvature, point.Valid), point.Frame, rebuilt);
    estimator.Begin(x, core.Normal(i), core.P, core.S);
    estimator.AddNeighbors(neighbors.data(), neighbors.size() / 3);
    const pcurv::PointCurvature original = estimator.Estimate(new01);
    if (rebuilt.Valid != original.Valid)
    {
      record.LargestDifference = HUGE_VAL;
    }
    else if (rebuilt.Valid)
    {
      record.LargestDifference = std::max({ record.LargestDifference,
        std::fabs(rebuilt.MinimumCurvature - original.MinimumCurvature),
        std::fabs(rebuilt.MaximumCurvature - original.MaximumCurvature) });
    }
    points.push_back(point);
  }
  record.Points = points.size();
  record.Directions = sums.size();
  double checksum = 0.0;
  const int runs = std::max(options.Runs, 5); // cheap: a few tenths of a second
  for (int run = 0; run < runs; ++run)
  {
    auto start = Clock::now();
    for (const pcurv::CgaSums& b : sums)
    {
      checksum += pcurv::FitPrevious(b).Curvature;
    }
    auto end = Clock::now();
    record.Fit[0].push_back(Seconds(start, end));
    start = Clock::now();
    for (const pcurv::CgaSums& b : sums)
    {
      checksum += pcurv::FitEquations23(b).Curvature;
    }
    end = Clock::now();
    record.Fit[1].push_back(Seconds(start, end));
    start = Clock::now();
    for (const pcurv::CgaSums& b : sums)
    {
      checksum += pcurv::FitEquations12(b).Curvature + pcurv::FitEquations23(b).Curvature;
    }
    end = Clock::now();
    record.Fit[2].push_back(Seconds(start, end));
    start = Clock::now();
    for (const PointDirections& point : points)
    {
      pcurv::PointCurvature result;
      pcurv::PrincipalCurvaturesFromSine(
        pcurv::FitSine(point.Curvature, point.Valid), point.Frame, result);
      checksum += result.MaximumCurvature + result.MinimumDirection[0];
    }
    end = Clock::now();
    record.Sine.push_back(Seconds(start, end));
  }
  std::fprintf(stderr, "    (fits checksum %.6g)\n", checksum);
  return record;
}

// ---------------------------------------------------------------------------
// The peer

#ifdef PCURV_WITH_CGAL
/// CGAL's jet fitting and the core, one thread, on the same query points
/// (spread over the surface) and the same neighborhoods (the filter's
/// radius, gathered once with the grid), scored the same way: mean
/// |k - exact| over max |exact k| of the cloud, points whose neighborhood
/// reaches a boundary left out.
PeerRecord MeasurePeer(const CoreCloud& core, const Options& options)
{
  PeerRecord record;
  const std::vector<std::int64_t> ids = SpreadQueries(core, options.PeerPoints);
  record.Queries = static_cast<long>(ids.size());
  pcurv::benchmark::CgalJetFitter jet;
  pcurv::PointCurvatureEstimator estimator;
  pcurv::FitSettings settings[3];
  for (int mode = 0; mode < 3; ++mode)
  {
    settings[mode].Mode = static_cast<pcurv::FitMode>(mode);
  }
  std::vector<double> neighbors;
  double checksum = 0.0;
  const double scale = core.LargestExact > 0.0 ? core.LargestExact : 1.0;
  for (int run = 0; run < options.Runs; ++run)
  {
    double search = 0.0, cgal = 0.0, ours[3] = { 0.0, 0.0, 0.0 };
    double cgalError[2] = { 0.0, 0.0 }, oursError[3][2] = {};
    long cgalScored = 0, oursScored[3] = {};
    for (const std::int64_t i : ids)
    {
      const pcurv::Vector3 x = core.Point(i);
      const pcurv::Vector3 n = core.Normal(i);
      const auto t0 = Clock::now();
      core.Grid.GatherWithinRadius(x.data(), core.S, neighbors);
      const auto t1 = Clock::now();
      const pcurv::benchmark::JetCurvatures fit =
        jet.Fit(x.data(), n.data(), neighbors.data(), neighbors.size() / 3);
      auto t2 = Clock::now();
      search += Seconds(t0, t1);
      cgal += Seconds(t1, t2);
      const bool scored = core.Boundary[i] > core.S;
      if (run == 0 && scored)
      {
        if (fit.Valid)
        {
          cgalError[0] += std::fabs(fit.Minimum - core.ExactMinimum[i]);
          cgalError[1] += std::fabs(fit.Maximum - core.ExactMaximum[i]);
          ++cgalScored;
        }
        else
        {
          ++record.CgalInvalid;
        }
      }
      checksum += fit.Valid ? fit.Maximum : 0.0;
      for (const int mode : options.Modes)
      {
        estimator.Begin(x, n, core.P, core.S);
        estimator.AddNeighbors(neighbors.data(), neighbors.size() / 3);
        const pcurv::PointCurvature result = estimator.Estimate(settings[mode]);
        const auto t3 = Clock::now();
        ours[mode] += Seconds(t2, t3);
        t2 = t3;
        checksum += result.Valid ? result.MaximumCurvature : 0.0;
        if (run == 0 && scored)
        {
          if (result.Valid)
          {
            oursError[mode][0] += std::fabs(result.MinimumCurvature - core.ExactMinimum[i]);
            oursError[mode][1] += std::fabs(result.MaximumCurvature - core.ExactMaximum[i]);
            ++oursScored[mode];
          }
          else
          {
            ++record.OursInvalid[mode];
          }
        }
      }
    }
    record.Search.push_back(search);
    record.Cgal.push_back(cgal);
    for (const int mode : options.Modes)
    {
      record.Ours[mode].push_back(ours[mode]);
    }
    if (run == 0)
    {
      for (int k = 0; k < 2; ++k)
      {
        record.CgalError[k] = cgalScored ? cgalError[k] / cgalScored / scale : NaN;
        for (const int mode : options.Modes)
        {
          record.OursError[mode][k] =
            oursScored[mode] ? oursError[mode][k] / oursScored[mode] / scale : NaN;
        }
      }
    }
  }
  std::fprintf(stderr, "    (peer checksum %.6g)\n", checksum);
  return record;
}
#endif

} // namespace

int main(int argc, char* argv[])
{
  const Options options = Parse(argc, argv);
  if (options.MemoryProbe)
  {
    return RunMemoryProbe(options);
  }
  CsvFile csv;
  if (!options.Csv.empty() && !csv.Open(options.Csv, options.Surface))
  {
    std::fprintf(stderr, "cannot write %s\n", options.Csv.c_str());
    return 1;
  }
  std::printf("# PrincipalCurvatureBenchmark\n\n");
  std::printf("command:");
  for (int i = 0; i < argc; ++i)
  {
    std::printf(" %s", argv[i]);
  }
  std::printf("\nmachine: %ld online cores, load average %s at the start; clouds: %s with exact "
              "normals and curvatures\n",
    sysconf(_SC_NPROCESSORS_ONLN),
    LoadAverage().c_str(),
    SurfaceDescription(options.Surface).c_str());
#ifdef PCURV_WITH_CGAL
  const bool peer = options.Peer && options.Phases;
  std::printf("peer: %s\n",
    peer ? "CGAL Monge_via_jet_fitting" : "CGAL found, skipped (--no-peer or --no-phases)");
#else
  const bool peer = false;
  std::printf("peer: skipped (built without CGAL; install libcgal-dev and reconfigure)\n");
#endif
  std::fflush(stdout);

  Results results;
  for (const long n : options.Sizes)
  {
    SizeRecord size;
    size.N = n;
    std::fprintf(stderr, "%s, %ld points: generating\n", options.Surface.c_str(), n);
    vtkSmartPointer<vtkPolyData> cloud = MakeBenchmarkCloud(options.Surface, n);

    // Whole filter: runs interleaved over modes and thread counts, so that
    // a slow phase of a shared machine does not fall on one of them.
    FilterReference reference;
    for (int run = 0; run < options.Runs; ++run)
    {
      for (const long threads : options.Threads)
      {
        for (const int mode : options.Modes)
        {
          FilterRecord& record = results.Filter[FilterKey{ n, mode, threads }];
          const bool first = run == 0 && threads == options.Threads.front();
          const double t =
            RunFilter(cloud, mode, threads, options, record, first ? &reference : nullptr);
          record.Times.push_back(t);
          std::fprintf(stderr,
            "  run %d/%d %-8s %ld thread(s): %.3f s\n",
            run + 1,
            options.Runs,
            ModeNames[mode],
            threads,
            t);
        }
      }
    }
    for (const long threads : options.Threads)
    {
      for (const int mode : options.Modes)
      {
        const FilterRecord& r = results.Filter[FilterKey{ n, mode, threads }];
        const std::string m = ModeNames[mode];
        csv.Row("filter", n, m, threads, "seconds", r.Median(), "s", "median");
        csv.Row("filter", n, m, threads, "seconds_min", Smallest(r.Times), "s");
        csv.Row("filter", n, m, threads, "seconds_max", Largest(r.Times), "s");
        csv.Row("filter", n, m, threads, "points_per_second", n / r.Median(), "1/s");
        // The errors do not depend on the thread count (bit-identical).
        const FilterRecord& first = results.Filter[FilterKey{ n, mode, options.Threads.front() }];
        csv.Row("filter", n, m, threads, "error_min", first.Errors.MeanMinimumError, "1");
        csv.Row("filter", n, m, threads, "error_max", first.Errors.MeanMaximumError, "1");
      }
    }
    for (const long threads : options.Threads)
    {
      for (const int mode : options.Modes)
      {
        if (threads != options.Threads.front())
        {
          results.Filter[FilterKey{ n, mode, threads }].Errors =
            results.Filter[FilterKey{ n, mode, options.Threads.front() }].Errors;
          results.Filter[FilterKey{ n, mode, threads }].MeanNeighbors =
            results.Filter[FilterKey{ n, mode, options.Threads.front() }].MeanNeighbors;
          results.Filter[FilterKey{ n, mode, threads }].Unestimated =
            results.Filter[FilterKey{ n, mode, options.Threads.front() }].Unestimated;
        }
      }
    }
    size.S = reference.S;
    size.P = reference.P;
    std::fprintf(stderr, "  radius s = %.6g, plane distance p = %.6g\n", size.S, size.P);

    if (options.Memory)
    {
      for (const int mode : options.Modes)
      {
        const long threads = options.Threads.back();
        std::fprintf(stderr, "  memory: %s, %ld thread(s)\n", ModeNames[mode], threads);
        const MemoryRecord m = ProbeMemory(options, n, mode, threads);
        size.Memory[{ mode, threads }] = m;
        if (m.Valid)
        {
          const std::string name = ModeNames[mode];
          csv.Row("memory", n, name, threads, "baseline_mb", m.BaselineMB, "MB");
          csv.Row("memory", n, name, threads, "peak_extra_mb", m.ExtraMB, "MB");
          csv.Row("memory",
            n,
            name,
            threads,
            "arrays_mb",
            m.InputMB + m.OutputMB,
            "MB",
            "input points and normals + output arrays created");
          csv.Row("memory", n, name, threads, "ratio_to_arrays", m.RatioToArrays(), "1");
        }
      }
    }

    if (options.Phases)
    {
      CoreCloud core(cloud, size.S, size.P);
      core.BuildGrid();
      std::fprintf(stderr, "  phases\n");
      size.Phases = MeasurePhases(core, options, reference);
      size.HasPhases = true;
      std::fprintf(stderr, "  fits alone\n");
      size.Fits = MeasureFitsAlone(core, options);
      size.HasFits = true;
#ifdef PCURV_WITH_CGAL
      if (peer)
      {
        std::fprintf(stderr, "  peer: CGAL jet fitting\n");
        size.Peer = MeasurePeer(core, options);
        size.HasPeer = true;
      }
#endif
    }
    results.Sizes.push_back(std::move(size));
  }
  (void)peer;
  PrintSummary(options, results, csv);
  std::printf("\nload average at the end: %s\n", LoadAverage().c_str());
  return 0;
}
