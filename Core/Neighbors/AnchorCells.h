/**
 * @file AnchorCells.h
 * @brief Anchor points chosen in space: one per occupied cell of a global
 * lattice, the same whatever the visiting order, thread count or split
 * among processes. No VTK.
 *
 * Fits that serve the points near them (the estimator's shared fits, the
 * curvature lines' fits of the curvatures) are made at these anchors.
 */
#ifndef AnchorCells_h
#define AnchorCells_h

#include <algorithm>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

namespace pcurv
{

/// The anchors of a cloud, one per occupied cell of a global lattice: the
/// eligible point nearest the cell's center (ties by coordinates, then by
/// normal), a strict order on distinct points, so no visiting order
/// changes the choice.
class AnchorCells
{
public:
  /// A cell of the lattice, by its indices.
  struct CellKey
  {
    std::int64_t I, J, K;
    bool operator==(const CellKey& other) const
    {
      return this->I == other.I && this->J == other.J && this->K == other.K;
    }
  };

  /// The anchors around the last cell asked for (AnchorsAround): points in
  /// the grid's order mostly share their cell with the one before. Point
  /// indices, or their positions in the list given to NumberAnchors once
  /// it was called.
  struct Around
  {
    bool Known = false;
    CellKey Cell{ 0, 0, 0 };
    std::vector<std::int64_t> Anchors;
  };

  /// `pointAt(j)`, j < count, visits the points (any order gives the same
  /// anchors; one that keeps a cell's points together, as the grid's,
  /// touches the table once per run of them); `eligible(point)` tells
  /// which may be anchors (those with a normal); lattice origin and cell
  /// side are global. `keepGoing()` is asked every CheckInterval points;
  /// false stops the build (the cells are then incomplete) and returns
  /// false.
  template<typename PointAt, typename Eligible, typename KeepGoing>
  bool Build(const double* coordinates,
    const double* normals,
    std::int64_t count,
    const PointAt& pointAt,
    const double origin[3],
    double cellSide,
    const Eligible& eligible,
    const KeepGoing& keepGoing)
  {
    this->Begin(origin, cellSide, coordinates, normals);
    bool inRun = false;
    CellKey runCell{ 0, 0, 0 };
    std::int64_t runBest = -1;
    for (std::int64_t j = 0; j < count; ++j)
    {
      if (j % CheckInterval == 0 && !keepGoing())
      {
        return false;
      }
      if (j + PrefetchDistance < count)
      {
        // In the grid's order the points are scattered in memory.
        const std::int64_t ahead = pointAt(j + PrefetchDistance);
        __builtin_prefetch(coordinates + 3 * ahead);
        __builtin_prefetch(normals + 3 * ahead);
      }
      const std::int64_t point = pointAt(j);
      if (!eligible(point))
      {
        continue;
      }
      const CellKey cell = this->KeyOf(coordinates + 3 * point);
      if (inRun && cell == runCell)
      {
        runBest = this->Precedes(point, runBest, cell) ? point : runBest;
        continue;
      }
      if (inRun)
      {
        this->Offer(runCell, runBest);
      }
      inRun = true;
      runCell = cell;
      runBest = point;
    }
    if (inRun)
    {
      this->Offer(runCell, runBest);
    }
    return true;
  }

  /// Points between two asks whether to go on.
  static constexpr std::int64_t CheckInterval = 1 << 16;
  /// How many points ahead Build asks for a point's data.
  static constexpr std::int64_t PrefetchDistance = 16;

  /// The anchor of the cell holding x, and of the 26 cells around it, in a
  /// fixed order (cells without anchors skipped), into `around` (which
  /// keeps them for the next point in the same cell). False when `around`
  /// held them already.
  bool AnchorsAround(const double x[3], Around& around) const;

  /// Sets marks[anchor] to 1 for the anchors around (AnchorsAround) any of
  /// the points `pointAt(j)`, j < count; false when `keepGoing()` (asked
  /// every CheckInterval points) said to stop.
  bool MarkAnchorsAround(std::int64_t count,
    const std::function<std::int64_t(std::int64_t)>& pointAt,
    std::vector<unsigned char>& marks,
    const std::function<bool()>& keepGoing) const;

  /// From now on AnchorsAround gives each anchor's position in `kept`
  /// (point indices of anchors), and skips the anchors not in it.
  void NumberAnchors(const std::vector<std::int64_t>& kept);

  /// Sets marks[anchor] to 1 for every anchor.
  void MarkEveryAnchor(std::vector<unsigned char>& marks) const
  {
    for (const auto& cell : this->Anchors)
    {
      marks[static_cast<std::size_t>(cell.second)] = 1;
    }
  }

  double GetCellSide() const { return this->CellSide; }

private:
  struct CellHash
  {
    std::size_t operator()(const CellKey& key) const;
  };

  void Begin(const double origin[3],
    double cellSide,
    const double* coordinates,
    const double* normals);
  /// `point` competes for the anchor of `cell`.
  void Offer(const CellKey& cell, std::int64_t point);
  CellKey KeyOf(const double x[3]) const;
  /// Whether point a comes before point b as the anchor of their cell.
  bool Precedes(std::int64_t a, std::int64_t b, const CellKey& cell) const;

  double Origin[3] = { 0.0, 0.0, 0.0 };
  double CellSide = 1.0;
  const double* Coordinates = nullptr;
  const double* Normals = nullptr;
  std::unordered_map<CellKey, std::int64_t, CellHash> Anchors;
};

} // namespace pcurv

#endif
