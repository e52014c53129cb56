#include "NormalEstimation.h"

#include "CloudEstimation.h"
#include "PointGrid.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <utility>

namespace pcurv
{
namespace
{
double Dot(const double* a, const double* b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

void Flip(double* n)
{
  n[0] = -n[0];
  n[1] = -n[1];
  n[2] = -n[2];
}

/// What the per-point pass leaves for the orientation: in grid order, the
/// normal (arbitrary sign) and the nearest neighbours' grid positions.
struct PlaneFits
{
  std::vector<double> Normals;            // 3 per grid position
  std::vector<std::int64_t> Neighbors;    // GraphNeighbors per position, -1 padded
  std::vector<std::int64_t> PositionOfId; // point id -> grid position
  int GraphNeighbors = 0;
};

/// The normal of the plane through the neighbours (offsets from the point,
/// in units of the radius) by PCA: the eigenvector of the smallest
/// eigenvalue of their covariance; signed so that its largest component is
/// positive (any fixed rule: the orientation decides the sign later).
void FitPlane(const NeighborOffsets& offsets, double inverseRadius, double* normal)
{
  const std::size_t count = offsets.Count;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < count; ++i)
  {
    mean += Eigen::Vector3d(offsets.Dx[i], offsets.Dy[i], offsets.Dz[i]) * inverseRadius;
  }
  mean /= static_cast<double>(count);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < count; ++i)
  {
    const Eigen::Vector3d d =
      Eigen::Vector3d(offsets.Dx[i], offsets.Dy[i], offsets.Dz[i]) * inverseRadius - mean;
    covariance += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(covariance);
  Eigen::Vector3d n = solver.eigenvectors().col(0);
  int largest = 0;
  for (int k = 1; k < 3; ++k)
  {
    largest = std::fabs(n[k]) > std::fabs(n[largest]) ? k : largest;
  }
  if (n[largest] < 0.0)
  {
    n = -n;
  }
  n.normalize();
  for (int k = 0; k < 3; ++k)
  {
    normal[k] = std::isfinite(n[k]) ? n[k] : 0.0;
  }
}

/// One point's plane and graph neighbours (`scratch` holds its buffers):
/// the k nearest found once, their offsets, distances and grid positions
/// gathered in one pass.
void FitPoint(const PointGrid& grid,
  const CloudPoints& cloud,
  const NormalSettings& settings,
  std::int64_t position,
  EstimationScratch& scratch,
  PlaneFits& fits)
{
  const double* x = &cloud.Coordinates[3 * grid.GetSortedId(position)];
  double* normal = &fits.Normals[3 * position];
  // k + 1: the point itself is among those found.
  const double squared =
    grid.SquaredDistanceToKth(x, settings.NumberOfNeighbors + 1, scratch.Distances);
  const double radius = std::nextafter(std::sqrt(squared), HUGE_VAL);
  NeighborOffsets& offsets = scratch.Neighbors;
  std::vector<std::pair<double, std::int64_t>>& nearest = scratch.Ranked;
  nearest.clear();
  offsets.Count = 0;
  grid.ForEachWithinRadius(x,
    radius,
    [&](const double* q, std::int64_t id)
    {
      const double d[3] = { q[0] - x[0], q[1] - x[1], q[2] - x[2] };
      if (offsets.Dx.size() <= offsets.Count)
      {
        offsets.Dx.resize(2 * offsets.Count + 64);
        offsets.Dy.resize(2 * offsets.Count + 64);
        offsets.Dz.resize(2 * offsets.Count + 64);
      }
      offsets.Dx[offsets.Count] = d[0];
      offsets.Dy[offsets.Count] = d[1];
      offsets.Dz[offsets.Count] = d[2];
      ++offsets.Count;
      const std::int64_t other = fits.PositionOfId[id];
      if (other != position)
      {
        nearest.emplace_back(Dot(d, d), other);
      }
    });
  if (offsets.Count < 3 || !(radius > 0.0) || !std::isfinite(radius))
  {
    normal[0] = normal[1] = normal[2] = 0.0;
    return;
  }
  FitPlane(offsets, 1.0 / radius, normal);

  // The graph's edges: the nearest others, by distance, then grid position.
  const std::size_t kept = std::min<std::size_t>(nearest.size(), fits.GraphNeighbors);
  std::partial_sort(nearest.begin(), nearest.begin() + kept, nearest.end());
  std::int64_t* edges = &fits.Neighbors[position * fits.GraphNeighbors];
  for (int e = 0; e < fits.GraphNeighbors; ++e)
  {
    edges[e] = e < static_cast<int>(kept) ? nearest[e].second : -1;
  }
}

/// The edges of the orientation graph, both directions, as adjacency lists.
struct Graph
{
  std::vector<std::int64_t> Start, Targets;

  explicit Graph(const PlaneFits& fits)
  {
    const std::int64_t n = static_cast<std::int64_t>(fits.PositionOfId.size());
    std::vector<std::int64_t> degree(n + 1, 0);
    auto forEachEdge = [&](auto&& visit)
    {
      for (std::int64_t a = 0; a < n; ++a)
      {
        for (int e = 0; e < fits.GraphNeighbors; ++e)
        {
          const std::int64_t b = fits.Neighbors[a * fits.GraphNeighbors + e];
          if (b >= 0)
          {
            visit(a, b);
            visit(b, a);
          }
        }
      }
    };
    forEachEdge([&](std::int64_t a, std::int64_t) { ++degree[a + 1]; });
    for (std::int64_t a = 0; a < n; ++a)
    {
      degree[a + 1] += degree[a];
    }
    this->Start = degree;
    this->Targets.resize(degree[n]);
    forEachEdge([&](std::int64_t a, std::int64_t b) { this->Targets[degree[a]++] = b; });
  }
};

/// Edges of the tree's frontier by weight, in buckets of sqrt(1 - |n_a . n_b|)
/// (about the angle between the normals): pushing and popping cost O(1), where
/// a binary heap's cost grew with the frontier. Within a bucket the last in
/// is the first out; ties are thereby decided by the grid's order as well.
class FrontierBuckets
{
public:
  static constexpr int Count = 1024;

  void Push(double agreement, std::int64_t to, std::int64_t from)
  {
    const double weight = std::sqrt(std::max(0.0, 1.0 - agreement));
    const int bucket = std::min(Count - 1, static_cast<int>(weight * Count));
    this->Buckets[bucket].emplace_back(to, from);
    this->Lowest = std::min(this->Lowest, bucket);
    ++this->Size;
  }

  bool Empty() const { return this->Size == 0; }

  std::pair<std::int64_t, std::int64_t> Pop()
  {
    while (this->Buckets[this->Lowest].empty())
    {
      ++this->Lowest;
    }
    const auto edge = this->Buckets[this->Lowest].back();
    this->Buckets[this->Lowest].pop_back();
    --this->Size;
    return edge;
  }

private:
  std::vector<std::pair<std::int64_t, std::int64_t>> Buckets[Count];
  int Lowest = Count - 1;
  std::int64_t Size = 0;
};

/// Propagates the sign from `seed` over a minimum spanning tree of the
/// normals' disagreement 1 - |n_a . n_b| (Prim's, weights in buckets);
/// returns the part's positions in the order reached.
std::vector<std::int64_t> OrientPart(const Graph& graph,
  std::int64_t seed,
  std::vector<double>& normals,
  std::vector<unsigned char>& reached,
  FrontierBuckets& frontier,
  StageProgress* progress)
{
  // The traversal is serial and takes seconds on millions of points: a stop
  // request is looked at every few thousand points (the normals are then
  // incomplete anyway).
  constexpr std::size_t StopCheckInterval = 4096;
  std::vector<std::int64_t> part;
  frontier.Push(1.0, seed, seed);
  while (!frontier.Empty())
  {
    const auto [to, from] = frontier.Pop();
    if (reached[to])
    {
      continue;
    }
    if (progress && part.size() % StopCheckInterval == 0 && !progress->Reach(1.0))
    {
      return part;
    }
    reached[to] = 1;
    part.push_back(to);
    double* n = &normals[3 * to];
    if (Dot(n, &normals[3 * from]) < 0.0)
    {
      Flip(n);
    }
    for (std::int64_t e = graph.Start[to]; e < graph.Start[to + 1]; ++e)
    {
      const std::int64_t next = graph.Targets[e];
      const double* m = &normals[3 * next];
      if (!reached[next] && (m[0] != 0.0 || m[1] != 0.0 || m[2] != 0.0))
      {
        frontier.Push(std::fabs(Dot(n, m)), next, to);
      }
    }
  }
  return part;
}

/// Turns a part's normals outward (see NormalOrientation::Outward). A
/// closed surface's normals sum to about zero (the integral of n over a
/// closed surface vanishes), and outward is where they agree with x - c;
/// an open part whose normals share a side (a height field, an aerial scan,
/// a bowl) points up, unless its normals are about horizontal, where up
/// says nothing and x - c decides again (a wall, an open cylinder).
void TurnPartOutward(const std::vector<std::int64_t>& part,
  const PointGrid& grid,
  const CloudPoints& cloud,
  std::vector<double>& normals)
{
  double centroid[3] = { 0.0, 0.0, 0.0 }, sum[3] = { 0.0, 0.0, 0.0 };
  for (const std::int64_t p : part)
  {
    for (int k = 0; k < 3; ++k)
    {
      centroid[k] += cloud.Coordinates[3 * grid.GetSortedId(p) + k];
      sum[k] += normals[3 * p + k];
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
    const double* x = &cloud.Coordinates[3 * grid.GetSortedId(p)];
    const double d[3] = { x[0] - centroid[0], x[1] - centroid[1], x[2] - centroid[2] };
    signedSum += Dot(&normals[3 * p], d);
  }
  const double meanLength = std::sqrt(Dot(sum, sum)) / count;
  const bool open = meanLength > 0.3 && std::fabs(sum[2]) > 0.3 * std::sqrt(Dot(sum, sum));
  const bool flip = open ? sum[2] < 0.0 : signedSum < 0.0;
  if (flip)
  {
    for (const std::int64_t p : part)
    {
      Flip(&normals[3 * p]);
    }
  }
}

/// Each normal on the side the settings ask for, point by point.
void OrientPointwise(const NormalSettings& settings,
  const PointGrid& grid,
  const CloudPoints& cloud,
  std::vector<double>& normals)
{
  for (std::int64_t p = 0; p < grid.GetNumberOfPoints(); ++p)
  {
    const double* x = &cloud.Coordinates[3 * grid.GetSortedId(p)];
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
} // namespace

NormalSummary EstimateNormals(const CloudPoints& cloud,
  const NormalSettings& settings,
  WorkRunner& runner,
  std::vector<double>& normals,
  StageProgress* progress)
{
  NormalSummary summary;
  const std::int64_t n = cloud.NumberOfOwnPoints;
  normals.assign(3 * n, 0.0);
  if (n == 0)
  {
    return summary;
  }
  const Collectives alone;
  const CloudBoxes boxes = MeasureBoxes(cloud, alone);
  const NormalSettings usable = [&]()
  {
    NormalSettings s = settings;
    s.NumberOfNeighbors = std::max(3, s.NumberOfNeighbors);
    s.GraphNeighbors = std::max(1, s.GraphNeighbors);
    return s;
  }();
  const double radius = TypicalRadius(cloud, alone, boxes, usable.NumberOfNeighbors);
  // A stop request is looked at between the serial steps too (each up to a
  // second on a million points); nothing is reported yet.
  if (progress && !progress->Reach(0.0))
  {
    return summary;
  }
  PointGrid grid;
  grid.Build(cloud.Coordinates.data(), n, GlobalLattice(boxes, radius));
  if (progress && !progress->Reach(0.0))
  {
    return summary;
  }

  PlaneFits fits;
  fits.GraphNeighbors = usable.GraphNeighbors;
  fits.Normals.assign(3 * n, 0.0);
  fits.Neighbors.assign(n * usable.GraphNeighbors, -1);
  fits.PositionOfId.resize(n);
  for (std::int64_t p = 0; p < n; ++p)
  {
    fits.PositionOfId[grid.GetSortedId(p)] = p;
  }
  runner.For(n,
    1024,
    [&](std::int64_t begin, std::int64_t end, EstimationScratch& scratch)
    {
      if (progress && progress->Stopped())
      {
        return;
      }
      for (std::int64_t p = begin; p < end; ++p)
      {
        FitPoint(grid, cloud, usable, p, scratch, fits);
      }
      if (progress)
      {
        progress->Advance(end - begin);
      }
    });
  if (progress && progress->Stopped())
  {
    return summary;
  }

  if (usable.Orientation == NormalOrientation::Outward)
  {
    const Graph graph(fits);
    std::vector<unsigned char> reached(n, 0);
    FrontierBuckets frontier;
    for (std::int64_t p = 0; p < n; ++p)
    {
      const double* normal = &fits.Normals[3 * p];
      if (!reached[p] && (normal[0] != 0.0 || normal[1] != 0.0 || normal[2] != 0.0))
      {
        TurnPartOutward(OrientPart(graph, p, fits.Normals, reached, frontier, progress),
          grid,
          cloud,
          fits.Normals);
        ++summary.Components;
        if (progress && progress->Stopped())
        {
          return summary;
        }
      }
    }
  }
  else
  {
    OrientPointwise(usable, grid, cloud, fits.Normals);
  }
  for (std::int64_t p = 0; p < n; ++p)
  {
    const double* normal = &fits.Normals[3 * p];
    summary.Undetermined += normal[0] == 0.0 && normal[1] == 0.0 && normal[2] == 0.0;
    std::copy_n(normal, 3, &normals[3 * grid.GetSortedId(p)]);
  }
  return summary;
}

} // namespace pcurv
