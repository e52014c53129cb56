// The neighbor grid (no VTK): exact queries in cells thousands of times
// denser than the rest, and the same grid on any threads.
#include "CloudTestSupport.h"

namespace
{
using namespace pcurv;
using namespace cloudtest;

/// A grid over a sparse cloud with a patch thousands of times denser: the
/// fine query finds exactly the points within the radius (as the plain one
/// and brute force do), a shell gathers the same points from an inner radius
/// on, and the k-th nearest distances equal brute force.
void TestDenseCells(Checks& checks)
{
  std::vector<double> xyz;
  std::uint64_t state = 12345;
  auto uniform = [&state]()
  {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) / 9007199254740992.0;
  };
  for (int i = 0; i < 5000; ++i) // sparse: a 4 x 4 square
  {
    xyz.insert(xyz.end(), { 4.0 * uniform(), 4.0 * uniform(), 0.01 * uniform() });
  }
  for (int i = 0; i < 20000; ++i) // dense: 0.02 x 0.02 at (1, 1)
  {
    xyz.insert(xyz.end(), { 1.0 + 0.02 * uniform(), 1.0 + 0.02 * uniform(), 0.01 * uniform() });
  }
  const std::int64_t n = static_cast<std::int64_t>(xyz.size() / 3);
  const double lower[3] = { 0.0, 0.0, 0.0 }, upper[3] = { 4.0, 4.0, 0.01 };
  const GridLattice lattice = GridLattice::Make(lower, upper, n, 0.2);
  PointGrid grid;
  grid.Build(xyz.data(), n, lattice);
  // Built on three threads in ranges of 7 points or cells, and in ranges
  // taken last to first: the same order, the same shells.
  ThreadRunner threads(3);
  PointGrid threaded, backwards;
  threaded.Build(xyz.data(), n, lattice, &threads, 7);
  BackwardsRunner last_to_first;
  backwards.Build(xyz.data(), n, lattice, &last_to_first, 5);
  bool sameOrder = true;
  for (const PointGrid* other : { &threaded, &backwards })
  {
    sameOrder = sameOrder && other->GetNumberOfPoints() == n &&
      std::equal(grid.GetSortedIds(), grid.GetSortedIds() + n, other->GetSortedIds());
    ShellPoints mine, theirs;
    for (int query = 0; query < 50; ++query)
    {
      const double* x = &xyz[3 * ((query * 104729) % n)];
      grid.GatherShell(x, 0.01, 0.2, mine);
      other->GatherShell(x, 0.01, 0.2, theirs);
      sameOrder = sameOrder && mine.Count == theirs.Count &&
        std::equal(mine.Ids.begin(), mine.Ids.begin() + mine.Count, theirs.Ids.begin()) &&
        std::equal(mine.Dx.begin(), mine.Dx.begin() + mine.Count, theirs.Dx.begin());
    }
  }
  checks.True("grid built in parallel ranges: the serial build's order and shells", sameOrder);
  int wrongSets = 0, wrongKth = 0, wrongShells = 0, wrongNearest = 0, wrongRanks = 0;
  std::vector<double> scratch;
  ShellPoints shell, nearest;
  RankScratch ranked;
  for (int query = 0; query < 300; ++query)
  {
    const double* x = &xyz[3 * ((query * 7919) % n)];
    const double radius = query % 3 == 0 ? 0.002 : (query % 3 == 1 ? 0.05 : 0.3);
    std::vector<std::int64_t> fine, plain, brute;
    grid.ForEachWithinRadiusFine(
      x, radius, [&](const double*, std::int64_t id) { fine.push_back(id); });
    grid.ForEachWithinRadius(
      x, radius, [&](const double*, std::int64_t id) { plain.push_back(id); });
    std::vector<double> distances;
    for (std::int64_t i = 0; i < n; ++i)
    {
      const double dx = xyz[3 * i] - x[0], dy = xyz[3 * i + 1] - x[1], dz = xyz[3 * i + 2] - x[2];
      const double squared = dx * dx + dy * dy + dz * dz;
      distances.push_back(squared);
      if (squared < radius * radius)
      {
        brute.push_back(i);
      }
    }
    // A shell: the fine query's points from an inner radius on, in its
    // order, with their offsets.
    const double inner = (query % 4) * 0.3 * radius;
    std::vector<std::int64_t> expectedShell;
    std::vector<double> expectedOffsets;
    grid.ForEachWithinRadiusFine(x,
      radius,
      [&](const double* q, std::int64_t id)
      {
        const double d[3] = { q[0] - x[0], q[1] - x[1], q[2] - x[2] };
        if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] >= inner * inner)
        {
          expectedShell.push_back(id);
          expectedOffsets.insert(expectedOffsets.end(), d, d + 3);
        }
      });
    grid.GatherShell(x, inner, radius, shell);
    bool shellRight = shell.Count == expectedShell.size();
    for (std::size_t i = 0; shellRight && i < shell.Count; ++i)
    {
      shellRight = shell.Ids[i] == expectedShell[i] && shell.Dx[i] == expectedOffsets[3 * i] &&
        shell.Dy[i] == expectedOffsets[3 * i + 1] && shell.Dz[i] == expectedOffsets[3 * i + 2];
    }
    wrongShells += !shellRight;
    std::sort(fine.begin(), fine.end());
    std::sort(plain.begin(), plain.end());
    wrongSets += fine != brute || plain != brute;
    const int k = 1 + query % 40;
    std::nth_element(distances.begin(), distances.begin() + (k - 1), distances.end());
    wrongKth += grid.SquaredDistanceToKth(x, k, scratch) != distances[k - 1];
    // The nearest: every point within the search's radius, at least k of
    // them, as the shell of that radius gathers them; the k-th and a
    // later rank among their distances are the brute force's.
    const double reach = grid.GatherNearest(x, k, nearest);
    grid.GatherShell(x, 0.0, reach, shell);
    bool nearestRight =
      reach > 0.0 && nearest.Count >= static_cast<std::size_t>(k) && nearest.Count == shell.Count;
    for (std::size_t i = 0; nearestRight && i < shell.Count; ++i)
    {
      nearestRight = nearest.Ids[i] == shell.Ids[i] && nearest.Dx[i] == shell.Dx[i] &&
        nearest.Dy[i] == shell.Dy[i] && nearest.Dz[i] == shell.Dz[i];
    }
    wrongNearest += !nearestRight;
    if (nearestRight)
    {
      std::vector<double> squared(nearest.Count);
      for (std::size_t i = 0; i < nearest.Count; ++i)
      {
        squared[i] = nearest.Dx[i] * nearest.Dx[i] + nearest.Dy[i] * nearest.Dy[i] +
          nearest.Dz[i] * nearest.Dz[i];
      }
      const std::size_t later = std::min<std::size_t>(k + 3, nearest.Count);
      std::nth_element(distances.begin(), distances.begin() + (later - 1), distances.end());
      const std::array<double, 2> ranks = SquaredDistanceRanks(
        squared, { static_cast<std::size_t>(k), later }, reach * reach, ranked);
      wrongRanks +=
        ranks[0] != grid.SquaredDistanceToKth(x, k, scratch) || ranks[1] != distances[later - 1];
    }
  }
  checks.True(
    "dense patch: its cell is searched through finer cells", grid.GetNumberOfDenseCells() >= 1);
  checks.True(
    "dense patch: the fine query finds exactly the points within the radius", wrongSets == 0);
  checks.True("dense patch: k-th nearest distances equal brute force", wrongKth == 0);
  checks.True("dense patch: the nearest are the shell of their radius, at least k of them",
    wrongNearest == 0);
  checks.True(
    "dense patch: ranks among the nearest's distances equal brute force", wrongRanks == 0);
  // Ranks where the distances do not spread evenly: ties, one crowded
  // bucket, values beyond the top.
  const std::vector<std::vector<double>> uneven = { std::vector<double>(30, 0.25),
    { 0.0, 0.0, 0.0, 0.9, 0.9, 0.1, 0.1, 0.1, 0.1, 0.5 },
    { 1e-9, 2e-9, 3e-9, 4e-9, 5e-9, 6e-9, 0.99, 2e-9 },
    { 0.3, 0.2, 5.0, 0.1, 7.0, 0.4 } };
  bool unevenRight = true;
  for (const std::vector<double>& values : uneven)
  {
    std::vector<double> sorted = values;
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t k = 1; k <= values.size(); ++k)
    {
      const std::array<double, 2> ranks =
        SquaredDistanceRanks(values, { k, values.size() }, 1.0, ranked);
      unevenRight = unevenRight && ranks[0] == sorted[k - 1] && ranks[1] == sorted.back();
    }
  }
  checks.True(
    "distance ranks: exact with ties, crowded buckets and values beyond the top", unevenRight);
  checks.True("dense patch: a shell's points are the fine query's beyond the inner radius, in "
              "its order",
    wrongShells == 0);
}

/// One point far from a unit square of points (a "missing value" sentinel
/// at 1e110, and points nearer): the box the grid spans stays within a few
/// times the square, not the far point's distance, so the square's points
/// spread over many cells (cells of at most a fifth of it) instead of
/// sharing one. The lattice clamps the far point to an outermost cell.
void TestFarPointBox(Checks& checks)
{
  for (const double far : { 1e7, 1e30, 1e110, -1e110, 1e300 })
  {
    CloudPoints cloud;
    const int side = 60;
    cloud.Reset(side * side + 1);
    const double normal[3] = { 0.0, 0.0, 1.0 };
    for (int i = 0; i < side * side; ++i)
    {
      const double x[3] = { (i % side + 0.5) / side, (i / side + 0.5) / side, 0.0 };
      cloud.AddInputPoint(i, x, normal);
    }
    const double outlier[3] = { far, far, far };
    cloud.AddInputPoint(side * side, outlier, normal);
    const CloudBoxes boxes = MeasureBoxes(cloud, Collectives{});
    double widest = 0.0;
    for (int k = 0; k < 2; ++k)
    {
      widest = std::max(widest, boxes.Upper[k] - boxes.Lower[k]);
    }
    const GridLattice lattice = GlobalLattice(boxes, 0.1);
    char label[160];
    std::snprintf(label,
      sizeof(label),
      "a point at %g: the grid spans about the unit square (width %g), cells of %g",
      far,
      widest,
      lattice.CellSize);
    checks.True(label, widest < 20.0 && lattice.CellSize < 0.2);
  }
}

} // namespace

int main(int argc, char* argv[])
{
  return RunNamedTests(argc,
    argv,
    {
      { "DenseCells", TestDenseCells },
      { "FarPointBox", TestFarPointBox },
    });
}
