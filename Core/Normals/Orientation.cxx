#include "Normals/Orientation.h"

#include "Common/Progress.h"
#include "Common/WorkRunner.h"
#include "Normals/OrderedCloud.h"
#include "Normals/OrientationGraph.h"
#include "Normals/ViewFromAbove.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <mutex>
#include <type_traits>
#include <utility>

namespace pcurv
{
namespace normals
{
namespace
{
using edge::Dot;
using edge::IsZero;

void Flip(double* n)
{
  n[0] = -n[0];
  n[1] = -n[1];
  n[2] = -n[2];
}

/// Points of the tree's frontier with the sign they would get, by their
/// edge's weight bucket: pushing and popping cost O(1), where a binary
/// heap's cost grew with the frontier. Within a bucket the last in is the
/// first out; ties are thereby decided by the grid's order as well.
template<typename Index>
class FrontierBuckets
{
public:
  void Push(int bucket, Index to, signed char sign)
  {
    // The sign in the lowest bit (positions are far below half the range).
    using Unsigned = std::make_unsigned_t<Index>;
    this->Buckets[bucket].push_back(
      static_cast<Unsigned>(2 * static_cast<Unsigned>(to) + (sign < 0)));
    this->Lowest = std::min(this->Lowest, bucket);
    ++this->Size;
  }

  bool Empty() const { return this->Size == 0; }

  std::pair<Index, signed char> Pop()
  {
    while (this->Buckets[this->Lowest].empty())
    {
      ++this->Lowest;
    }
    const auto entry = this->Buckets[this->Lowest].back();
    this->Buckets[this->Lowest].pop_back();
    --this->Size;
    return { static_cast<Index>(entry >> 1), static_cast<signed char>(entry & 1 ? -1 : 1) };
  }

private:
  std::vector<std::make_unsigned_t<Index>> Buckets[edge::Buckets];
  int Lowest = edge::Buckets - 1;
  std::int64_t Size = 0;
};

/// Pushes the edges from `from` (signed) to the points not signed yet.
template<typename Index>
void PushEdges(const Graph<Index>& graph,
  std::int64_t from,
  const std::vector<signed char>& signs,
  FrontierBuckets<Index>& frontier)
{
  for (std::int64_t e = graph.Start[from]; e < graph.Start[from + 1]; ++e)
  {
    const auto& entry = graph.Entries[e];
    if (signs[entry.Target] == 0 && entry.Code != edge::Unused)
    {
      frontier.Push(
        edge::BucketOf(entry.Code), entry.Target, edge::Propagate(entry.Code, signs[from]));
    }
  }
}

/// Grows a minimum spanning tree of the normals' disagreement
/// 1 - |n_a . n_b| (Prim's, weights in buckets) from the frontier: each
/// point reached gets the sign (+1 or -1: the normal as fitted, or
/// flipped) its tree edge carries; returns them in the order reached.
template<typename Index>
std::vector<std::int64_t> GrowTree(const Graph<Index>& graph,
  std::vector<signed char>& signs,
  FrontierBuckets<Index>& frontier,
  StageProgress* progress)
{
  // The traversal is serial and takes a while on millions of points: a
  // stop request is looked at every few thousand points (the normals are
  // then incomplete anyway).
  constexpr std::size_t StopCheckInterval = 4096;
  std::vector<std::int64_t> reached;
  while (!frontier.Empty())
  {
    const auto [to, sign] = frontier.Pop();
    if (signs[to] != 0)
    {
      continue;
    }
    if (progress && reached.size() % StopCheckInterval == 0 && !progress->Reach(1.0))
    {
      return reached;
    }
    signs[to] = sign;
    reached.push_back(to);
    PushEdges(graph, to, signs, frontier);
  }
  return reached;
}

void FlipPart(const std::vector<std::int64_t>& part, std::vector<signed char>& signs)
{
  for (const std::int64_t p : part)
  {
    signs[p] = static_cast<signed char>(-signs[p]);
  }
}

/// The median of `values` (the upper one of an even count; 0 of none);
/// reorders them.
double Median(std::vector<double>& values)
{
  if (values.empty())
  {
    return 0.0;
  }
  const auto middle = values.begin() + values.size() / 2;
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

/// The coordinate-wise median of a part's points: its center, wherever a
/// few strays connected to it lie.
std::array<double, 3> PartCenter(const std::vector<std::int64_t>& part, const OrderedCloud& ordered)
{
  std::array<std::vector<double>, 3> coordinates;
  for (const std::int64_t p : part)
  {
    double x[3];
    ordered.Point(p, x);
    for (int k = 0; k < 3; ++k)
    {
      coordinates[k].push_back(x[k]);
    }
  }
  return { Median(coordinates[0]), Median(coordinates[1]), Median(coordinates[2]) };
}

/// Turns a part's normals outward (see NormalOrientation::Outward), by
/// their signs. A closed surface's normals sum to about zero (the integral
/// of n over a closed surface vanishes), and outward is where they agree
/// with x - c (the integral of n . (x - c) is three times the volume,
/// whatever c); an open part whose normals share a side (a height field, an
/// aerial scan, a bowl) points up, unless its normals are about horizontal,
/// where up says nothing and x - c decides again (a wall, an open cylinder).
/// c is the part's median point and each point's |x - c| counts at most
/// four times the median one, so that a stray connected to the part (a
/// "missing value" sentinel's point, whose normal is arbitrary) cannot
/// outvote the surface.
void TurnPartOutward(const std::vector<std::int64_t>& part,
  const OrderedCloud& ordered,
  const std::vector<double>& normals,
  std::vector<signed char>& signs)
{
  if (part.empty())
  {
    return;
  }
  const std::array<double, 3> center = PartCenter(part, ordered);
  double sum[3] = { 0.0, 0.0, 0.0 };
  std::vector<double> distances;
  distances.reserve(part.size());
  for (const std::int64_t p : part)
  {
    double x[3];
    ordered.Point(p, x);
    const double d[3] = { x[0] - center[0], x[1] - center[1], x[2] - center[2] };
    distances.push_back(std::sqrt(Dot(d, d)));
    for (int k = 0; k < 3; ++k)
    {
      sum[k] += signs[p] * normals[3 * p + k];
    }
  }
  const double longest = 4.0 * Median(distances);
  double signedSum = 0.0;
  for (const std::int64_t p : part)
  {
    double x[3];
    ordered.Point(p, x);
    const double d[3] = { x[0] - center[0], x[1] - center[1], x[2] - center[2] };
    const double length = std::sqrt(Dot(d, d));
    const double weight = length > longest ? longest / length : 1.0;
    signedSum += signs[p] * weight * Dot(&normals[3 * p], d);
  }
  const double count = static_cast<double>(part.size());
  const double meanLength = std::sqrt(Dot(sum, sum)) / count;
  const bool open = meanLength > 0.3 && std::fabs(sum[2]) > 0.3 * std::sqrt(Dot(sum, sum));
  const bool flip = open ? sum[2] < 0.0 : signedSum < 0.0;
  if (flip)
  {
    FlipPart(part, signs);
  }
}

/// Turns a part of a scan seen from above towards the sky. Every normal
/// within 60 degrees of vertical points up on its own, which undoes the
/// tree's wrong turns in vegetation, where the fitted planes disagree from
/// point to point. The steeper ones (walls, the sides of crowns), whose
/// vertical component says little, take their sides from a tree grown
/// anew from all the others at once: the side of the crown's top they
/// bend away from. A part with no such point keeps its tree's signs,
/// turned to the side most vertical components take.
template<typename Index>
void TurnPartUp(const std::vector<std::int64_t>& part,
  const Graph<Index>& graph,
  const std::vector<double>& normals,
  std::vector<signed char>& signs,
  FrontierBuckets<Index>& frontier)
{
  double vote = 0.0;
  std::vector<std::int64_t> steep;
  for (const std::int64_t p : part)
  {
    vote += signs[p] * normals[3 * p + 2];
    if (std::fabs(normals[3 * p + 2]) < SteepBelow)
    {
      steep.push_back(p);
    }
  }
  if (vote < 0.0)
  {
    FlipPart(part, signs);
  }
  if (steep.size() == part.size())
  {
    return;
  }
  for (const std::int64_t p : steep)
  {
    signs[p] = 0;
  }
  for (const std::int64_t p : part)
  {
    if (signs[p] != 0)
    {
      signs[p] = static_cast<signed char>(normals[3 * p + 2] > 0.0 ? 1 : -1);
    }
  }
  for (const std::int64_t p : part)
  {
    if (std::fabs(normals[3 * p + 2]) >= SteepBelow)
    {
      PushEdges(graph, p, signs, frontier);
    }
  }
  GrowTree<Index>(graph, signs, frontier, nullptr);
}

/// Orients a part: in a scan seen from above, up unless the part hides
/// about half of itself from the view, as a closed object does; otherwise
/// outward.
template<typename Index>
void OrientFoundPart(const std::vector<std::int64_t>& part,
  const Graph<Index>& graph,
  const OrderedCloud& ordered,
  const std::vector<double>& normals,
  const std::vector<Sight>& sights,
  std::vector<signed char>& signs,
  FrontierBuckets<Index>& frontier)
{
  // A closed surface shows about half its points; a crown or a roof seen
  // from above shows most of them.
  constexpr double ClosedShare = 0.65;
  if (!sights.empty() && ShareOfTops(sights, &part) > ClosedShare)
  {
    TurnPartUp(part, graph, normals, signs, frontier);
  }
  else
  {
    TurnPartOutward(part, ordered, normals, signs);
  }
}

} // namespace

/// Each normal on the side the settings ask for, point by point.
void OrientPointwise(const NormalSettings& settings,
  const OrderedCloud& ordered,
  std::vector<double>& normals)
{
  for (std::int64_t p = 0; p < ordered.Size(); ++p)
  {
    double x[3];
    ordered.Point(p, x);
    double towards[3];
    for (int k = 0; k < 3; ++k)
    {
      towards[k] = settings.Orientation == NormalOrientation::TowardsViewpoint
        ? settings.Viewpoint[k] - x[k]
        : settings.Axis[k];
    }
    if (Dot(&normals[3 * p], towards) < 0.0)
    {
      Flip(&normals[3 * p]);
    }
  }
}

/// Orients every connected part of the graph (NormalOrientation::Outward);
/// false when the progress monitor asked to stop. The fits' repeated edges
/// are dropped.
template<typename Index>
bool OrientOutward(PlaneFits& fits,
  const OrderedCloud& ordered,
  double radius,
  WorkRunner& runner,
  std::vector<double>& normals,
  NormalSummary& summary,
  StageProgress* progress)
{
  const std::int64_t n = ordered.Size();
  // Columns about half the normals' neighborhood wide hold a few points
  // of any surface above; a slope up to about 45 degrees stays within a
  // neighborhood's radius of its column's top.
  std::vector<Sight> sights = SightsFromAbove(ordered, normals, 0.5 * radius, radius);
  summary.SeenFromAbove = SeenFromAbove(sights);
  if (!summary.SeenFromAbove)
  {
    std::vector<Sight>().swap(sights);
  }
  DropRepeatedEdges(fits, runner);
  const Graph<Index> graph(fits, runner);
  std::vector<signed char> signs(n, 0); // 0: not reached yet
  FrontierBuckets<Index> frontier;
  for (std::int64_t p = 0; p < n; ++p)
  {
    if (signs[p] == 0 && !IsZero(&normals[3 * p]))
    {
      frontier.Push(edge::Bucket(1.0), static_cast<Index>(p), 1);
      OrientFoundPart(GrowTree(graph, signs, frontier, progress),
        graph,
        ordered,
        normals,
        sights,
        signs,
        frontier);
      ++summary.Components;
      if (progress && progress->Stopped())
      {
        return false;
      }
    }
  }
  for (std::int64_t p = 0; p < n; ++p)
  {
    if (signs[p] < 0)
    {
      Flip(&normals[3 * p]);
    }
  }
  return true;
}

// The two widths of positions EstimateNormals uses.
template bool OrientOutward<std::int32_t>(PlaneFits&,
  const OrderedCloud&,
  double,
  WorkRunner&,
  std::vector<double>&,
  NormalSummary&,
  StageProgress*);
template bool OrientOutward<std::int64_t>(PlaneFits&,
  const OrderedCloud&,
  double,
  WorkRunner&,
  std::vector<double>&,
  NormalSummary&,
  StageProgress*);

} // namespace normals
} // namespace pcurv
