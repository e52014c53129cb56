/**
 * @file OrientationGraph.h
 * @brief The graph along which the estimated normals' signs are propagated
 * (NormalEstimation.h): each point's plane-fit normal and nearest
 * neighbors, and from them adjacency lists in a fixed order, each entry
 * with its edge's weight bucket and sign relation. No VTK.
 */
#ifndef OrientationGraph_h
#define OrientationGraph_h

#include "Common/IndexList.h"
#include "Common/WorkRunner.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace pcurv
{

/// What the per-point pass leaves for the orientation: in grid order, the
/// normal (arbitrary sign) and the nearest neighbors' grid positions.
struct PlaneFits
{
  std::vector<double> Normals; // 3 per grid position
  IndexList Neighbors;         // GraphNeighbors per position, -1 padded
  int GraphNeighbors = 0;
};

/// Drops the graph edges a -> b the orientation can do without (their
/// neighbor entry becomes -1): those whose reverse b -> a is an edge too
/// and comes later in a's adjacency list (b > a). The traversal pushes
/// both with the same weight and sign, the later one is popped first (last
/// in, first out within a bucket), and the earlier one then always finds b
/// reached: dropping it changes nothing but the work. The entries are
/// marked first and dropped after, so that every search reads the lists as
/// they were; the marks are freed before the graph is built (its peak).
void DropRepeatedEdges(PlaneFits& fits, WorkRunner& runner);

/// What the traversal needs of an edge a -> b, worked out (in parallel)
/// with the graph: the bucket of its weight sqrt(1 - |n_a . n_b|) (about
/// the angle between the normals), and how b's sign follows a's (the sign
/// of n_a . n_b; zero: b keeps its own), in one code; the traversal then
/// reads no normal. Edges to a point without a normal are never followed.
namespace edge
{
/// Normals' helpers (NormalEstimation.cxx uses them too).
inline double Dot(const double* a, const double* b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline bool IsZero(const double* n)
{
  return n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0;
}

constexpr int Buckets = 1024;
constexpr std::int16_t Unused = -1;
enum Relation : std::int16_t
{
  Unrelated = 0,
  Same = 1,
  Opposite = 2
};

/// The bucket of an edge's weight, from the agreement |n_a . n_b|.
inline int Bucket(double agreement)
{
  const double weight = std::sqrt(std::max(0.0, 1.0 - agreement));
  return std::min(Buckets - 1, static_cast<int>(weight * Buckets));
}

/// The code of the edge from a point of normal a to one of normal b. The
/// sign of n_b flips exactly with that of n_a: the agreement, and the
/// relation, do not depend on the signs chosen so far.
inline std::int16_t Code(const double* a, const double* b)
{
  if (IsZero(b))
  {
    return Unused;
  }
  const double dot = Dot(a, b);
  const std::int16_t relation = dot > 0.0 ? Same : dot < 0.0 ? Opposite : Unrelated;
  return static_cast<std::int16_t>(Bucket(std::fabs(dot)) * 4 + relation);
}

inline int BucketOf(std::int16_t code)
{
  return code >> 2;
}

/// The sign of b given the sign of a.
inline signed char Propagate(std::int16_t code, signed char sign)
{
  const int relation = code & 3;
  return relation == Same ? sign : relation == Opposite ? static_cast<signed char>(-sign) : 1;
}
} // namespace edge

/// The edges of the orientation graph, both directions, as adjacency lists
/// in the order of the edges a -> b by a, then by b's rank among a's
/// nearest (the order the traversal's ties follow), each entry with its
/// edge's code. Built in parallel: the sources are cut into blocks, each
/// block counts, then writes, its entries at offsets that the blocks
/// before it leave free. Targets of type Index: 32 bits where they fit
/// halve the memory the traversal reads.
template<typename Index>
struct Graph
{
  // Packed: six bytes an entry with 32-bit targets (eight when aligned),
  // the largest part of the orientation's memory.
#pragma pack(push, 2)
  struct Entry
  {
    Index Target;
    std::int16_t Code;
  };
#pragma pack(pop)
  std::vector<std::int64_t> Start; // per position, its first entry; one extra
  std::vector<Entry> Entries;

  /// From fits whose repeated edges are dropped (DropRepeatedEdges).
  Graph(const PlaneFits& fits, WorkRunner& runner)
  {
    // A point has its own edges and those of the points it is nearest to:
    // far fewer than 256 entries, but for a hub of many neighborhoods,
    // which makes the build start again with wider counts.
    if (!this->Build<std::uint8_t>(fits, runner))
    {
      this->Build<std::int32_t>(fits, runner);
    }
  }

private:
  /// Builds the lists with per-block counts of type Count; false (the
  /// lists unusable) when some point has Count's largest value of entries
  /// or more.
  template<typename Count>
  bool Build(const PlaneFits& fits, WorkRunner& runner)
  {
    const std::int64_t n = static_cast<std::int64_t>(fits.Normals.size() / 3);
    constexpr std::int64_t Blocks = 4;
    constexpr Count Largest = std::numeric_limits<Count>::max();
    // Per block, per position: the entries the block gives it, then where
    // the block writes the next one (from the position's first entry).
    std::vector<std::vector<Count>> placed(Blocks);
    auto forEachEdge = [&](std::int64_t block, auto&& visit)
    {
      const int k = fits.GraphNeighbors;
      fits.Neighbors.Visit(
        [&](const auto* ids)
        {
          for (std::int64_t a = block * n / Blocks; a < (block + 1) * n / Blocks; ++a)
          {
            for (int e = 0; e < k; ++e)
            {
              const std::int64_t b = ids[a * k + e];
              if (b >= 0)
              {
                visit(a, b);
                visit(b, a);
              }
            }
          }
        });
    };
    runner.For(Blocks,
      1,
      [&](std::int64_t begin, std::int64_t end)
      {
        for (std::int64_t block = begin; block < end; ++block)
        {
          placed[block].assign(n, 0);
          forEachEdge(block,
            [&](std::int64_t a, std::int64_t)
            {
              Count& count = placed[block][a];
              count = static_cast<Count>(count + (count < Largest)); // saturating
            });
        }
      });
    this->Start.assign(n + 1, 0);
    for (std::int64_t a = 0; a < n; ++a)
    {
      std::int64_t entries = 0;
      for (std::vector<Count>& counts : placed)
      {
        const Count count = counts[a];
        counts[a] = static_cast<Count>(entries);
        entries += count;
      }
      // Also reached when a block's count saturated: the offsets of the
      // writes might not fit.
      if (entries >= Largest)
      {
        return false;
      }
      this->Start[a + 1] = this->Start[a] + entries;
    }
    this->Entries.resize(static_cast<std::size_t>(this->Start[n]));
    runner.For(Blocks,
      1,
      [&](std::int64_t begin, std::int64_t end)
      {
        for (std::int64_t block = begin; block < end; ++block)
        {
          forEachEdge(block,
            [&](std::int64_t a, std::int64_t b)
            {
              const std::int64_t entry = this->Start[a] + placed[block][a]++;
              this->Entries[entry] = { static_cast<Index>(b),
                edge::Code(&fits.Normals[3 * a], &fits.Normals[3 * b]) };
            });
        }
      });
    return true;
  }
};

} // namespace pcurv

#endif
