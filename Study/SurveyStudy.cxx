// The 2026 survey's protocol on the project's own core (Arnal-Anger et al.,
// "Survey on differential estimators for 3D point clouds", CGF 45(2)):
// its nine shapes with exact curvatures, clean, with position noise, with
// noisy normals and with outliers, each with the normals given and with
// them estimated; the RMSE over all points of the unsigned, sorted
// principal curvatures (a point not estimated counts as k = 0), beside the
// survey's own results at each estimator's best radius. The shapes and the
// survey's results are read from the workplace's folder, not copied here.
//
//   SurveyStudy SURVEY_FOLDER [--shapes a,b] [--conditions clean,pos0.01,...]
//                             [--threads N] [--details] [--keep-outliers] [--dump FOLDER]
//                             [--normal-field]
//
// --details: per shape, also the error of the points left in place and of
// those made outliers, and the share of each flagged as outliers;
// --keep-outliers: the estimation without its outlier step (to compare);
// --normal-field: NormalFieldFit on (the normal field's fit where the given
// normals' positions are noisy);
// --dump: every point's position, truth, estimate and verdict as CSV, one
// file per condition, shape and normals.
//
// The noise is one realization per shape and condition (std::mt19937_64,
// seed 1), not the survey's own sequence. Study/REPORT.md, "The survey's
// protocol", reports a run.
#include "Cloud/CloudPoints.h"
#include "Cloud/Collectives.h"
#include "Estimation/CloudEstimation.h"
#include "ThreadRunner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace
{
using namespace pcurv;

const std::vector<std::string> Shapes = { "cylinder",
  "ellipsoid",
  "goursat",
  "goursat-hole",
  "hyperboloid",
  "paraboloid",
  "selle",
  "torus",
  "tube" };
const std::vector<std::string> Conditions = { "clean",
  "pos0.0025",
  "pos0.005",
  "pos0.01",
  "pos0.015",
  "pos0.01+nrm0.1",
  "out0.01s0.1",
  "out0.05s0.1",
  "out0.1s0.1",
  "out0.01s0.2",
  "out0.05s0.2",
  "out0.1s0.2" };
// The survey's principal-curvature estimators (its methods.py lists, without
// the ones it leaves out), and those that read positions only: the peers of
// a run with estimated normals.
const std::set<std::string> Principal = { "3DQuadric",
  "Cov2D",
  "NormCov2D",
  "ShapeOperator",
  "2-Monge",
  "PC-MLS",
  "JetFitting",
  "WaveJets",
  "ASO",
  "Varifolds",
  "AvgHexagram" };
const std::set<std::string> PositionOnly = { "3DQuadric",
  "PC-MLS",
  "2-Monge",
  "WaveJets",
  "PCA",
  "APSS",
  "Sphere",
  "UnorientedSphere",
  "Cov2D",
  "Mean",
  "JetFitting" };

/// A shape in the survey's frame: centered on its barycenter, the farthest
/// point at distance 1, curvatures scaled alike.
struct Shape
{
  std::vector<double> Points, Normals, K1, K2, D1, D2; // 3 per point for vectors
  std::vector<unsigned char> Moved;                    // 1: made an outlier (Perturb)
  std::size_t Size() const { return this->K1.size(); }
};

bool LoadShape(const std::string& path, Shape& shape)
{
  std::ifstream file(path);
  std::string line;
  while (std::getline(file, line))
  {
    if (line.empty() || line[0] == '#')
    {
      continue;
    }
    std::istringstream in(line);
    double v[16];
    for (double& value : v)
    {
      in >> value;
    }
    if (!in)
    {
      return false;
    }
    shape.Points.insert(shape.Points.end(), v, v + 3);
    shape.Normals.insert(shape.Normals.end(), v + 5, v + 8);
    shape.K1.push_back(v[8]);
    shape.K2.push_back(v[9]);
    shape.D1.insert(shape.D1.end(), v + 10, v + 13);
    shape.D2.insert(shape.D2.end(), v + 13, v + 16);
  }
  const std::size_t n = shape.Size();
  if (n == 0)
  {
    return false;
  }
  double center[3] = { 0.0, 0.0, 0.0 };
  for (std::size_t i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      center[c] += shape.Points[3 * i + c] / static_cast<double>(n);
    }
  }
  double farthest = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    double squared = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      shape.Points[3 * i + c] -= center[c];
      squared += shape.Points[3 * i + c] * shape.Points[3 * i + c];
    }
    farthest = std::max(farthest, std::sqrt(squared));
  }
  for (double& x : shape.Points)
  {
    x /= farthest;
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    shape.K1[i] *= farthest;
    shape.K2[i] *= farthest;
  }
  return true;
}

/// The condition's cloud: position noise of `pos` (and normal noise of
/// `nrm`, the normals renormalized), or a share `rate` of outliers moved by
/// a Gaussian of `sigma`, all in the survey's unit.
void Perturb(const Shape& shape, const std::string& condition, Shape& noisy)
{
  noisy = shape;
  double pos = 0.0, nrm = 0.0, rate = 0.0, sigma = 0.0;
  if (condition.rfind("pos", 0) == 0)
  {
    pos = std::atof(condition.c_str() + 3);
    const std::size_t plus = condition.find("+nrm");
    nrm = plus == std::string::npos ? 0.0 : std::atof(condition.c_str() + plus + 4);
  }
  else if (condition.rfind("out", 0) == 0)
  {
    rate = std::atof(condition.c_str() + 3);
    sigma = std::atof(condition.c_str() + condition.find('s') + 1);
  }
  noisy.Moved.assign(shape.Size(), 0);
  std::mt19937_64 generator(1);
  std::normal_distribution<double> gaussian;
  std::uniform_real_distribution<double> uniform;
  for (std::size_t i = 0; i < shape.Size(); ++i)
  {
    const double g[3] = { gaussian(generator), gaussian(generator), gaussian(generator) };
    const bool outlier = uniform(generator) < rate;
    const double move = outlier ? sigma : pos;
    noisy.Moved[i] = outlier ? 1 : 0;
    double length = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      noisy.Points[3 * i + c] += move * g[c];
      noisy.Normals[3 * i + c] += nrm * g[c];
      length += noisy.Normals[3 * i + c] * noisy.Normals[3 * i + c];
    }
    for (int c = 0; c < 3 && nrm > 0.0; ++c)
    {
      noisy.Normals[3 * i + c] /= std::sqrt(length);
    }
  }
}

struct Estimate
{
  std::vector<double> Minimum, Maximum, MinimumDirection, MaximumDirection;
  std::vector<unsigned char> Valid, Outlier;
  std::vector<double> SurfaceDistance, StandardError;
  std::vector<int> NeighborCount;
  bool FourthOrder = false; // whether the automatic scale fitted the fourth order
};

/// EstimationSettings::NormalFieldFit for every run (--normal-field).
bool NormalFieldFit = false;

/// The core with the filter's defaults (estimating the normals when none
/// are given), on all cores.
Estimate Run(const Shape& cloud, bool givenNormals, int threads, bool moveOutliers)
{
  const std::size_t n = cloud.Size();
  CloudPoints points;
  points.Reset(static_cast<std::int64_t>(n));
  const double none[3] = { 0.0, 0.0, 0.0 };
  for (std::size_t i = 0; i < n; ++i)
  {
    points.AddInputPoint(static_cast<std::int64_t>(i),
      &cloud.Points[3 * i],
      givenNormals ? &cloud.Normals[3 * i] : none);
  }
  EstimationSettings settings;
  settings.EstimateNormals = !givenNormals;
  settings.MoveOutliers = moveOutliers;
  settings.NormalFieldFit = NormalFieldFit;
  Estimate e;
  e.Minimum.resize(n);
  e.Maximum.resize(n);
  e.MinimumDirection.resize(3 * n);
  e.MaximumDirection.resize(3 * n);
  e.Valid.resize(n);
  e.Outlier.resize(n);
  e.SurfaceDistance.resize(n);
  std::vector<double> mean(n), gauss(n), rms(n), surroundings(n), plane(n), fitted(3 * n),
    normals(3 * n);
  e.StandardError.resize(n);
  e.NeighborCount.resize(n);
  std::vector<int> directions(n);
  std::vector<unsigned char> trusted(n);
  CurvatureBuffers out;
  out.Minimum = e.Minimum.data();
  out.Maximum = e.Maximum.data();
  out.Mean = mean.data();
  out.Gauss = gauss.data();
  out.MinimumDirection = e.MinimumDirection.data();
  out.MaximumDirection = e.MaximumDirection.data();
  out.SineFitRms = rms.data();
  out.Surroundings = surroundings.data();
  out.PlaneDistance = plane.data();
  out.Valid = e.Valid.data();
  out.NeighborCount = e.NeighborCount.data();
  out.ValidDirections = directions.data();
  out.StandardError = e.StandardError.data();
  out.Trusted = trusted.data();
  out.FittedNormal = fitted.data();
  out.Normals = givenNormals ? nullptr : normals.data();
  out.Outlier = e.Outlier.data();
  out.SurfaceDistance = e.SurfaceDistance.data();
  testing::ThreadRunner runner(threads);
  e.FourthOrder =
    EstimateCloud(std::move(points), settings, Collectives{}, runner, nullptr, out).FourthOrderFits;
  return e;
}

/// |k1| <= |k2| with the directions along, as the survey compares them.
void SortByMagnitude(double& a, double& b, const double*& u, const double*& v)
{
  a = std::fabs(a);
  b = std::fabs(b);
  if (a > b)
  {
    std::swap(a, b);
    std::swap(u, v);
  }
}

double AngleDegrees(const double* u, const double* v)
{
  const double dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  const double lengths = std::sqrt(
    (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
  return std::acos(std::min(1.0, std::fabs(dot) / lengths)) * 180.0 / 3.14159265358979323846;
}

struct Score
{
  double K = 0.0, K1 = 0.0, K2 = 0.0, D1 = 0.0, Unestimated = 0.0;
  /// The share of the squared error of k1 and k2 carried by the worst 1 %
  /// of the points.
  double WorstShare = 0.0;
  /// k over the points left in place and over those made outliers; the
  /// share of each flagged as outliers.
  double KKept = 0.0, KMoved = 0.0, FlaggedKept = 0.0, FlaggedMoved = 0.0;
  /// The share of the valid points whose error max(|dk1|, |dk2|) is within
  /// twice their reported standard error.
  double Covered = 0.0;
};

/// k, and the share flagged, over the points of `truth` with Moved == moved.
void ScoreGroup(const std::vector<double>& squared,
  const Estimate& e,
  const Shape& noisy,
  unsigned char moved,
  double& k,
  double& flagged)
{
  double sum = 0.0, count = 0.0, flags = 0.0;
  for (std::size_t i = 0; i < squared.size(); ++i)
  {
    if (noisy.Moved[i] == moved)
    {
      sum += squared[i];
      count += 1.0;
      flags += e.Outlier[i] != 0 ? 1.0 : 0.0;
    }
  }
  k = count > 0.0 ? std::sqrt(0.5 * sum / count) : 0.0;
  flagged = count > 0.0 ? flags / count : 0.0;
}

/// The survey's metric over all points; a point not estimated is k = 0 with
/// Ponca's default directions.
Score ScoreOf(const Estimate& e, const Shape& truth, const Shape& noisy)
{
  const std::size_t n = truth.Size();
  const double x[3] = { 1.0, 0.0, 0.0 }, y[3] = { 0.0, 1.0, 0.0 };
  double s1 = 0.0, s2 = 0.0, sd = 0.0;
  std::vector<double> squared(n);
  Score score;
  for (std::size_t i = 0; i < n; ++i)
  {
    const bool failed = !e.Valid[i] || !std::isfinite(e.Minimum[i]) || !std::isfinite(e.Maximum[i]);
    double a = failed ? 0.0 : e.Minimum[i], b = failed ? 0.0 : e.Maximum[i];
    const double* u = failed ? x : &e.MinimumDirection[3 * i];
    const double* v = failed ? y : &e.MaximumDirection[3 * i];
    double g1 = truth.K1[i], g2 = truth.K2[i];
    const double* t1 = &truth.D1[3 * i];
    const double* t2 = &truth.D2[3 * i];
    SortByMagnitude(a, b, u, v);
    SortByMagnitude(g1, g2, t1, t2);
    squared[i] = (a - g1) * (a - g1) + (b - g2) * (b - g2);
    s1 += (a - g1) * (a - g1);
    s2 += (b - g2) * (b - g2);
    const double angle = std::fabs(g1 - g2) <= 1e-6 ? 0.0 : AngleDegrees(u, t1);
    sd += angle * angle;
    score.Unestimated += failed ? 1.0 : 0.0;
  }
  score.K1 = std::sqrt(s1 / n);
  score.K2 = std::sqrt(s2 / n);
  score.K = std::sqrt(0.5 * (score.K1 * score.K1 + score.K2 * score.K2));
  score.D1 = std::sqrt(sd / n);
  score.Unestimated /= static_cast<double>(n);
  double valid = 0.0, covered = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (e.Valid[i] && std::isfinite(e.Minimum[i]) && std::isfinite(e.Maximum[i]))
    {
      // Signed curvatures, as the standard error is stated for them, with
      // the normals' side either way (estimated normals may face the other).
      const double low = std::min(truth.K1[i], truth.K2[i]);
      const double high = std::max(truth.K1[i], truth.K2[i]);
      const double error =
        std::min(std::max(std::fabs(e.Minimum[i] - low), std::fabs(e.Maximum[i] - high)),
          std::max(std::fabs(e.Minimum[i] + high), std::fabs(e.Maximum[i] + low)));
      valid += 1.0;
      covered += error <= 2.0 * e.StandardError[i] ? 1.0 : 0.0;
    }
  }
  score.Covered = valid > 0.0 ? covered / valid : 0.0;
  ScoreGroup(squared, e, noisy, 0, score.KKept, score.FlaggedKept);
  ScoreGroup(squared, e, noisy, 1, score.KMoved, score.FlaggedMoved);
  std::sort(squared.begin(), squared.end(), std::greater<double>());
  const std::size_t worst = std::max<std::size_t>(1, n / 100);
  double all = 0.0, top = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    all += squared[i];
    top += i < worst ? squared[i] : 0.0;
  }
  score.WorstShare = all > 0.0 ? top / all : 0.0;
  return score;
}

/// Every point's position, truth, estimate and verdicts, as CSV (for a
/// closer look at the worst points).
void Dump(const std::string& path, const Estimate& e, const Shape& truth, const Shape& noisy)
{
  std::ofstream file(path);
  file << "x,y,z,moved,outlier,surface_distance,valid,k1,k2,true_k1,true_k2,neighbors,"
          "standard_error\n";
  file.precision(9);
  for (std::size_t i = 0; i < truth.Size(); ++i)
  {
    file << noisy.Points[3 * i] << ',' << noisy.Points[3 * i + 1] << ',' << noisy.Points[3 * i + 2]
         << ',' << int(noisy.Moved[i]) << ',' << int(e.Outlier[i]) << ',' << e.SurfaceDistance[i]
         << ',' << int(e.Valid[i]) << ',' << e.Minimum[i] << ',' << e.Maximum[i] << ','
         << truth.K1[i] << ',' << truth.K2[i] << ',' << e.NeighborCount[i] << ','
         << e.StandardError[i] << '\n';
  }
}

/// survey[condition][estimator][metric] = mean over the shapes run of the
/// best RMSE over the survey's radii.
using SurveyMeans = std::map<std::string, std::map<std::string, std::map<std::string, double>>>;

SurveyMeans LoadSurvey(const std::string& path, const std::vector<std::string>& shapes)
{
  SurveyMeans means;
  std::ifstream file(path);
  std::string line;
  std::getline(file, line); // header
  const std::set<std::string> wanted(shapes.begin(), shapes.end());
  while (std::getline(file, line))
  {
    std::vector<std::string> fields;
    std::istringstream in(line);
    for (std::string field; std::getline(in, field, ',');)
    {
      fields.push_back(field);
    }
    if (fields.size() < 5 || !wanted.count(fields[1]))
    {
      continue;
    }
    means[fields[0]][fields[2]][fields[3]] += std::atof(fields[4].c_str()) / shapes.size();
  }
  return means;
}

/// The best of `pool` in the survey's means for a metric (name, value).
std::pair<std::string, double> Best(
  const std::map<std::string, std::map<std::string, double>>& byEstimator,
  const std::string& metric,
  const std::set<std::string>& pool,
  const std::string& except = "")
{
  std::pair<std::string, double> best{ "-", INFINITY };
  for (const auto& [estimator, metrics] : byEstimator)
  {
    const auto found = metrics.find(metric);
    if (pool.count(estimator) && estimator != except && found != metrics.end() &&
      found->second < best.second)
    {
      best = { estimator, found->second };
    }
  }
  return best;
}

std::vector<std::string> Split(const std::string& text)
{
  std::vector<std::string> parts;
  std::istringstream in(text);
  for (std::string part; std::getline(in, part, ',');)
  {
    parts.push_back(part);
  }
  return parts;
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::fprintf(stderr,
      "usage: SurveyStudy SURVEY_FOLDER [--shapes a,b] [--conditions c,d] "
      "[--threads N] [--details] [--keep-outliers] [--dump FOLDER] [--normal-field]\n");
    return EXIT_FAILURE;
  }
  const std::string folder = argv[1];
  std::vector<std::string> shapes = Shapes, conditions = Conditions;
  int threads = std::max(1u, std::thread::hardware_concurrency());
  bool details = false, moveOutliers = true;
  std::string dump;
  for (int a = 2; a < argc; ++a)
  {
    const std::string arg = argv[a];
    if (arg == "--shapes" && a + 1 < argc)
    {
      shapes = Split(argv[++a]);
    }
    else if (arg == "--conditions" && a + 1 < argc)
    {
      conditions = Split(argv[++a]);
    }
    else if (arg == "--threads" && a + 1 < argc)
    {
      threads = std::max(1, std::atoi(argv[++a]));
    }
    else if (arg == "--details")
    {
      details = true;
    }
    else if (arg == "--keep-outliers")
    {
      moveOutliers = false;
    }
    else if (arg == "--normal-field")
    {
      NormalFieldFit = true;
    }
    else if (arg == "--dump" && a + 1 < argc)
    {
      dump = argv[++a];
    }
  }
  std::map<std::string, Shape> clouds;
  for (const std::string& name : shapes)
  {
    if (!LoadShape(folder + "/shapes/" + name + "_25000.pts", clouds[name]))
    {
      std::fprintf(stderr, "cannot read %s/shapes/%s_25000.pts\n", folder.c_str(), name.c_str());
      return EXIT_FAILURE;
    }
  }
  const SurveyMeans survey = LoadSurvey(folder + "/survey_results.csv", shapes);
  std::printf("k = sqrt((RMSE_k1^2 + RMSE_k2^2) / 2) over all points, mean over %zu shapes; "
              "the survey at 50k points, each estimator at its best radius per shape\n",
    shapes.size());
  std::printf("%-15s %9s %9s | %-26s | %-26s | %-26s | %11s | %11s | %9s\n",
    "condition",
    "given",
    "estimated",
    "best survey",
    "runner-up",
    "best position-only",
    "worst 1 %",
    "unest %",
    "d1 given");
  for (const std::string& condition : conditions)
  {
    Score given{}, estimated{};
    for (const std::string& name : shapes)
    {
      Shape noisy;
      Perturb(clouds[name], condition, noisy);
      Score both[2];
      bool fourthOrder[2] = { false, false };
      for (int g = 0; g < 2; ++g)
      {
        const Estimate e = Run(noisy, g == 0, threads, moveOutliers);
        both[g] = ScoreOf(e, clouds[name], noisy);
        fourthOrder[g] = e.FourthOrder;
        if (!dump.empty())
        {
          Dump(dump + "/" + condition + "_" + name + (g == 0 ? "_given" : "_estimated") + ".csv",
            e,
            clouds[name],
            noisy);
        }
      }
      if (details)
      {
        std::printf("  %-15s %-13s given k %.4f (worst 1 %% %.0f %%), estimated k %.4f; "
                    "k kept %.4f %.4f, moved %.4f %.4f; flagged kept %.2f %%, moved %.1f %%; "
                    "within 2 SE %.1f %% %.1f %%; fourth order %d %d\n",
          condition.c_str(),
          name.c_str(),
          both[0].K,
          100 * both[0].WorstShare,
          both[1].K,
          both[0].KKept,
          both[1].KKept,
          both[0].KMoved,
          both[1].KMoved,
          100 * both[0].FlaggedKept,
          100 * both[0].FlaggedMoved,
          100 * both[0].Covered,
          100 * both[1].Covered,
          fourthOrder[0] ? 1 : 0,
          fourthOrder[1] ? 1 : 0);
      }
      for (Score* sum : { &given, &estimated })
      {
        const Score& s = both[sum == &given ? 0 : 1];
        sum->K += s.K / shapes.size();
        sum->D1 += s.D1 / shapes.size();
        sum->WorstShare += s.WorstShare / shapes.size();
        sum->Unestimated += s.Unestimated / shapes.size();
      }
    }
    const auto& row = survey.count(condition) ? survey.at(condition) : SurveyMeans::mapped_type{};
    const auto best = Best(row, "k", Principal);
    const auto second = Best(row, "k", Principal, best.first);
    std::set<std::string> positions;
    std::set_intersection(Principal.begin(),
      Principal.end(),
      PositionOnly.begin(),
      PositionOnly.end(),
      std::inserter(positions, positions.begin()));
    const auto position = Best(row, "k", positions);
    std::printf("%-15s %9.4f %9.4f | %-17s %8.4f | %-17s %8.4f | %-17s %8.4f | %4.0f %% %4.0f %% | "
                "%4.2f %4.2f | %9.2f\n",
      condition.c_str(),
      given.K,
      estimated.K,
      best.first.c_str(),
      best.second,
      second.first.c_str(),
      second.second,
      position.first.c_str(),
      position.second,
      100 * given.WorstShare,
      100 * estimated.WorstShare,
      100 * given.Unestimated,
      100 * estimated.Unestimated,
      given.D1);
  }
  return EXIT_SUCCESS;
}
