// Curvature lines (no VTK): the extremal lines of the principal curvatures
// found from exact curvatures (the extraction alone) and from the
// estimator's, on surfaces whose lines are known: a triaxial ellipsoid (its
// three principal ellipses), an extruded Gaussian bump (a ridge on its
// crest, a valley on each side), and surfaces with none (a torus, a plane).
#include "CloudTestSupport.h"
#include "LineScoring.h"

#include "Lines/CurvatureLines.h"
#include "Lines/LineDerivatives.h"

#include <limits>

namespace
{
using namespace pcurv;
using namespace cloudtest;
using linetest::LineScore;
using linetest::TruePolyline;
using testing::Vec;

constexpr double A = 3.0, B = 2.0, C = 1.0;             // the ellipsoid's semi-axes
constexpr double Height = 0.5, Width = 1.0, Half = 4.0; // the bump's

/// The arrays a LineInput points to.
struct LineArrays
{
  std::vector<double> Points, Normals, Maximum, Minimum, MaximumDirection, MinimumDirection,
    StandardError, Radius;
  std::vector<unsigned char> Valid;

  LineInput Input() const
  {
    LineInput in;
    in.Count = static_cast<std::int64_t>(this->Maximum.size());
    in.Points = this->Points.data();
    in.Normals = this->Normals.data();
    in.MaximumCurvature = this->Maximum.data();
    in.MinimumCurvature = this->Minimum.data();
    in.MaximumDirection = this->MaximumDirection.data();
    in.MinimumDirection = this->MinimumDirection.data();
    in.StandardError = this->StandardError.empty() ? nullptr : this->StandardError.data();
    in.Radius = this->Radius.empty() ? nullptr : this->Radius.data();
    in.Valid = this->Valid.empty() ? nullptr : this->Valid.data();
    return in;
  }
};

void AddGeometry(LineArrays& arrays, const std::vector<testing::SurfaceSample>& samples)
{
  for (const testing::SurfaceSample& s : samples)
  {
    arrays.Points.insert(arrays.Points.end(), s.Point.begin(), s.Point.end());
    arrays.Normals.insert(arrays.Normals.end(), s.Normal.begin(), s.Normal.end());
  }
}

/// The exact curvatures and directions, with a radius of `radius`.
LineArrays ExactArrays(const std::vector<testing::SurfaceSample>& samples, double radius)
{
  LineArrays arrays;
  AddGeometry(arrays, samples);
  for (const testing::SurfaceSample& s : samples)
  {
    arrays.Maximum.push_back(s.MaximumCurvature);
    arrays.Minimum.push_back(s.MinimumCurvature);
    arrays.MaximumDirection.insert(
      arrays.MaximumDirection.end(), s.MaximumDirection.begin(), s.MaximumDirection.end());
    const Vec other = testing::Cross(s.Normal, s.MaximumDirection);
    arrays.MinimumDirection.insert(arrays.MinimumDirection.end(), other.begin(), other.end());
    arrays.Radius.push_back(radius);
  }
  return arrays;
}

/// The estimator's curvatures (default settings, the given normals), with
/// its standard errors and neighborhood radii.
LineArrays EstimatedArrays(const std::vector<testing::SurfaceSample>& samples)
{
  Results out(samples.size(), false);
  std::vector<double> standardError(samples.size());
  CurvatureBuffers buffers = out.Buffers();
  buffers.StandardError = standardError.data();
  ThreadRunner threads(2);
  EstimateCloud(MakeCloud(samples), EstimationSettings{}, Collectives{}, threads, nullptr, buffers);
  LineArrays arrays;
  AddGeometry(arrays, samples);
  arrays.Maximum = out.Maximum;
  arrays.Minimum = out.Minimum;
  arrays.MaximumDirection = out.MaximumDirection;
  arrays.MinimumDirection = out.MinimumDirection;
  arrays.StandardError = standardError;
  arrays.Radius = out.Surroundings;
  arrays.Valid = out.Valid;
  return arrays;
}

LineResult Extract(const LineArrays& arrays, unsigned kinds)
{
  LineSettings settings;
  settings.Kinds = kinds;
  ThreadRunner threads(2);
  return ExtractCurvatureLines(arrays.Input(), settings, &threads);
}

double EllipsoidSpacing(std::size_t n)
{
  const double p = 1.6075;
  const double mean = (std::pow(A * B, p) + std::pow(A * C, p) + std::pow(B * C, p)) / 3.0;
  const double area = 4.0 * testing::Pi * std::pow(mean, 1.0 / p);
  return std::sqrt(area / static_cast<double>(n));
}

/// The three principal ellipses, where every extremal line of a triaxial
/// ellipsoid lies.
std::vector<TruePolyline> PrincipalEllipses()
{
  std::vector<TruePolyline> ellipses(3);
  const int samples = 40000;
  for (int i = 0; i <= samples; ++i)
  {
    const double t = 2.0 * testing::Pi * i / samples, c = std::cos(t), s = std::sin(t);
    ellipses[0].push_back({ { A * c, B * s, 0.0 } });
    ellipses[1].push_back({ { A * c, 0.0, C * s } });
    ellipses[2].push_back({ { 0.0, B * c, C * s } });
  }
  return ellipses;
}

LineScore ScoreEllipsoid(const LineResult& result, double spacing)
{
  return linetest::Score(
    result, PrincipalEllipses(), spacing, 2.0, 2.0, [](const Vec&) { return true; });
}

/// The bump z = h exp(-x^2 / 2 w^2), extruded along y.
testing::Surface Bump()
{
  return testing::HeightField("bump",
    Half,
    [](double x, double)
    {
      const double g = Height * std::exp(-x * x / (2.0 * Width * Width));
      const double w2 = Width * Width;
      return std::array<double, 6>{
        { g, -x / w2 * g, 0.0, (x * x / (w2 * w2) - 1.0 / w2) * g, 0.0, 0.0 }
      };
    });
}

/// The curvature of the bump's profile (positive on the crest, as the
/// filter's sign with normals up).
double ProfileCurvature(double x)
{
  const double w2 = Width * Width;
  const double g = Height * std::exp(-x * x / (2.0 * w2));
  const double slope = -x / w2 * g, second = (x * x / (w2 * w2) - 1.0 / w2) * g;
  return -second / std::pow(1.0 + slope * slope, 1.5);
}

/// Where the profile's curvature is least (x > 0): the valley, by golden
/// section on [w, 3w], where it has its one minimum.
double ValleyPosition()
{
  double low = Width, high = 3.0 * Width;
  const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int i = 0; i < 200; ++i)
  {
    const double a = high - ratio * (high - low), b = low + ratio * (high - low);
    if (ProfileCurvature(a) < ProfileCurvature(b))
    {
      high = b;
    }
    else
    {
      low = a;
    }
  }
  return 0.5 * (low + high);
}

std::vector<TruePolyline> BumpLines()
{
  std::vector<TruePolyline> lines;
  const double valley = ValleyPosition();
  for (double x : { -valley, 0.0, valley })
  {
    TruePolyline line;
    const double z = Height * std::exp(-x * x / (2.0 * Width * Width));
    for (int i = 0; i <= 20000; ++i)
    {
      line.push_back({ { x, -Half + 2.0 * Half * i / 20000.0, z } });
    }
    lines.push_back(line);
  }
  return lines;
}

/// The bump's scores away from its patch's edges, where the estimator's
/// neighborhoods are one-sided.
LineScore ScoreBump(const LineResult& result, double spacing, double tolerance)
{
  const double margin = 0.5;
  return linetest::Score(result,
    BumpLines(),
    spacing,
    tolerance,
    tolerance,
    [=](const Vec& x)
    { return std::fabs(x[0]) < Half - margin && std::fabs(x[1]) < Half - margin; });
}

double TotalLength(const LineResult& result)
{
  double length = 0.0;
  for (const CurvatureLine& line : result.Lines)
  {
    length += line.Length;
  }
  return length;
}

/// Every extremal line of a triaxial ellipsoid lies on its principal
/// ellipses and the lines cover them, from the exact curvatures.
void TestExactEllipsoid(Checks& checks)
{
  const std::size_t n = 100000;
  const auto samples = testing::Sample(testing::Ellipsoid(A, B, C), n, 71);
  const double spacing = EllipsoidSpacing(n);
  const LineScore score =
    ScoreEllipsoid(Extract(ExactArrays(samples, 4.0 * spacing), AllLineKinds), spacing);
  score.Print("ellipsoid, exact curvatures, all kinds");
  checks.True("exact ellipsoid: 95 % of line points within 1 spacing", score.WithinOne >= 0.95);
  checks.True("exact ellipsoid: 95 % of the ellipses covered", score.Covered >= 0.95);
  checks.Below("exact ellipsoid: false length share", score.FalseShare, 0.02);
}

/// The scores of the estimator's lines on independent draws of the
/// ellipsoid (100k points, uniform in area), with `noise` spacings of
/// position noise: one draw's coverage moves by a few percent from the
/// next's (where the lines stop short of the ellipses' ends), so the
/// tests hold the draws' mean and each draw's floor.
std::vector<LineScore> EllipsoidDraws(double noise, const char* what)
{
  const std::size_t n = 100000;
  const double spacing = EllipsoidSpacing(n);
  std::vector<LineScore> scores;
  for (std::uint64_t draw = 0; draw < 6; ++draw)
  {
    auto samples = testing::Sample(testing::Ellipsoid(A, B, C), n, 72 + 100 * draw);
    if (noise > 0.0)
    {
      testing::AddPositionNoise(samples, noise * spacing, 74 + 100 * draw);
    }
    scores.push_back(ScoreEllipsoid(Extract(EstimatedArrays(samples), AllLineKinds), spacing));
    scores.back().Print(what);
  }
  return scores;
}

/// The mean of one score over the draws.
double MeanOf(const std::vector<LineScore>& scores, double LineScore::*score)
{
  double sum = 0.0;
  for (const LineScore& s : scores)
  {
    sum += s.*score;
  }
  return scores.empty() ? 0.0 : sum / static_cast<double>(scores.size());
}

/// The worst of one score over the draws (the least, or the most where
/// less is better).
double WorstOf(const std::vector<LineScore>& scores, double LineScore::*score, bool lessIsBetter)
{
  double worst = lessIsBetter ? 0.0 : 1.0;
  for (const LineScore& s : scores)
  {
    worst = lessIsBetter ? std::max(worst, s.*score) : std::min(worst, s.*score);
  }
  return worst;
}

/// The estimator's curvatures of the noise-free ellipsoid (the targets'
/// first row), and with 0.4 spacings of noise (the second), over six draws.
void TestEstimatedEllipsoid(Checks& checks)
{
  const std::vector<LineScore> draws =
    EllipsoidDraws(0.0, "ellipsoid, estimated, noise-free, all kinds");
  checks.True("estimated ellipsoid: 95 % of line points within 1 spacing, every draw",
    WorstOf(draws, &LineScore::WithinOne, false) >= 0.95);
  checks.True("estimated ellipsoid: 95 % of the ellipses covered, mean of the draws",
    MeanOf(draws, &LineScore::Covered) >= 0.95);
  checks.True("estimated ellipsoid: 93.5 % covered, every draw",
    WorstOf(draws, &LineScore::Covered, false) >= 0.935);
  checks.Below("estimated ellipsoid: false length share, every draw",
    WorstOf(draws, &LineScore::FalseShare, true),
    0.02);
}

void TestNoisyEllipsoid(Checks& checks)
{
  const std::vector<LineScore> draws =
    EllipsoidDraws(0.4, "ellipsoid, estimated, 0.4 spacings of noise, all kinds");
  checks.True("noisy ellipsoid: 96 % of line points within 2 spacings, mean of the draws",
    MeanOf(draws, &LineScore::WithinTwo) >= 0.96);
  checks.True("noisy ellipsoid: 93 % within 2 spacings, every draw",
    WorstOf(draws, &LineScore::WithinTwo, false) >= 0.93);
  checks.True("noisy ellipsoid: 65 % of the ellipses covered, mean of the draws",
    MeanOf(draws, &LineScore::Covered) >= 0.65);
  checks.True("noisy ellipsoid: 60 % covered, every draw",
    WorstOf(draws, &LineScore::Covered, false) >= 0.60);
  checks.Below("noisy ellipsoid: false length share, mean of the draws",
    MeanOf(draws, &LineScore::FalseShare),
    0.04);
  checks.Below("noisy ellipsoid: false length share, every draw",
    WorstOf(draws, &LineScore::FalseShare, true),
    0.08);
}

/// The bump's ridge and valleys, exact and estimated (default kinds:
/// ridges and valleys), tagged with their kinds.
void TestBump(Checks& checks)
{
  const std::size_t n = 60000;
  const double spacing = std::sqrt(4.0 * Half * Half / n);
  const auto samples = testing::Sample(Bump(), n, 75);
  std::printf(
    "bump: valleys at x = +-%.6f (sqrt(3) w = %.6f)\n", ValleyPosition(), std::sqrt(3.0) * Width);
  const LineResult exact = Extract(ExactArrays(samples, 4.0 * spacing), RidgesAndValleys);
  const LineScore exactScore = ScoreBump(exact, spacing, 1.0);
  exactScore.Print("bump, exact curvatures");
  checks.True("exact bump: 95 % of line points within 1 spacing", exactScore.WithinOne >= 0.95);
  checks.True("exact bump: 95 % covered", exactScore.Covered >= 0.95);
  int ridges = 0, valleys = 0;
  for (const CurvatureLine& line : exact.Lines)
  {
    const double x = line.Points[0];
    ridges += line.Kind == LineKind::Ridge && std::fabs(x) < spacing;
    valleys +=
      line.Kind == LineKind::Valley && std::fabs(std::fabs(x) - ValleyPosition()) < spacing;
  }
  checks.True(
    "exact bump: a ridge on the crest, valleys on both sides", ridges >= 1 && valleys >= 2);

  const LineScore estimated =
    ScoreBump(Extract(EstimatedArrays(samples), RidgesAndValleys), spacing, 2.0);
  estimated.Print("bump, estimated, noise-free");
  checks.True("estimated bump: 95 % within 2 spacings", estimated.WithinTwo >= 0.95);
  checks.True("estimated bump: 90 % covered", estimated.Covered >= 0.90);
  auto noisy = samples;
  testing::AddPositionNoise(noisy, 0.4 * spacing, 76);
  const LineScore noisyScore =
    ScoreBump(Extract(EstimatedArrays(noisy), RidgesAndValleys), spacing, 2.0);
  noisyScore.Print("bump, estimated, 0.4 spacings of noise");
  checks.True("noisy bump: 95 % within 2 spacings", noisyScore.WithinTwo >= 0.95);
  checks.True("noisy bump: 80 % covered", noisyScore.Covered >= 0.80);
  checks.Below("noisy bump: false length share", noisyScore.FalseShare, 0.05);
}

/// A torus's principal curvatures are constant along their own directions:
/// its extremal lines are degenerate, and none may be drawn; nor on a plane.
void TestNoLines(Checks& checks)
{
  const std::size_t n = 40000;
  const auto torus = testing::Sample(testing::Torus(1.0, 0.35), n, 77);
  const double spacing = std::sqrt(4.0 * testing::Pi * testing::Pi * 0.35 / n);
  const double exact = TotalLength(Extract(ExactArrays(torus, 4.0 * spacing), AllLineKinds));
  const double estimated = TotalLength(Extract(EstimatedArrays(torus), AllLineKinds));
  auto noisyTorus = torus;
  testing::AddPositionNoise(noisyTorus, 0.4 * spacing, 78);
  const double noisy = TotalLength(Extract(EstimatedArrays(noisyTorus), AllLineKinds));
  auto plane = testing::Sample(testing::Plane(1.0), n, 79);
  const double planeSpacing = std::sqrt(4.0 / n);
  testing::AddPositionNoise(plane, 0.4 * planeSpacing, 80);
  const double flat = TotalLength(Extract(EstimatedArrays(plane), AllLineKinds));
  std::printf("no lines: torus exact %.4g, estimated %.4g, noisy %.4g (circumference %.4g); "
              "noisy plane %.4g\n",
    exact,
    estimated,
    noisy,
    2.0 * testing::Pi * 1.35,
    flat);
  checks.Below("torus, exact: line length", exact, 1e-12);
  checks.Below("torus, estimated: line length (a tenth of its outer circle)",
    estimated,
    0.1 * 2.0 * testing::Pi * 1.35);
  checks.Below("torus, noisy: line length (a tenth of its outer circle)",
    noisy,
    0.1 * 2.0 * testing::Pi * 1.35);
  checks.Below("noisy plane: line length (a tenth of its side)", flat, 0.2);
}

constexpr double BoxRounding = 0.2;
const Vec BoxHalf{ { 1.2, 0.9, 0.6 } }; // the flat box the rounded one wraps

/// The length of the lines whose points lie over the interior of a flat
/// face of the rounded box: farther than `margin` from where its rounding
/// begins.
double LengthOverFaces(const LineResult& result, double margin)
{
  double length = 0.0;
  for (const CurvatureLine& line : result.Lines)
  {
    const std::size_t n = line.Points.size() / 3;
    for (std::size_t i = 1; i < n; ++i)
    {
      const double* a = &line.Points[3 * (i - 1)];
      const double* b = &line.Points[3 * i];
      bool overFace = false;
      for (int axis = 0; axis < 3 && !overFace; ++axis)
      {
        overFace = std::fabs(a[axis]) > BoxHalf[axis] && std::fabs(b[axis]) > BoxHalf[axis];
        for (int k = 1; k < 3; ++k)
        {
          const int other = (axis + k) % 3;
          overFace = overFace && std::fabs(a[other]) < BoxHalf[other] - margin &&
            std::fabs(b[other]) < BoxHalf[other] - margin;
        }
      }
      if (overFace)
      {
        length += std::sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
          (b[2] - a[2]) * (b[2] - a[2]));
      }
    }
  }
  return length;
}

/// A rounded box with noise: the crests run along its rounded edges, and no
/// line may cross the interiors of its flat faces, where the curvatures
/// are zero and their derivatives noise. Without the significance tests
/// (Significance, RelativeBend and MinimumLength 0) the same clouds do get
/// lines there: the check can see them.
void TestRoundedBox(Checks& checks)
{
  const int n = 60000;
  const double area =
    8.0 * (BoxHalf[0] * BoxHalf[1] + BoxHalf[1] * BoxHalf[2] + BoxHalf[2] * BoxHalf[0]) +
    2.0 * testing::Pi * BoxRounding * 2.0 * (BoxHalf[0] + BoxHalf[1] + BoxHalf[2]) +
    4.0 * testing::Pi * BoxRounding * BoxRounding;
  const double spacing = std::sqrt(area / n);
  for (const double noise : { 0.1, 0.5 })
  {
    auto samples = testing::SampleRoundedBox(BoxHalf, BoxRounding, n, 81);
    testing::AddPositionNoise(samples, noise * spacing, 82);
    const LineArrays arrays = EstimatedArrays(samples);
    LineSettings settings;
    ThreadRunner threads(2);
    const LineResult result = ExtractCurvatureLines(arrays.Input(), settings, &threads);
    const double margin = 1.5 * result.MedianRadius;
    settings.Kinds = AllLineKinds;
    const LineResult allKinds = ExtractCurvatureLines(arrays.Input(), settings, &threads);
    settings.Significance = 0.0;
    settings.RelativeBend = 0.0;
    settings.MinimumLength = 0.0;
    const LineResult unguarded = ExtractCurvatureLines(arrays.Input(), settings, &threads);
    const double overFaces = LengthOverFaces(result, margin);
    const double allOverFaces = LengthOverFaces(allKinds, margin);
    const double unguardedOverFaces = LengthOverFaces(unguarded, margin);
    std::printf("rounded box, %.1f spacings of noise: %zu lines, length %.3f (the edges' %.3f); "
                "over the faces' interiors %.4f, of all kinds %.4f (without the significance "
                "tests %.3f)\n",
      noise,
      result.Lines.size(),
      TotalLength(result),
      4.0 * 2.0 * (BoxHalf[0] + BoxHalf[1] + BoxHalf[2]),
      overFaces,
      allOverFaces,
      unguardedOverFaces);
    checks.Below(
      "rounded box: ridge and valley length over the faces' interiors", overFaces, 1e-12);
    checks.Below(
      "rounded box: line length of all kinds over the faces' interiors", allOverFaces, 1e-12);
    checks.True("rounded box: the check sees lines over the faces when unguarded",
      unguardedOverFaces > 10.0 * spacing);
    checks.True("rounded box: crests along the edges", TotalLength(result) > 0.0);
  }
}

/// Bad input is a clear error; threads do not change the lines.
void TestInputAndThreads(Checks& checks)
{
  LineInput missing;
  missing.Count = 10;
  bool thrown = false;
  try
  {
    ExtractCurvatureLines(missing, LineSettings{});
  }
  catch (const LineInputError& error)
  {
    thrown = std::strstr(error.what(), "required") != nullptr;
  }
  checks.True("missing arrays: LineInputError", thrown);
  checks.True(
    "no points: no lines", ExtractCurvatureLines(LineInput{}, LineSettings{}).Lines.empty());
  const auto samples = testing::Sample(testing::Ellipsoid(A, B, C), 20000, 81);
  const LineArrays arrays = ExactArrays(samples, 4.0 * EllipsoidSpacing(20000));
  LineSettings settings;
  settings.Kinds = AllLineKinds;
  const LineResult serial = ExtractCurvatureLines(arrays.Input(), settings);
  ThreadRunner threads(3);
  const LineResult threaded = ExtractCurvatureLines(arrays.Input(), settings, &threads);
  bool same = !serial.Lines.empty() && serial.Lines.size() == threaded.Lines.size();
  for (std::size_t i = 0; same && i < serial.Lines.size(); ++i)
  {
    same = serial.Lines[i].Points == threaded.Lines[i].Points &&
      serial.Lines[i].Kind == threaded.Lines[i].Kind;
  }
  checks.True("lines on 3 threads: the serial lines", same);
}

/// Without a typical radius there are no shared fits: every point fits its
/// own, exactly as when no neighborhood is dense enough to share. With one,
/// the same cloud shares fits (the comparison is not empty).
void TestNoTypicalRadius(Checks& checks)
{
  const std::size_t n = 20000;
  const LineArrays arrays =
    ExactArrays(testing::Sample(testing::Ellipsoid(A, B, C), n, 77), 8.0 * EllipsoidSpacing(n));
  LineInput input = arrays.Input();
  const double lower[3] = { -A, -B, -C }, upper[3] = { A, B, C };
  PointGrid grid;
  grid.Build(input.Points, input.Count, GridLattice::Make(lower, upper, input.Count, 0.2));
  LineSettings unshared;
  unshared.SharedFitPoints = std::numeric_limits<int>::max();
  auto same = [&](const PointDerivatives& a, const PointDerivatives& b)
  {
    bool equal = a.Fitted == b.Fitted;
    for (std::size_t i = 0; equal && i < n; ++i)
    {
      equal = a.Maximum[i].Slope == b.Maximum[i].Slope && a.Maximum[i].Bend == b.Maximum[i].Bend &&
        a.Minimum[i].Slope == b.Minimum[i].Slope && a.Minimum[i].Bend == b.Minimum[i].Bend;
    }
    return equal;
  };
  const PointDerivatives own = FitDerivatives(input, unshared, grid, nullptr);
  checks.True("no typical radius: every point fits its own",
    same(FitDerivatives(input, LineSettings{}, grid, nullptr), own));
  input.TypicalRadius = arrays.Radius[0];
  checks.True("a typical radius: dense points share fits",
    !same(FitDerivatives(input, LineSettings{}, grid, nullptr), own));
}

} // namespace

int main(int argc, char* argv[])
{
  return RunNamedTests(argc,
    argv,
    {
      { "ExactEllipsoid", TestExactEllipsoid },
      { "EstimatedEllipsoid", TestEstimatedEllipsoid },
      { "NoisyEllipsoid", TestNoisyEllipsoid },
      { "Bump", TestBump },
      { "NoLines", TestNoLines },
      { "RoundedBox", TestRoundedBox },
      { "InputAndThreads", TestInputAndThreads },
      { "NoTypicalRadius", TestNoTypicalRadius },
    });
}
