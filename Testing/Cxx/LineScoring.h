/**
 * @file LineScoring.h
 * @brief Scores of extracted curvature lines against true lines sampled
 * densely: distances of the line points (in spacings), the share of the
 * true lines' length covered and the length of false lines. No VTK.
 */
#ifndef LineScoring_h
#define LineScoring_h

#include "AnalyticSurfaces.h"
#include "Lines/CurvatureLines.h"
#include "Neighbors/PointGrid.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

namespace linetest
{
using pcurv::testing::Vec;

/// A true line as points a small fraction of a spacing apart.
using TruePolyline = std::vector<Vec>;

struct LineScore
{
  double Median = 0.0, P95 = 0.0;          ///< distance of line points, in spacings
  double WithinOne = 0.0, WithinTwo = 0.0; ///< shares of line points
  double Covered = 0.0;                    ///< share of the true length within CoverTolerance
  double FalseShare = 0.0;                 ///< share of the output length beyond FalseTolerance
  double Length = 0.0, TrueLength = 0.0;
  int Lines = 0;

  void Print(const char* what) const
  {
    std::printf("%s: %d lines, length %.4g (true %.4g); distance median %.3f, 95th %.3f "
                "spacings; within 1: %.1f %%, within 2: %.1f %%; covered %.1f %%; false %.2f %%\n",
      what,
      this->Lines,
      this->Length,
      this->TrueLength,
      this->Median,
      this->P95,
      100.0 * this->WithinOne,
      100.0 * this->WithinTwo,
      100.0 * this->Covered,
      100.0 * this->FalseShare);
  }
};

/// Nearest-point distances to a dense point set.
class DenseSet
{
public:
  DenseSet(const std::vector<Vec>& points, double reach)
    : Reach(reach)
  {
    double lower[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL },
           upper[3] = { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
    for (const Vec& p : points)
    {
      this->Xyz.insert(this->Xyz.end(), p.begin(), p.end());
      for (int k = 0; k < 3; ++k)
      {
        lower[k] = std::min(lower[k], p[k]);
        upper[k] = std::max(upper[k], p[k]);
      }
    }
    const std::int64_t n = static_cast<std::int64_t>(points.size());
    if (n > 0)
    {
      this->Grid.Build(this->Xyz.data(), n, pcurv::GridLattice::Make(lower, upper, n, reach));
    }
  }

  /// Distance to the nearest point, capped at the reach.
  double Distance(const Vec& x) const
  {
    double best = this->Reach * this->Reach;
    this->Grid.ForEachWithinRadius(x.data(),
      this->Reach,
      [&](const double* q, std::int64_t)
      {
        const double d = (q[0] - x[0]) * (q[0] - x[0]) + (q[1] - x[1]) * (q[1] - x[1]) +
          (q[2] - x[2]) * (q[2] - x[2]);
        best = std::min(best, d);
      });
    return std::sqrt(best);
  }

private:
  double Reach;
  std::vector<double> Xyz;
  pcurv::PointGrid Grid;
};

/// The output lines' points, and their segments split to `step`.
inline std::vector<Vec> Densify(const pcurv::LineResult& result, double step)
{
  std::vector<Vec> dense;
  for (const pcurv::CurvatureLine& line : result.Lines)
  {
    const std::size_t n = line.Points.size() / 3;
    for (std::size_t i = 0; i + 1 < n; ++i)
    {
      const Vec a{ { line.Points[3 * i], line.Points[3 * i + 1], line.Points[3 * i + 2] } };
      const Vec b{ { line.Points[3 * i + 3], line.Points[3 * i + 4], line.Points[3 * i + 5] } };
      const double length =
        std::sqrt(pcurv::testing::Dot(pcurv::testing::Add(b, pcurv::testing::Scale(-1.0, a)),
          pcurv::testing::Add(b, pcurv::testing::Scale(-1.0, a))));
      const int pieces = std::max(1, static_cast<int>(std::ceil(length / step)));
      for (int k = 0; k <= pieces; ++k)
      {
        const double t = static_cast<double>(k) / pieces;
        dense.push_back(
          pcurv::testing::Add(pcurv::testing::Scale(1.0 - t, a), pcurv::testing::Scale(t, b)));
      }
    }
  }
  return dense;
}

/// Scores `result` against `truth`; `inside` selects the region scored
/// (a patch's interior), lengths in units of `spacing`.
inline LineScore Score(const pcurv::LineResult& result,
  const std::vector<TruePolyline>& truth,
  double spacing,
  double coverTolerance,
  double falseTolerance,
  const std::function<bool(const Vec&)>& inside)
{
  LineScore score;
  std::vector<Vec> truePoints;
  for (const TruePolyline& line : truth)
  {
    truePoints.insert(truePoints.end(), line.begin(), line.end());
  }
  const double reach = 10.0 * spacing;
  const DenseSet trueSet(truePoints, reach);
  std::vector<double> distances;
  for (const pcurv::CurvatureLine& line : result.Lines)
  {
    const std::size_t n = line.Points.size() / 3;
    for (std::size_t i = 0; i < n; ++i)
    {
      const Vec a{ { line.Points[3 * i], line.Points[3 * i + 1], line.Points[3 * i + 2] } };
      if (inside(a))
      {
        distances.push_back(trueSet.Distance(a) / spacing);
      }
      if (i + 1 < n)
      {
        const Vec b{ { line.Points[3 * i + 3], line.Points[3 * i + 4], line.Points[3 * i + 5] } };
        const Vec d = pcurv::testing::Add(b, pcurv::testing::Scale(-1.0, a));
        const double length = std::sqrt(pcurv::testing::Dot(d, d));
        const Vec middle = pcurv::testing::Add(a, pcurv::testing::Scale(0.5, d));
        if (inside(middle))
        {
          score.Length += length;
          score.FalseShare += trueSet.Distance(middle) > falseTolerance * spacing ? length : 0.0;
        }
      }
    }
  }
  score.Lines = static_cast<int>(result.Lines.size());
  score.FalseShare = score.Length > 0.0 ? score.FalseShare / score.Length : 0.0;
  if (!distances.empty())
  {
    std::sort(distances.begin(), distances.end());
    score.Median = distances[distances.size() / 2];
    score.P95 = distances[static_cast<std::size_t>(0.95 * (distances.size() - 1))];
    score.WithinOne =
      static_cast<double>(
        std::upper_bound(distances.begin(), distances.end(), 1.0) - distances.begin()) /
      distances.size();
    score.WithinTwo =
      static_cast<double>(
        std::upper_bound(distances.begin(), distances.end(), 2.0) - distances.begin()) /
      distances.size();
  }
  const DenseSet found(Densify(result, 0.25 * spacing), reach);
  double covered = 0.0;
  for (const TruePolyline& line : truth)
  {
    for (std::size_t i = 0; i + 1 < line.size(); ++i)
    {
      const Vec d = pcurv::testing::Add(line[i + 1], pcurv::testing::Scale(-1.0, line[i]));
      const double length = std::sqrt(pcurv::testing::Dot(d, d));
      if (inside(line[i]))
      {
        score.TrueLength += length;
        covered += found.Distance(line[i]) <= coverTolerance * spacing ? length : 0.0;
      }
    }
  }
  score.Covered = score.TrueLength > 0.0 ? covered / score.TrueLength : 0.0;
  return score;
}

} // namespace linetest

#endif
