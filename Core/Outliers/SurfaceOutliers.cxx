#include "Outliers/SurfaceOutliers.h"

#include "Cloud/CloudPoints.h"
#include "Cloud/CloudStatistics.h"
#include "Cloud/Collectives.h"
#include "Cloud/Halo.h"
#include "Common/ScratchPool.h"
#include "Common/WorkRunner.h"
#include "Neighbors/PointGrid.h"
#include "Outliers/RobustSurface.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

namespace pcurv
{
namespace
{
using namespace outliers;

constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
/// A point is farther from its surface than noise explains beyond this
/// many robust standard deviations of its neighbors' distances to it (a
/// deviation measured on 24 points is itself uncertain: a 6 keeps the
/// points of Gaussian noise of a spacing or less flagged below 0.4 %).
constexpr double NoiseFactor = 6.0;
/// ... and farther than this many spacings: within them a point displaced
/// along the normal is as near to the surface as its neighbors are to each
/// other, and pulls their fits no more than noise does.
constexpr double SpacingFactor = 0.5;
/// ... and has fewer than this many points nearer than half its distance
/// or StructureSpacings spacings: a point with points of its own about it,
/// as near as the surface's are to each other, is on a structure (a step,
/// a wire, a small object), not off one; other outliers are farther.
constexpr std::size_t OwnPoints = 3;
constexpr double StructureSpacings = 2.0;
/// The quick look's radius, in the cloud's typical radius of the neighbors
/// (ClearlyOnSurface): about 27 points, enough for a plane at half the
/// cost of all 48.
constexpr double ScreenRadius = 0.75;
/// Passes of the verdicts (SurfaceOutliers.h).
constexpr int Passes = 3;
/// Feet an outlier is moved through at most on its way to the surface.
constexpr int PlacingSteps = 4;
/// One thread's buffers.
struct OutlierScratch : FitScratch
{
  ShellPoints Shell;
};

/// The cloud's points in a grid, and which of them are judged outliers
/// (so far): a verdict sees the others only.
struct SurfaceGrid
{
  PointGrid Grid;
  const unsigned char* Outlier = nullptr; // per point of the cloud
  double Typical = 0.0;                   // the cloud's typical radius of the neighbors

  /// Whether point `id` (of the grid, the cloud's) counts as a neighbor of
  /// point `self`.
  bool Counts(std::int64_t id, std::int64_t self) const { return id != self && !this->Outlier[id]; }
};

/// The `count` nearest other points of cloud point `self` at x among the
/// grid's, nearest first
/// (ties by offset: an order of the geometry alone), offsets in units of
/// the count-th one's distance, which is returned (0 with fewer points).
double GatherNearestOthers(const SurfaceGrid& grid,
  const double x[3],
  std::int64_t self,
  std::size_t count,
  OutlierScratch& scratch)
{
  std::vector<Neighbor>& nearest = scratch.Nearest;
  // Asked for more where some of those found do not count.
  constexpr int Tries = 4;
  int wanted = static_cast<int>(count) + 1;
  nearest.clear();
  for (int attempt = 0; attempt < Tries && nearest.size() < count; ++attempt)
  {
    nearest.clear();
    if (!(grid.Grid.GatherNearest(x, wanted, scratch.Shell) > 0.0))
    {
      return 0.0;
    }
    const ShellPoints& shell = scratch.Shell;
    for (std::size_t j = 0; j < shell.Count; ++j)
    {
      if (grid.Counts(shell.Ids[j], self))
      {
        const Eigen::Vector3d offset(shell.Dx[j], shell.Dy[j], shell.Dz[j]);
        nearest.push_back({ offset.squaredNorm(), offset, shell.Ids[j] });
      }
    }
    wanted += 2 * static_cast<int>(count);
  }
  if (nearest.size() < count)
  {
    return 0.0;
  }
  const auto precedes = [](const Neighbor& a, const Neighbor& b)
  {
    if (a.Squared != b.Squared)
    {
      return a.Squared < b.Squared;
    }
    return std::lexicographical_compare(
      a.Offset.data(), a.Offset.data() + 3, b.Offset.data(), b.Offset.data() + 3);
  };
  if (nearest.size() > count)
  {
    std::nth_element(nearest.begin(), nearest.begin() + (count - 1), nearest.end(), precedes);
    nearest.resize(count);
  }
  std::sort(nearest.begin(), nearest.end(), precedes);
  const double radius = std::sqrt(nearest.back().Squared);
  if (!(radius > 0.0) || !std::isfinite(radius))
  {
    return 0.0;
  }
  for (Neighbor& neighbor : nearest)
  {
    neighbor.Offset /= radius;
    neighbor.Squared = neighbor.Offset.squaredNorm();
  }
  return radius;
}

/// The points a quick look at x reads (into scratch.Shell) and the radius
/// they lie within: those within ScreenRadius typical radii, or, where
/// that would read more than DenseScreen candidates (a patch far denser
/// than the cloud, as near a scanner), the ScreenCount nearest, which cost
/// what they cost elsewhere.
std::pair<std::size_t, double> GatherScreened(const SurfaceGrid& grid,
  const double x[3],
  OutlierScratch& scratch)
{
  constexpr std::int64_t DenseScreen = 4096;
  constexpr int ScreenCount = 28; // about as many as ScreenRadius holds
  const double radius = ScreenRadius * grid.Typical;
  // Only a grid with dense cells can hold that many (most have none).
  if (grid.Grid.GetNumberOfDenseCells() == 0 || grid.Grid.CountCandidates(x, radius) <= DenseScreen)
  {
    return { grid.Grid.GatherShell(x, 0.0, radius, scratch.Shell), radius };
  }
  const double nearest = grid.Grid.GatherNearest(x, ScreenCount, scratch.Shell);
  return { scratch.Shell.Count, nearest };
}

/// A quick look before the robust fit (most points need no more): the
/// plane of the points within ScreenRadius of x (its own
/// point `self` left out). A point within ScreenFactor of their deviations
/// from it, or within a tenth of the radius (a third of a spacing), is no
/// outlier (on a curved surface the point's and its neighbors' distances to
/// the plane grow alike); `distance` gets its distance (working unit). An
/// outlier among many may pass for a point of the surface, until the others
/// are out (the passes). False with too few points to judge by.
bool ClearlyOnSurface(const SurfaceGrid& grid,
  const double x[3],
  std::int64_t self,
  OutlierScratch& scratch,
  double& distance)
{
  constexpr double ScreenFactor = 2.5;
  constexpr double ScreenReach = 0.1;
  constexpr std::size_t FewestScreened = 12;
  const auto [gathered, radius] = GatherScreened(grid, x, scratch);
  if (!(radius > 0.0))
  {
    return false;
  }
  const ShellPoints& shell = scratch.Shell;
  // Offsets in units of the radius: one pass, without cancellation.
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d products = Eigen::Matrix3d::Zero();
  std::size_t count = 0;
  const double inverse = 1.0 / radius;
  for (std::size_t j = 0; j < gathered; ++j)
  {
    const double weight = grid.Counts(shell.Ids[j], self) ? 1.0 : 0.0;
    const Eigen::Vector3d d(shell.Dx[j] * inverse, shell.Dy[j] * inverse, shell.Dz[j] * inverse);
    sum += weight * d;
    products += (weight * d) * d.transpose();
    count += weight > 0.0;
  }
  if (count < FewestScreened)
  {
    return false;
  }
  const Eigen::Vector3d mean = sum / static_cast<double>(count);
  const Eigen::Matrix3d scatter = products - static_cast<double>(count) * mean * mean.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(scatter);
  const Eigen::Vector3d normal = solver.eigenvectors().col(0);
  const double deviation =
    std::sqrt(std::max(solver.eigenvalues()[0], 0.0) / static_cast<double>(count - 3));
  const double own = std::fabs(normal.dot(mean));
  distance = own * radius;
  return normal.allFinite() && own <= std::max(ScreenFactor * deviation, ScreenReach);
}

/// One point's verdict: its distance to the surface (working unit), and,
/// for an outlier, where it goes and the surface's normal there.
struct Verdict
{
  double Distance = NaN;
  bool Outlier = false;
  Eigen::Vector3d Foot = Eigen::Vector3d::Zero();
  /// The neighbor on the surface nearest to the foot: its coordinates and
  /// normal (zero without normals).
  Eigen::Vector3d Reference = Eigen::Vector3d::Zero();
  Eigen::Vector3d ReferenceNormal = Eigen::Vector3d::Zero();
  std::int64_t ReferenceId = -1; // in the cloud, halo included
  /// The distance to the farthest of the neighbors judged by (working unit).
  double Reach = 0.0;
};

/// The verdict on point i of the cloud, were it at x (with `rankByFoot`,
/// scratch.ByFoot ranks its surface's points too).
Verdict Judge(const SurfaceGrid& grid,
  const CloudPoints& cloud,
  std::int64_t i,
  const double x[3],
  OutlierScratch& scratch,
  bool rankByFoot = false)
{
  Verdict verdict;
  double screened = 0.0;
  if (!rankByFoot && grid.Typical > 0.0 && ClearlyOnSurface(grid, x, i, scratch, screened))
  {
    // Within the typical radius of a point of the surface: its neighbors
    // (those a farther outlier would be judged again for) are within it.
    verdict.Distance = screened;
    verdict.Reach = ScreenRadius * grid.Typical;
    return verdict;
  }
  const double radius =
    GatherNearestOthers(grid, x, i, static_cast<std::size_t>(OutlierNeighbors), scratch);
  verdict.Reach = radius;
  if (!(radius > 0.0))
  {
    return verdict;
  }
  LocalSurface surface;
  double deviation = 0.0;
  if (!FitRobustSurface(scratch, surface, deviation))
  {
    return verdict;
  }
  const double distance = std::fabs(surface.Residual(Eigen::Vector3d::Zero()));
  verdict.Distance = distance * radius;
  const double spacing = SpacingAmong(scratch);
  const double limit = std::max(NoiseFactor * deviation, SpacingFactor * spacing);
  const double ownReach = std::min(0.5 * distance, StructureSpacings * spacing);
  const bool alone = scratch.Nearest[OwnPoints - 1].Squared > ownReach * ownReach;
  verdict.Outlier = distance > limit && alone;
  verdict.Foot =
    Eigen::Vector3d(x[0], x[1], x[2]) + radius * surface.FootOf(Eigen::Vector3d::Zero());
  if (rankByFoot)
  {
    RankByFoot(surface, scratch);
  }
  return verdict;
}

/// The point ranked first in scratch.ByFoot (none of the grid's points is
/// an outlier), written to `verdict`'s Reference; false if there is none.
bool ChooseReference(const CloudPoints& cloud, const OutlierScratch& scratch, Verdict& verdict)
{
  if (scratch.ByFoot.empty())
  {
    return false;
  }
  const std::int64_t reference = scratch.Nearest[scratch.ByFoot.front().second].Id;
  verdict.ReferenceId = reference;
  verdict.Reference = Eigen::Map<const Eigen::Vector3d>(&cloud.Coordinates[3 * reference]);
  if (!cloud.Normals.empty())
  {
    verdict.ReferenceNormal = Eigen::Map<const Eigen::Vector3d>(&cloud.Normals[3 * reference]);
  }
  return true;
}

/// An outlier's place on the surface: the foot of its neighbors' surface,
/// then the foot of the surface about that foot while that is still off it
/// (a point far off a curved surface sees it flatter than it is), a few
/// times at most; there, the point of the surface nearest to the foot
/// (beyond a surface's edge: a point of the edge). False where the point
/// has no neighbors to fit a surface to.
bool PlaceOnSurface(const SurfaceGrid& grid,
  const CloudPoints& cloud,
  std::int64_t i,
  OutlierScratch& scratch,
  Verdict& verdict)
{
  verdict = Judge(grid, cloud, i, &cloud.Coordinates[3 * i], scratch);
  for (int step = 0; step < PlacingSteps; ++step)
  {
    const Verdict atFoot = Judge(grid, cloud, i, verdict.Foot.data(), scratch, true);
    verdict.Foot = atFoot.Foot;
    if (!atFoot.Outlier)
    {
      break;
    }
  }
  return ChooseReference(cloud, scratch, verdict);
}

/// Moves an outlier judged on the cloud as given onto the point of the
/// surface nearest to its foot, normal included: an exact repeat of that
/// point, which gets that point's results. (An estimate at the foot itself
/// would need the foot exact to a small part of a spacing: the fits of a
/// clean surface take the point as a point of the surface.)
void MoveOntoSurface(CloudPoints& cloud, std::int64_t i, const Verdict& verdict)
{
  std::copy_n(verdict.Reference.data(), 3, &cloud.Coordinates[3 * i]);
  std::copy_n(verdict.ReferenceNormal.data(), 3, &cloud.Normals[3 * i]);
}

/// again[i]: whether one of the `found` points is among point i's
/// neighbors, all of them within reach[i] of it.
void MarkNeighborsOf(const CloudPoints& cloud,
  const std::vector<unsigned char>& found,
  const std::vector<double>& reach,
  const GridLattice& lattice,
  WorkRunner& runner,
  std::vector<unsigned char>& again)
{
  std::vector<double> coordinates;
  for (std::size_t i = 0; i < found.size(); ++i)
  {
    if (found[i])
    {
      coordinates.insert(
        coordinates.end(), &cloud.Coordinates[3 * i], &cloud.Coordinates[3 * i] + 3);
    }
  }
  PointGrid grid;
  grid.Build(
    coordinates.data(), static_cast<std::int64_t>(coordinates.size() / 3), lattice, &runner);
  runner.For(static_cast<std::int64_t>(found.size()),
    4096,
    [&](std::int64_t begin, std::int64_t end)
    {
      for (std::int64_t i = begin; i < end; ++i)
      {
        bool near = false;
        grid.ForEachWithinRadius(&cloud.Coordinates[3 * i],
          std::nextafter(reach[i], HUGE_VAL),
          [&](const double*, std::int64_t) { near = true; });
        again[i] = near ? 1 : 0;
      }
    });
}

/// Judges the points of the cloud (halo included) in passes: outlier[i]
/// and distance[i], the verdicts' flags and distances; the grid sees the
/// points not flagged in outlier.
void JudgeInPasses(const SurfaceGrid& grid,
  const CloudPoints& cloud,
  const Collectives& processes,
  const GridLattice& lattice,
  WorkRunner& runner,
  std::vector<unsigned char>& outlier,
  std::vector<double>& distance)
{
  // Outliers judged in passes, each on the points not judged outliers
  // before: a point among many outliers sees its surface once the farther
  // ones are gone. Only the points whose neighbors were judged outliers in
  // the pass before are judged again: the others' neighbors are the same.
  const std::int64_t all = cloud.GetNumberOfPoints();
  std::vector<unsigned char> again(all, 1);
  std::vector<double> reach(all, 0.0);
  ScratchPool<OutlierScratch> scratches;
  for (int pass = 0; pass < Passes; ++pass)
  {
    std::vector<unsigned char> found(all, 0);
    runner.For(all,
      1024,
      [&](std::int64_t begin, std::int64_t end)
      {
        const ScratchPool<OutlierScratch>::Lease scratch(scratches);
        for (std::int64_t i = begin; i < end; ++i)
        {
          if (!outlier[i] && again[i])
          {
            const Verdict verdict = Judge(grid, cloud, i, &cloud.Coordinates[3 * i], *scratch);
            distance[i] = verdict.Distance;
            reach[i] = verdict.Reach;
            found[i] = verdict.Outlier ? 1 : 0;
          }
        }
      });
    const std::int64_t more = std::count(found.begin(), found.end(), 1);
    if (processes.Max(static_cast<double>(more)) == 0.0)
    {
      break;
    }
    MarkNeighborsOf(cloud, found, reach, lattice, runner, again);
    for (std::int64_t i = 0; i < all; ++i)
    {
      outlier[i] |= found[i];
    }
  }
}

/// Places the own outliers flagged in found on the surface, then, the halo
/// dropped, moves those whose surface point is an own point and lists the
/// others in found's Remote arrays; found.Count: the outliers placed over
/// every process.
void PlaceOutliers(const SurfaceGrid& grid,
  CloudPoints& cloud,
  const Collectives& processes,
  std::int64_t own,
  SurfaceOutliers& found)
{
  // Placed once every verdict is in, and moved once every place is found.
  std::vector<std::pair<std::int64_t, Verdict>> moves;
  OutlierScratch scratch;
  for (std::int64_t i = 0; i < own; ++i)
  {
    Verdict verdict;
    if (found.Flag[i] && PlaceOnSurface(grid, cloud, i, scratch, verdict))
    {
      moves.emplace_back(i, verdict);
    }
  }
  cloud.DropHalo();
  for (const auto& [i, verdict] : moves)
  {
    if (verdict.ReferenceId < own)
    {
      MoveOntoSurface(cloud, i, verdict);
    }
    else
    {
      found.RemotePoints.push_back(i);
      found.RemoteReferences.insert(
        found.RemoteReferences.end(), verdict.Reference.data(), verdict.Reference.data() + 3);
      found.RemoteReferences.insert(found.RemoteReferences.end(),
        verdict.ReferenceNormal.data(),
        verdict.ReferenceNormal.data() + 3);
    }
  }
  found.Count = processes.Sum(static_cast<std::int64_t>(moves.size()));
}

} // namespace

SurfaceOutliers MoveOutliersOntoSurface(CloudPoints& cloud,
  const Collectives& processes,
  WorkRunner& runner)
{
  SurfaceOutliers found;
  const std::int64_t own = cloud.NumberOfOwnPoints;
  found.Distance.assign(own, NaN);
  found.Flag.assign(own, 0);
  if (processes.Sum(own) <= OutlierNeighbors)
  {
    return found;
  }
  const CloudBoxes boxes = MeasureBoxes(cloud, processes);
  const double typical = TypicalRadius(cloud, processes, boxes, OutlierNeighbors, &runner);
  if (!(typical > 0.0) || !std::isfinite(typical))
  {
    return found;
  }
  const GridLattice lattice = GlobalLattice(boxes, typical);
  if (processes.IsDistributed())
  {
    // Every own point's neighbors, their neighbors for the verdicts of
    // the passes before, and so on; an outlier's feet (each within a reach
    // of the one before) and their neighbors' verdicts likewise.
    const double reach = processes.Max(LargestLocalKthDistance(cloud, lattice, OutlierNeighbors));
    ExchangeHalo(cloud, processes, (Passes + PlacingSteps + 2) * reach);
    RemoveRepeatedHalo(cloud);
  }
  const std::int64_t all = cloud.GetNumberOfPoints();
  std::vector<unsigned char> outlier(all, 0);
  std::vector<double> distance(all, NaN);
  SurfaceGrid grid;
  grid.Grid.Build(cloud.Coordinates.data(), all, lattice, &runner);
  grid.Outlier = outlier.data();
  grid.Typical = typical;
  JudgeInPasses(grid, cloud, processes, lattice, runner, outlier, distance);
  std::copy_n(distance.begin(), own, found.Distance.begin());
  std::copy_n(outlier.begin(), own, found.Flag.begin());
  PlaceOutliers(grid, cloud, processes, own, found);
  return found;
}

} // namespace pcurv
