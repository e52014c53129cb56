// PrincipalCurvatureBenchmark's report (BenchmarkReport.h): one function a
// table, the targets one function a row.
#include "BenchmarkReport.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace pcurv
{
namespace benchmark
{
namespace
{

/// A duration or other positive value with about three significant digits.
std::string Short(double value)
{
  if (!std::isfinite(value))
  {
    return "n/a";
  }
  const double magnitude = std::fabs(value);
  if (magnitude >= 100.0)
    return Format("%.0f", value);
  if (magnitude >= 10.0)
    return Format("%.1f", value);
  if (magnitude >= 1.0)
    return Format("%.2f", value);
  if (magnitude >= 0.1)
    return Format("%.3f", value);
  return Format("%.4f", value);
}

std::string Ratio(double value)
{
  if (!std::isfinite(value))
  {
    return "n/a";
  }
  return value < 0.1 ? Format("%.3fx", value) : Format("%.2fx", value);
}

/// 1234567 -> "1,234,567".
std::string Grouped(double value)
{
  if (!std::isfinite(value))
  {
    return "n/a";
  }
  std::string digits = Format("%.0f", value);
  for (int at = static_cast<int>(digits.size()) - 3; at > 0 && digits[at - 1] != '-'; at -= 3)
  {
    digits.insert(static_cast<std::size_t>(at), ",");
  }
  return digits;
}

/// 1000000 -> "1M", 20000 -> "20k".
std::string SizeName(long n)
{
  if (n >= 1000000 && n % 1000000 == 0)
    return Format("%ldM", n / 1000000);
  if (n >= 1000 && n % 1000 == 0)
    return Format("%ldk", n / 1000);
  return Format("%ld", n);
}

/// An aligned Markdown table: readable in a terminal, pasted as is.
class Table
{
public:
  explicit Table(std::vector<std::string> header)
    : Header(std::move(header))
  {
  }

  void Add(std::vector<std::string> row)
  {
    row.resize(this->Header.size());
    this->Rows.push_back(std::move(row));
  }

  void Print(const std::string& title, const std::string& note = "") const
  {
    std::vector<std::size_t> widths;
    for (const std::string& cell : this->Header)
    {
      widths.push_back(cell.size());
    }
    for (const auto& row : this->Rows)
    {
      for (std::size_t c = 0; c < row.size(); ++c)
      {
        widths[c] = std::max(widths[c], row[c].size());
      }
    }
    auto line = [&](const std::vector<std::string>& cells)
    {
      std::string text = "|";
      for (std::size_t c = 0; c < cells.size(); ++c)
      {
        text += " " + cells[c] + std::string(widths[c] - cells[c].size(), ' ') + " |";
      }
      std::printf("%s\n", text.c_str());
    };
    std::printf("\n### %s\n\n", title.c_str());
    line(this->Header);
    std::vector<std::string> rule;
    for (const std::size_t width : widths)
    {
      rule.push_back(std::string(width, '-'));
    }
    line(rule);
    for (const auto& row : this->Rows)
    {
      line(row);
    }
    if (!note.empty())
    {
      std::printf("\n%s\n", note.c_str());
    }
    std::fflush(stdout);
  }

private:
  std::vector<std::string> Header;
  std::vector<std::vector<std::string>> Rows;
};

/// Least-squares slope of log(time) against log(N).
double Exponent(const std::vector<std::pair<double, double>>& points)
{
  if (points.size() < 2)
  {
    return NaN;
  }
  double mx = 0.0, my = 0.0;
  for (const auto& p : points)
  {
    mx += std::log(p.first);
    my += std::log(p.second);
  }
  mx /= points.size();
  my /= points.size();
  double sxy = 0.0, sxx = 0.0;
  for (const auto& p : points)
  {
    sxy += (std::log(p.first) - mx) * (std::log(p.second) - my);
    sxx += (std::log(p.first) - mx) * (std::log(p.first) - mx);
  }
  return sxy / sxx;
}

/// The filter's median times against N, one point a size where it ran.
double ScalingExponent(const Options& options, const Results& results, int mode, long threads)
{
  std::vector<std::pair<double, double>> points;
  for (const long n : options.Sizes)
  {
    const double t = results.FilterTime(n, mode, threads);
    if (std::isfinite(t))
    {
      points.emplace_back(n, t);
    }
  }
  return Exponent(points);
}

void PrintHeading(const Options& options)
{
  const std::string description = SurfaceDescription(options.Surface);
  const std::string settings = options.Adjustment.empty()
    ? std::string("default settings (automatic radius for 375 neighbors, p = 0.1 s)")
    : "the dynamic adjustment, constants: " + options.Adjustment;
  std::printf("\n## Results: %s, exact normals, %s, medians of %d runs\n",
    description.c_str(),
    settings.c_str(),
    options.Runs);
}

void PrintFilterTable(const Options& options, const Results& results)
{
  Table table({ "points",
    "mode",
    "threads",
    "median s",
    "min..max s",
    "points/s",
    "vs New01",
    "speed-up vs 1 thread",
    "CPU use",
    "error k_min",
    "error k_max",
    "neighbors",
    "unestimated" });
  for (const long n : options.Sizes)
  {
    for (const long threads : options.Threads)
    {
      for (const int mode : options.Modes)
      {
        const auto found = results.Filter.find(FilterKey{ n, mode, threads });
        if (found == results.Filter.end())
        {
          continue;
        }
        const FilterRecord& r = found->second;
        const double t = r.Median();
        const double single = results.FilterTime(n, mode, options.Threads.front());
        table.Add({ SizeName(n),
          ModeNames[mode],
          std::to_string(threads),
          Short(t),
          Short(Smallest(r.Times)) + ".." + Short(Largest(r.Times)),
          Grouped(n / t),
          Ratio(t / results.FilterTime(n, 1, threads)),
          threads == options.Threads.front() ? "" : Ratio(single / t),
          Format("%.0f %%", 100.0 * Median(r.Utilization)),
          Format("%.4f", r.Errors.MeanMinimumError),
          Format("%.4f", r.Errors.MeanMaximumError),
          Format("%.0f", r.MeanNeighbors),
          std::to_string(r.Unestimated) });
      }
    }
  }
  table.Print("Whole filter: vtkPrincipalCurvatureEstimation::Update(), wall time",
    "errors: mean |k - k_true| / max |k_true| (MeasureErrors); \"vs New01\": time over New01's "
    "at the same size and threads; speed-up: time on " +
      std::to_string(options.Threads.front()) +
      " thread(s) over this one; CPU use: process CPU time over wall time x threads (well "
      "under 100 % means the threads waited, e.g. for other work on a shared machine).");
}

void PrintScalingTable(const Options& options, const Results& results, CsvFile& csv)
{
  std::vector<std::string> header{ "mode", "threads" };
  for (const long n : options.Sizes)
  {
    header.push_back(SizeName(n) + " us/point");
  }
  for (std::size_t k = 1; k < options.Sizes.size(); ++k)
  {
    header.push_back(
      "t(" + SizeName(options.Sizes[k]) + ")/t(" + SizeName(options.Sizes[k - 1]) + ")");
  }
  header.push_back("exponent (log-log fit)");
  Table table(header);
  for (const long threads : options.Threads)
  {
    for (const int mode : options.Modes)
    {
      std::vector<std::string> row{ ModeNames[mode], std::to_string(threads) };
      for (const long n : options.Sizes)
      {
        row.push_back(Short(1e6 * results.FilterTime(n, mode, threads) / n));
      }
      for (std::size_t k = 1; k < options.Sizes.size(); ++k)
      {
        row.push_back(Ratio(results.FilterTime(options.Sizes[k], mode, threads) /
          results.FilterTime(options.Sizes[k - 1], mode, threads)));
      }
      const double exponent = ScalingExponent(options, results, mode, threads);
      row.push_back(Format("%.3f", exponent));
      csv.Row("scaling", 0, ModeNames[mode], threads, "exponent", exponent, "1");
      table.Add(row);
    }
  }
  table.Print("Scaling: whole filter against N", "exponent 1 = linear in N.");
}

void PrintMemoryTable(const Results& results)
{
  Table table({ "points",
    "mode",
    "threads",
    "before update MB",
    "peak over it MB",
    "input MB (points, normals)",
    "output MB (new arrays)",
    "ratio to input+output",
    "process peak MB" });
  bool any = false;
  for (const SizeRecord& size : results.Sizes)
  {
    for (const auto& entry : size.Memory)
    {
      const MemoryRecord& m = entry.second;
      if (!m.Valid)
      {
        continue;
      }
      any = true;
      table.Add({ SizeName(size.N),
        ModeNames[entry.first.first],
        std::to_string(entry.first.second),
        Short(m.BaselineMB),
        Short(m.ExtraMB),
        Short(m.InputMB),
        Short(m.OutputMB),
        Ratio(m.RatioToArrays()),
        Short(m.ProcessPeakMB) });
    }
  }
  if (any)
  {
    table.Print("Peak memory of one Update() (a fresh child process per row)",
      "peak over it: VmHWM during the update minus VmRSS just before (reset through "
      "/proc/self/clear_refs); process peak: getrusage ru_maxrss, cloud generation included.");
  }
}

/// The phase table's note: where the queries are, and whether the core
/// gave the filter's results.
std::string PhaseNote(const Options& options, const PhaseRecord& ph)
{
  std::string note = Format("%ld query points (%s), %.0f neighbors each on average; ",
    ph.Queries,
    ph.Scale > 1.0 ? "16 blocks of the grid order, times scaled to the whole cloud"
                   : "the whole cloud in the filter's order",
    ph.Neighbors / ph.Queries);
  note += "same radius, lattice and order as the filter: the core's results equal the "
          "filter's at ";
  for (const int mode : options.Modes)
  {
    note += Format("%s %ld/%ld ", ModeNames[mode], ph.Queries - ph.Mismatches[mode], ph.Queries);
    if (ph.Mismatches[mode])
    {
      note += Format("(largest difference %.2g) ", ph.LargestDifference[mode]);
    }
  }
  note += "points. The sine fit is timed alone per point (FitSine + principal values and "
          "directions) and subtracted from Estimate(); Estimate() also forms each "
          "direction's six sums from the banks AddNeighborOffsets filled.";
  return note;
}

/// The phases that do not depend on the fit mode, and the sine fit, in
/// seconds for the whole cloud (extrapolated from the query points).
struct PhaseTimes
{
  double Grid;
  double Search;
  double Accumulate;
  double Sine;
};

PhaseTimes WholeCloudPhases(const SizeRecord& size)
{
  const PhaseRecord& ph = size.Phases;
  const double sinePerPoint =
    size.HasFits && size.Fits.Points ? Median(size.Fits.Sine) / size.Fits.Points : NaN;
  return { Median(ph.GridBuild),
    Median(ph.Search) * ph.Scale,
    Median(ph.Accumulate) * ph.Scale,
    sinePerPoint * size.N };
}

/// The rows that are the same in every mode's column: grid, search, sums.
void AddSharedPhaseRows(const Options& options,
  const PhaseRecord& ph,
  const PhaseTimes& times,
  Table& table)
{
  const double neighbors = ph.Neighbors; // per run, over the queries
  auto same = [&](const char* name, double value, const std::string& perNeighbor)
  {
    std::vector<std::string> row{ name };
    for (std::size_t m = 0; m < options.Modes.size(); ++m)
    {
      row.push_back(Short(value));
    }
    row.push_back(perNeighbor);
    table.Add(row);
  };
  same("grid build (counting sort, whole cloud)", times.Grid, "");
  same("neighbor search (GatherOffsetsWithinRadius)",
    times.Search,
    Format("%.1f ns", 1e9 * Median(ph.Search) / neighbors));
  same("half planes + sums (Begin, AddNeighborOffsets)",
    times.Accumulate,
    Format("%.1f ns", 1e9 * Median(ph.Accumulate) / neighbors));
}

void WritePhaseCsv(const SizeRecord& size,
  int mode,
  const PhaseTimes& times,
  double estimate,
  double rest,
  CsvFile& csv)
{
  const PhaseRecord& ph = size.Phases;
  const std::string name = ModeNames[mode];
  const std::string note = ph.Scale > 1.0 ? Format("extrapolated from %ld query points", ph.Queries)
                                          : std::string("all points");
  csv.Row("phase", size.N, name, 1, "grid_build_seconds", times.Grid, "s");
  csv.Row("phase", size.N, name, 1, "search_seconds", times.Search, "s", note);
  csv.Row("phase", size.N, name, 1, "binning_sums_seconds", times.Accumulate, "s", note);
  csv.Row("phase", size.N, name, 1, "fits_seconds", estimate - times.Sine, "s", note);
  csv.Row("phase", size.N, name, 1, "sine_seconds", times.Sine, "s", note);
  csv.Row("phase", size.N, name, 1, "rest_seconds", rest, "s");
}

void PrintPhaseTable(const Options& options,
  const Results& results,
  const SizeRecord& size,
  CsvFile& csv)
{
  const PhaseRecord& ph = size.Phases;
  const PhaseTimes times = WholeCloudPhases(size);
  std::vector<std::string> header{ "phase (1 thread)" };
  for (const int mode : options.Modes)
  {
    header.push_back(std::string(ModeNames[mode]) + " s");
  }
  header.push_back("per neighbor");
  Table table(header);
  AddSharedPhaseRows(options, ph, times, table);
  std::vector<std::string> fits{ "circle fits (Estimate minus sine fit)" };
  std::vector<std::string> sineRow{ "sine fit + directions (measured alone)" };
  std::vector<std::string> estimateRow{ "Estimate(): fits + sine fit" };
  std::vector<std::string> total{ "sum of the phases" };
  std::vector<std::string> whole{ "whole filter, 1 thread" };
  std::vector<std::string> rest{ "rest (arrays in/out, radius estimate, threads)" };
  std::vector<std::string> fitShare{ "fit phase vs Previous's" };
  const double previousEstimate =
    Median(ph.Estimate[0]) * ph.Scale; // NaN when Previous was not measured
  for (const int mode : options.Modes)
  {
    const double estimate = Median(ph.Estimate[mode]) * ph.Scale;
    const double sum = times.Grid + times.Search + times.Accumulate + estimate;
    const double filter = results.FilterTime(size.N, mode, 1);
    fits.push_back(Short(estimate - times.Sine));
    sineRow.push_back(Short(times.Sine));
    estimateRow.push_back(Short(estimate));
    total.push_back(Short(sum));
    whole.push_back(Short(filter));
    rest.push_back(Short(filter - sum));
    fitShare.push_back(Ratio(estimate / previousEstimate));
    WritePhaseCsv(size, mode, times, estimate, filter - sum, csv);
  }
  for (const auto* row : { &fits, &sineRow, &estimateRow, &total, &whole, &rest })
  {
    table.Add(*row);
  }
  if (std::find(options.Modes.begin(), options.Modes.end(), 0) != options.Modes.end())
  {
    table.Add(fitShare);
  }
  table.Print(Format("Phases, %s points, seconds for the whole cloud", SizeName(size.N).c_str()),
    PhaseNote(options, ph));
}

void PrintFitsAloneTable(const Options& options, const SizeRecord& size, CsvFile& csv)
{
  const FitsRecord& f = size.Fits;
  const double directions = static_cast<double>(f.Directions);
  const double previous = Median(f.Fit[0]);
  const double perPoint = directions / static_cast<double>(f.Points);
  Table table(
    { "fit", "ns per direction", "ns per point", "vs Previous", "paper (Getto & Hildenbrand)" });
  const char* paper[3] = { "1", "about 0.5", "about 0.75" };
  const char* names[3] = { "Previous (3x3 symmetric eigen solve)",
    "New01 (kappa_23)",
    "New02's two closed forms (kappa_12 + kappa_23)" };
  for (int mode = 0; mode < 3; ++mode)
  {
    const double t = Median(f.Fit[mode]);
    table.Add({ names[mode],
      Format("%.1f", 1e9 * t / directions),
      Format("%.0f", 1e9 * t / directions * perPoint),
      Ratio(t / previous),
      paper[mode] });
    csv.Row("fits_alone",
      size.N,
      ModeNames[mode],
      1,
      "ns_per_direction",
      1e9 * t / directions,
      "ns",
      Format("%zu directions of %zu points", f.Directions, f.Points));
  }
  table.Add({ "sine fit + principal values and directions",
    "",
    Format("%.0f", 1e9 * Median(f.Sine) / f.Points),
    "",
    "" });
  // In the pipeline, for comparison: Estimate() per point (fits, New02's
  // pass over the points, sine fit).
  if (size.HasPhases)
  {
    for (const int mode : options.Modes)
    {
      const double t = Median(size.Phases.Estimate[mode]) / size.Phases.Queries;
      table.Add({ std::string("in the pipeline: Estimate(), ") + ModeNames[mode],
        "",
        Format("%.0f", 1e9 * t),
        Ratio(Median(size.Phases.Estimate[mode]) / Median(size.Phases.Estimate[0])),
        "" });
    }
  }
  table.Print(Format("The paper's timing claim: fits alone on identical CGA sums (%zu "
                     "directions of %zu points of the %s cloud)",
                f.Directions,
                f.Points,
                SizeName(size.N).c_str()),
    Format("Each fit over the same collected sums, medians of %zu runs. New02's choice between "
           "its two candidates also needs a pass over the direction's points (the summed "
           "distance to each circle), included in the Estimate() rows (which add the sine "
           "fit). Rebuilt from these sums, New01's estimate equals the core's to %.1g.",
      f.Fit[0].size(),
      f.LargestDifference));
}

/// The peer's CSV rows of one size: CGAL's, then the core's in every mode.
void WritePeerCsv(const Options& options, const SizeRecord& size, double cgal, CsvFile& csv)
{
  const PeerRecord& p = size.Peer;
  const double search = Median(p.Search) / p.Queries;
  const std::string note = Format("%ld query points, extrapolated per point", p.Queries);
  csv.Row("peer", size.N, "CGAL", 1, "seconds", cgal * size.N, "s", note);
  csv.Row("peer", size.N, "CGAL", 1, "error_min", p.CgalError[0], "1", note);
  csv.Row("peer", size.N, "CGAL", 1, "error_max", p.CgalError[1], "1", note);
  for (const int mode : options.Modes)
  {
    const std::string core = std::string("core ") + ModeNames[mode];
    const double seconds = (search + Median(p.Ours[mode]) / p.Queries) * size.N;
    csv.Row("peer", size.N, core, 1, "seconds", seconds, "s", note);
    csv.Row("peer", size.N, core, 1, "error_min", p.OursError[mode][0], "1", note);
    csv.Row("peer", size.N, core, 1, "error_max", p.OursError[mode][1], "1", note);
  }
}

void PrintPeerTable(const Options& options, const Results& results, CsvFile& csv)
{
  Table table({ "points",
    "query points",
    "CGAL us/point (search + jet fit)",
    "ours us/point (search + core, New01)",
    "CGAL / ours",
    "ours whole filter us/point (1 thread)",
    "CGAL / whole filter",
    "CGAL whole cloud s (extrapolated)",
    "CGAL errors k_min / k_max",
    "ours errors k_min / k_max (same points)" });
  for (const SizeRecord& size : results.Sizes)
  {
    if (!size.HasPeer)
    {
      continue;
    }
    const PeerRecord& p = size.Peer;
    const int ourMode =
      std::find(options.Modes.begin(), options.Modes.end(), 1) != options.Modes.end()
      ? 1
      : options.Modes.front();
    const double search = Median(p.Search) / p.Queries;
    const double cgal = search + Median(p.Cgal) / p.Queries;
    const double ours = search + Median(p.Ours[ourMode]) / p.Queries;
    const double whole = results.FilterTime(size.N, ourMode, 1) / size.N;
    table.Add({ SizeName(size.N),
      Grouped(p.Queries),
      Short(1e6 * cgal),
      Short(1e6 * ours),
      Ratio(cgal / ours),
      Short(1e6 * whole),
      Ratio(cgal / whole),
      Short(cgal * size.N),
      Format("%.4f / %.4f", p.CgalError[0], p.CgalError[1]),
      Format("%.4f / %.4f", p.OursError[ourMode][0], p.OursError[ourMode][1]) });
    WritePeerCsv(options, size, cgal, csv);
  }
  table.Print("Peer: CGAL Monge_via_jet_fitting (degree 2, Monge degree 2), one core, same "
              "neighborhoods",
    "CGAL is timed on the query points only (spread over the surface) and extrapolated per "
    "point to the whole cloud. Its curvatures are turned to the exact (outward) normal "
    "(comply_wrt_given_normal) and to the filter's sign. Same radius neighbors as the "
    "filter, gathered with the same grid; errors on the same query points, over max "
    "|k_true| of the cloud.");
}

// ---------------------------------------------------------------------------
// Against the targets: one row a target.

/// What the target rows are judged on: the largest size, the largest
/// thread count, and the extrapolation of the largest size to 1M points.
struct TargetContext
{
  const Options& Opt;
  const Results& Res;
  long Largest;
  long Two;
  bool HasTwo;
  double At;
  std::string Where;
};

const char* Verdict(bool known, bool met)
{
  return known ? (met ? "yes" : "**no**") : "n/a";
}

void AddTimeTargets(const TargetContext& c, Table& table)
{
  {
    const double t = c.Res.FilterTime(c.Largest, 1, c.Two) * c.At;
    table.Add({ "whole filter, 1M points, New01, 2 threads <= 1.5 s",
      Format("%s s on %ld thread(s)%s", Short(t).c_str(), c.Two, c.Where.c_str()),
      Verdict(std::isfinite(t) && c.HasTwo, t <= 1.5) });
  }
  std::string measured;
  bool known = c.HasTwo, met = true;
  for (const int mode : c.Opt.Modes)
  {
    const double t = c.Res.FilterTime(c.Largest, mode, c.Two) * c.At;
    measured += Format("%s %s s; ", ModeNames[mode], Short(t).c_str());
    known = known && std::isfinite(t);
    met = met && t <= 3.0;
  }
  table.Add({ "every mode <= 2x that (3 s)", measured + c.Where, Verdict(known, met) });
}

void AddPeerTarget(const TargetContext& c, Table& table)
{
  double ratio = NaN;
  for (const SizeRecord& size : c.Res.Sizes)
  {
    if (size.HasPeer && size.N == c.Largest)
    {
      const PeerRecord& p = size.Peer;
      const double cgal = (Median(p.Search) + Median(p.Cgal)) / p.Queries;
      ratio = cgal / (c.Res.FilterTime(size.N, 1, 1) / size.N);
    }
  }
  table.Add({ ">= 30x faster than CGAL jet fitting per core",
    Format("%s (CGAL per point over the whole filter's per point, 1 thread, %s)",
      Ratio(ratio).c_str(),
      SizeName(c.Largest).c_str()),
    Verdict(std::isfinite(ratio), ratio >= 30.0) });
}

void AddLinearTarget(const TargetContext& c, Table& table)
{
  std::string measured;
  bool known = c.Opt.Sizes.size() > 1, met = true;
  for (const long threads : c.Opt.Threads)
  {
    for (const int mode : c.Opt.Modes)
    {
      const double exponent = ScalingExponent(c.Opt, c.Res, mode, threads);
      known = known && std::isfinite(exponent);
      met = met && std::fabs(exponent - 1.0) <= 0.1;
      if (mode == 1 || c.Opt.Modes.size() == 1)
      {
        measured += Format("New01 %ld thread(s): exponent %.3f; ", threads, exponent);
      }
    }
  }
  table.Add({ "time linear in N (log-log exponent within 1 +- 0.1, every mode)",
    measured,
    Verdict(known, met) });
}

void AddThreadsTarget(const TargetContext& c, Table& table)
{
  double worst = HUGE_VAL;
  std::string measured;
  for (const int mode : c.Opt.Modes)
  {
    const double s = c.Res.FilterTime(c.Largest, mode, c.Opt.Threads.front()) /
      c.Res.FilterTime(c.Largest, mode, c.Two);
    worst = std::min(worst, s);
    measured += Format("%s %s; ", ModeNames[mode], Ratio(s).c_str());
  }
  table.Add({ "2 threads >= 1.8x faster than 1",
    measured + "at " + SizeName(c.Largest),
    Verdict(c.HasTwo && c.Opt.Threads.front() == 1 && std::isfinite(worst), worst >= 1.8) });
}

void AddMemoryTarget(const TargetContext& c, Table& table)
{
  double worst = NaN;
  for (const SizeRecord& size : c.Res.Sizes)
  {
    for (const auto& entry : size.Memory)
    {
      if (entry.second.Valid)
      {
        const double r = entry.second.RatioToArrays();
        worst = std::isfinite(worst) ? std::max(worst, r) : r;
      }
    }
  }
  table.Add({ "peak memory <= 3x input + output arrays",
    Format("at most %s", Ratio(worst).c_str()),
    Verdict(std::isfinite(worst), worst <= 3.0) });
}

void AddFitPhaseTarget(const TargetContext& c, Table& table)
{
  double pipeline = NaN, alone = NaN;
  std::string which;
  for (const SizeRecord& size : c.Res.Sizes)
  {
    if (size.HasPhases)
    {
      pipeline = Median(size.Phases.Estimate[1]) / Median(size.Phases.Estimate[0]);
      which = SizeName(size.N);
    }
    if (size.HasFits && size.N == c.Opt.Sizes.front())
    {
      alone = Median(size.Fits.Fit[1]) / Median(size.Fits.Fit[0]);
    }
  }
  table.Add({ "New01 fit phase <= 0.5x Previous's",
    Format("%s in the pipeline (fits + sine fit, %s); %s fits alone",
      Ratio(pipeline).c_str(),
      which.c_str(),
      Ratio(alone).c_str()),
    Verdict(std::isfinite(pipeline), pipeline <= 0.5) });
}

void AddPreviousTarget(const TargetContext& c, Table& table)
{
  std::string measured;
  bool known = true, met = true;
  for (const long threads : c.Opt.Threads)
  {
    const double r =
      c.Res.FilterTime(c.Largest, 0, threads) / c.Res.FilterTime(c.Largest, 1, threads);
    known = known && std::isfinite(r);
    met = met && r <= 1.5;
    measured += Format("%s on %ld thread(s); ", Ratio(r).c_str(), threads);
  }
  table.Add({ "Previous whole pipeline <= 1.5x New01's",
    measured + "at " + SizeName(c.Largest),
    Verdict(known, met) });
}

void PrintTargets(const Options& options, const Results& results)
{
  const long largest = options.Sizes.back();
  const long two = options.Threads.back();
  const TargetContext context{ options,
    results,
    largest,
    two,
    two >= 2,
    1e6 / largest, // extrapolation to 1M points
    largest == 1000000 ? "" : Format(" (from %s, scaled to 1M)", SizeName(largest).c_str()) };
  Table table({ "target", "measured", "met?" });
  AddTimeTargets(context, table);
  AddPeerTarget(context, table);
  AddLinearTarget(context, table);
  AddThreadsTarget(context, table);
  AddMemoryTarget(context, table);
  AddFitPhaseTarget(context, table);
  AddPreviousTarget(context, table);
  table.Print("Against the targets");
}

} // namespace

void PrintSummary(const Options& options, const Results& results, CsvFile& csv)
{
  PrintHeading(options);
  PrintFilterTable(options, results);
  if (options.Sizes.size() > 1)
  {
    PrintScalingTable(options, results, csv);
  }
  PrintMemoryTable(results);
  for (const SizeRecord& size : results.Sizes)
  {
    if (size.HasPhases)
    {
      PrintPhaseTable(options, results, size, csv);
    }
  }
  for (const SizeRecord& size : results.Sizes)
  {
    if (size.HasFits && size.N == options.Sizes.front())
    {
      PrintFitsAloneTable(options, size, csv);
    }
  }
  const bool anyPeer = std::any_of(results.Sizes.begin(),
    results.Sizes.end(),
    [](const SizeRecord& size) { return size.HasPeer; });
  if (anyPeer)
  {
    PrintPeerTable(options, results, csv);
  }
  PrintTargets(options, results);
}

} // namespace benchmark
} // namespace pcurv
