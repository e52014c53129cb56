/**
 * @file BenchmarkResults.h
 * @brief What PrincipalCurvatureBenchmark measures and is asked for: its
 * options, the records of each measurement, the CSV file, and the small
 * helpers (medians, printf into a string) that the measuring code and the
 * report (BenchmarkReport.h) share.
 */
#ifndef BenchmarkResults_h
#define BenchmarkResults_h

#include "AnalyticClouds.h"

#include "vtkType.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace pcurv
{
namespace benchmark
{

inline const char* const ModeNames[3] = { "Previous", "New01", "New02" };
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

inline double Median(std::vector<double> values)
{
  if (values.empty())
  {
    return NaN;
  }
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

inline double Smallest(const std::vector<double>& values)
{
  return values.empty() ? NaN : *std::min_element(values.begin(), values.end());
}

inline double Largest(const std::vector<double>& values)
{
  return values.empty() ? NaN : *std::max_element(values.begin(), values.end());
}

/// printf into a std::string.
template<typename... Args>
std::string Format(const char* format, Args... args)
{
  const int length = std::snprintf(nullptr, 0, format, args...);
  std::string text(static_cast<std::size_t>(std::max(length, 0)) + 1, '\0');
  std::snprintf(&text[0], text.size(), format, args...);
  text.resize(text.size() - 1);
  return text;
}

inline std::string SurfaceDescription(const std::string& name)
{
  if (name == "sphere")
    return "sphere r = 1";
  if (name == "ellipsoid")
    return "ellipsoid 3 x 2 x 1";
  return "torus R = 3, r = 1";
}

/// One measurement a line: section,surface,points,mode,threads,metric,value,unit,note.
class CsvFile
{
public:
  bool Open(const std::string& path, const std::string& surface)
  {
    this->Surface = surface;
    this->File = std::fopen(path.c_str(), "w");
    if (this->File)
    {
      std::fprintf(this->File, "section,surface,points,mode,threads,metric,value,unit,note\n");
    }
    return this->File != nullptr;
  }

  ~CsvFile()
  {
    if (this->File)
    {
      std::fclose(this->File);
    }
  }

  void Row(const char* section,
    long points,
    const std::string& mode,
    long threads,
    const char* metric,
    double value,
    const char* unit,
    const std::string& note = "")
  {
    if (this->File)
    {
      std::fprintf(this->File,
        "%s,%s,%ld,%s,%ld,%s,%.9g,%s,%s\n",
        section,
        this->Surface.c_str(),
        points,
        mode.c_str(),
        threads,
        metric,
        value,
        unit,
        note.c_str());
      std::fflush(this->File);
    }
  }

private:
  std::FILE* File = nullptr;
  std::string Surface;
};

struct Options
{
  std::vector<long> Sizes{ 10000, 100000, 1000000 };
  std::vector<long> Threads{ 1, 2 };
  std::vector<int> Modes{ 0, 1, 2 };
  int Runs = 5;
  std::string Surface = "torus";
  long PhasePoints = 200000;
  long FitPoints = 20000;
  long PeerPoints = 20000;
  bool Peer = true;
  bool Phases = true;
  bool Memory = true;
  bool MemoryProbe = false; // internal: this process is the memory child
  std::string Csv;
  std::string Adjustment; // empty: fixed thresholds (the filter's default)
};

// ---------------------------------------------------------------------------
// The records of the measurements

struct MemoryRecord
{
  bool Valid = false;
  double BaselineMB = NaN; // resident before the update (the input cloud, libraries)
  double ExtraMB = NaN;    // peak resident during the update, over the baseline
  double ProcessPeakMB = NaN;
  double InputMB = NaN;  // points + normals
  double OutputMB = NaN; // arrays created by the filter
  double RatioToArrays() const { return this->ExtraMB / (this->InputMB + this->OutputMB); }
};

struct FilterRecord
{
  std::vector<double> Times;
  std::vector<double> Utilization; // CPU time / (wall time x threads)
  pcurv::testing::CurvatureErrors Errors;
  vtkIdType Unestimated = 0;
  double MeanNeighbors = NaN;
  double Median() const { return benchmark::Median(this->Times); }
};

using FilterKey = std::tuple<long, int, long>; // points, mode, threads

struct PhaseRecord
{
  long Queries = 0;
  double Neighbors = 0.0; // summed over the queries (one run)
  std::vector<double> GridBuild, Search, Accumulate, Estimate[3];
  double Scale = 1.0;      // N / Queries: extrapolation to the whole cloud
  long Mismatches[3] = {}; // points where the core differs from the filter
  double LargestDifference[3] = {};
};

/// The fits timed alone on identical per-direction sums (the paper's claim).
struct FitsRecord
{
  std::size_t Points = 0;
  std::size_t Directions = 0;
  std::vector<double> Fit[3];     // seconds over all directions; New02: both closed forms
  std::vector<double> Sine;       // seconds over all points: FitSine + principal values/directions
  double LargestDifference = 0.0; // rebuilt New01 estimate against the core's Estimate()
};

struct PeerRecord
{
  long Queries = 0;
  std::vector<double> Search, Cgal, Ours[3]; // seconds over the queries
  double CgalError[2] = { NaN, NaN };        // k_min, k_max
  double OursError[3][2] = { { NaN, NaN }, { NaN, NaN }, { NaN, NaN } };
  long CgalInvalid = 0;
  long OursInvalid[3] = {};
};

/// Everything measured on one cloud size but the whole-filter runs.
struct SizeRecord
{
  long N = 0;
  double S = NaN, P = NaN;
  bool HasPhases = false, HasFits = false, HasPeer = false;
  PhaseRecord Phases;
  FitsRecord Fits;
  PeerRecord Peer;
  std::map<std::pair<int, long>, MemoryRecord> Memory; // (mode, threads)
};

/// Everything measured, for the summary.
struct Results
{
  std::map<FilterKey, FilterRecord> Filter;
  std::vector<SizeRecord> Sizes;

  double FilterTime(long n, int mode, long threads) const
  {
    const auto found = this->Filter.find(FilterKey{ n, mode, threads });
    return found == this->Filter.end() ? NaN : found->second.Median();
  }
};

} // namespace benchmark
} // namespace pcurv

#endif
