#include "Normals/Orientation.h"

#include "Common/Progress.h"
#include "Common/WorkRunner.h"
#include "Normals/OrderedCloud.h"
#include "Normals/OrientationGraph.h"

#include <algorithm>
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

/// Propagates the sign from `seed` over a minimum spanning tree of the
/// normals' disagreement 1 - |n_a . n_b| (Prim's, weights in buckets):
/// signs[p] becomes +1 or -1 (the normal as fitted, or flipped) for the
/// part's points; returns them in the order reached.
template<typename Index>
std::vector<std::int64_t> OrientPart(const Graph<Index>& graph,
  std::int64_t seed,
  std::vector<signed char>& signs,
  FrontierBuckets<Index>& frontier,
  StageProgress* progress)
{
  // The traversal is serial and takes a while on millions of points: a
  // stop request is looked at every few thousand points (the normals are
  // then incomplete anyway).
  constexpr std::size_t StopCheckInterval = 4096;
  std::vector<std::int64_t> part;
  frontier.Push(edge::Bucket(1.0), static_cast<Index>(seed), 1);
  while (!frontier.Empty())
  {
    const auto [to, sign] = frontier.Pop();
    if (signs[to] != 0)
    {
      continue;
    }
    if (progress && part.size() % StopCheckInterval == 0 && !progress->Reach(1.0))
    {
      return part;
    }
    signs[to] = sign;
    part.push_back(to);
    for (std::int64_t e = graph.Start[to]; e < graph.Start[to + 1]; ++e)
    {
      const auto& entry = graph.Entries[e];
      if (signs[entry.Target] == 0 && entry.Code != edge::Unused)
      {
        frontier.Push(edge::BucketOf(entry.Code), entry.Target, edge::Propagate(entry.Code, sign));
      }
    }
  }
  return part;
}

/// Turns a part's normals outward (see NormalOrientation::Outward), by
/// their signs. A closed surface's normals sum to about zero (the integral
/// of n over a closed surface vanishes), and outward is where they agree
/// with x - c; an open part whose normals share a side (a height field, an
/// aerial scan, a bowl) points up, unless its normals are about horizontal,
/// where up says nothing and x - c decides again (a wall, an open cylinder).
void TurnPartOutward(const std::vector<std::int64_t>& part,
  const OrderedCloud& ordered,
  const std::vector<double>& normals,
  std::vector<signed char>& signs)
{
  double centroid[3] = { 0.0, 0.0, 0.0 }, sum[3] = { 0.0, 0.0, 0.0 };
  for (const std::int64_t p : part)
  {
    double x[3];
    ordered.Point(p, x);
    for (int k = 0; k < 3; ++k)
    {
      centroid[k] += x[k];
      sum[k] += signs[p] * normals[3 * p + k];
    }
  }
  const double count = static_cast<double>(part.size());
  for (double& c : centroid)
  {
    c /= count;
  }
  double signedSum = 0.0;
  for (const std::int64_t p : part)
  {
    double x[3];
    ordered.Point(p, x);
    const double d[3] = { x[0] - centroid[0], x[1] - centroid[1], x[2] - centroid[2] };
    signedSum += signs[p] * Dot(&normals[3 * p], d);
  }
  const double meanLength = std::sqrt(Dot(sum, sum)) / count;
  const bool open = meanLength > 0.3 && std::fabs(sum[2]) > 0.3 * std::sqrt(Dot(sum, sum));
  const bool flip = open ? sum[2] < 0.0 : signedSum < 0.0;
  if (flip)
  {
    for (const std::int64_t p : part)
    {
      signs[p] = static_cast<signed char>(-signs[p]);
    }
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
  WorkRunner& runner,
  std::vector<double>& normals,
  NormalSummary& summary,
  StageProgress* progress)
{
  const std::int64_t n = ordered.Size();
  DropRepeatedEdges(fits, runner);
  const Graph<Index> graph(fits, runner);
  std::vector<signed char> signs(n, 0); // 0: not reached yet
  FrontierBuckets<Index> frontier;
  for (std::int64_t p = 0; p < n; ++p)
  {
    if (signs[p] == 0 && !IsZero(&normals[3 * p]))
    {
      TurnPartOutward(OrientPart(graph, p, signs, frontier, progress), ordered, normals, signs);
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
  WorkRunner&,
  std::vector<double>&,
  NormalSummary&,
  StageProgress*);
template bool OrientOutward<std::int64_t>(PlaneFits&,
  const OrderedCloud&,
  WorkRunner&,
  std::vector<double>&,
  NormalSummary&,
  StageProgress*);

} // namespace normals
} // namespace pcurv
