#include "Lines/LineTracing.h"

#include "Neighbors/PointGrid.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pcurv
{
namespace
{
using Vec3 = std::array<double, 3>;

double Dot(const Vec3& a, const Vec3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec3 Minus(const Vec3& a, const Vec3& b)
{
  return { { a[0] - b[0], a[1] - b[1], a[2] - b[2] } };
}
Vec3 Unit(const Vec3& v, const Vec3& fallback)
{
  const double length = std::sqrt(Dot(v, v));
  return length > 0.0 ? Vec3{ { v[0] / length, v[1] / length, v[2] / length } } : fallback;
}

class Tracer
{
public:
  Tracer(const std::vector<LineCrossing>& crossings, double step)
    : Crossings(crossings)
    , Used(crossings.size(), 0)
    , Band(step)
    , Reach(3.0 * step)
  {
    std::vector<double> xyz;
    double lower[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL },
           upper[3] = { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
    for (const LineCrossing& c : crossings)
    {
      for (int k = 0; k < 3; ++k)
      {
        xyz.push_back(c.Position[k]);
        lower[k] = std::min(lower[k], c.Position[k]);
        upper[k] = std::max(upper[k], c.Position[k]);
      }
    }
    const std::int64_t n = static_cast<std::int64_t>(crossings.size());
    this->Grid.Build(xyz.data(), n, GridLattice::Make(lower, upper, n, this->Reach));
  }

  bool IsUsed(std::size_t i) const { return this->Used[i] != 0; }

  TracedLine Trace(std::size_t seed)
  {
    TracedLine line;
    line.Kind = this->Crossings[seed].Kind;
    this->Used[seed] = 1;
    std::vector<Vec3> points{ this->TakeBand(seed) };
    std::vector<double> curvature{ this->BandCurvature };
    const Vec3 tangent = this->Crossings[seed].Tangent;
    line.Closed = this->Walk(seed, tangent, points, curvature, true);
    if (!line.Closed)
    {
      std::vector<Vec3> back{ points.front() };
      std::vector<double> backCurvature{ curvature.front() };
      const Vec3 reverse{ { -tangent[0], -tangent[1], -tangent[2] } };
      this->Walk(seed, reverse, back, backCurvature, false);
      line.Points.assign(back.rbegin(), back.rend() - 1);
      line.Curvature.assign(backCurvature.rbegin(), backCurvature.rend() - 1);
    }
    line.Points.insert(line.Points.end(), points.begin(), points.end());
    line.Curvature.insert(line.Curvature.end(), curvature.begin(), curvature.end());
    if (line.Closed)
    {
      line.Points.push_back(line.Points.front());
      line.Curvature.push_back(line.Curvature.front());
    }
    return line;
  }

private:
  /// Steps from `from` along `direction` while a crossing lies ahead;
  /// returns whether the walk came back to where it started (a loop).
  bool Walk(std::size_t from,
    Vec3 direction,
    std::vector<Vec3>& points,
    std::vector<double>& curvature,
    bool mayClose)
  {
    const Vec3 start = this->Crossings[from].Position;
    Vec3 x = start;
    const LineKind kind = this->Crossings[from].Kind;
    for (;;)
    {
      const std::int64_t next = this->Next(x, direction, kind);
      if (next < 0)
      {
        const Vec3 home = Minus(start, x);
        return mayClose && points.size() > 3 && Dot(home, home) <= this->Reach * this->Reach &&
          Dot(home, direction) > 0.0;
      }
      const LineCrossing& c = this->Crossings[next];
      const Vec3 stepDirection = Unit(Minus(c.Position, x), direction);
      const double sign = Dot(c.Tangent, direction) >= 0.0 ? 1.0 : -1.0;
      direction = Unit(Vec3{ { stepDirection[0] + sign * c.Tangent[0],
                         stepDirection[1] + sign * c.Tangent[1],
                         stepDirection[2] + sign * c.Tangent[2] } },
        stepDirection);
      x = c.Position;
      this->Used[next] = 1;
      points.push_back(this->TakeBand(static_cast<std::size_t>(next)));
      curvature.push_back(this->BandCurvature);
    }
  }

  /// The unused crossing of `kind` ahead of x that continues the line
  /// best: close to the line x + s direction, at a tangent like it.
  std::int64_t Next(const Vec3& x, const Vec3& direction, LineKind kind) const
  {
    std::int64_t best = -1;
    double bestCost = HUGE_VAL;
    this->Grid.ForEachWithinRadius(x.data(),
      this->Reach,
      [&](const double* q, std::int64_t id)
      {
        const LineCrossing& c = this->Crossings[id];
        const Vec3 d{ { q[0] - x[0], q[1] - x[1], q[2] - x[2] } };
        const double distance = std::sqrt(Dot(d, d));
        const double along = Dot(d, direction);
        if (this->Used[id] || c.Kind != kind || !(along > 0.5 * distance) ||
          std::fabs(Dot(c.Tangent, direction)) < 0.5)
        {
          return;
        }
        const double lateral = std::sqrt(std::max(0.0, distance * distance - along * along));
        const double cost = distance + 2.0 * lateral;
        if (cost < bestCost || (cost == bestCost && id < best))
        {
          bestCost = cost;
          best = id;
        }
      });
    return best;
  }

  /// Takes up the unused crossings of i's kind within a band's width of
  /// crossing i; their centroid (and mean curvature, in BandCurvature).
  Vec3 TakeBand(std::size_t i)
  {
    const LineCrossing& center = this->Crossings[i];
    Vec3 sum = center.Position;
    double curvature = center.Curvature;
    int count = 1;
    this->Grid.ForEachWithinRadius(center.Position.data(),
      this->Band,
      [&](const double* q, std::int64_t id)
      {
        if (this->Used[id] || this->Crossings[id].Kind != center.Kind)
        {
          return;
        }
        this->Used[id] = 1;
        for (int k = 0; k < 3; ++k)
        {
          sum[k] += q[k];
        }
        curvature += this->Crossings[id].Curvature;
        ++count;
      });
    this->BandCurvature = curvature / count;
    return { { sum[0] / count, sum[1] / count, sum[2] / count } };
  }

  const std::vector<LineCrossing>& Crossings;
  std::vector<unsigned char> Used;
  PointGrid Grid;
  double Band, Reach;
  double BandCurvature = 0.0;
};

} // namespace

std::vector<TracedLine> TraceLines(const std::vector<LineCrossing>& crossings, double step)
{
  std::vector<TracedLine> lines;
  if (crossings.empty() || !(step > 0.0))
  {
    return lines;
  }
  // Strongest curvature first: a line starts where it is surest.
  std::vector<std::size_t> order(crossings.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(),
    order.end(),
    [&](std::size_t a, std::size_t b)
    { return std::fabs(crossings[a].Curvature) > std::fabs(crossings[b].Curvature); });
  Tracer tracer(crossings, step);
  for (std::size_t seed : order)
  {
    if (!tracer.IsUsed(seed))
    {
      lines.push_back(tracer.Trace(seed));
    }
  }
  return lines;
}

} // namespace pcurv
