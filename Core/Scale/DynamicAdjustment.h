/**
 * @file DynamicAdjustment.h
 * @brief The paper's dynamic variable adjustment (Getto & Hildenbrand 2011,
 * section 5) of the surroundings-threshold s and the plane-distance-threshold
 * p while points are processed one after another. No VTK.
 *
 * State: a target combination (N_t, p_t), initially the first of three, and
 * s, initially InitialSurroundingsThreshold. After the N neighbors of a
 * point within s are gathered:
 *  1. p = p_t * N_t / N for this point (fewer points than targeted: wider
 *     planes, so each direction still gets points);
 *  2. s <- s * sqrt(N_t / N) for the next point (on a surface the count
 *     grows with the area, s^2);
 *  3. when s falls below the first switch length the targets move to the
 *     second combination, below the second to the third; when s rises above
 *     the return length they step back one combination.
 * Every length (initial s, switch lengths, p_t) is multiplied by a length
 * unit L: L = 1 gives the paper's absolute values; a cloud-derived L makes
 * the method scale free.
 */
#ifndef DynamicAdjustment_h
#define DynamicAdjustment_h

#include "Settings/SettingsTable.h"

#include <array>

namespace pcurv
{

struct AdjustmentSettings
{
  double LengthUnit = 1.0; ///< L, multiplies every length below
  double InitialSurroundingsThreshold =
    PCURV_DEFAULT("InitialSurroundingsThreshold"); ///< s at the start, in units of L
  std::array<double, 3> TargetNeighborCounts = PCURV_DEFAULT3("TargetNeighborCounts");
  std::array<double, 3> TargetPlaneDistances =
    PCURV_DEFAULT3("TargetPlaneDistances"); ///< units of L
  /// Switch to the second combination below SwitchLengths[0], to the third
  /// below SwitchLengths[1]; step back one above SwitchLengths[2] (units of L).
  std::array<double, 3> SwitchLengths = PCURV_DEFAULT3("SwitchLengths");
  /// s never grows beyond this (units of L; the paper has no bound): in a
  /// region far sparser than the targets it would otherwise grow without
  /// limit, and a parallel run must know how far a query can reach.
  double MaximumSurroundingsThreshold = 16.0;
};

/// The "banded ladder" (docs/dynamic-adjustment.md): the paper's mechanism
/// with its switch lengths next to the initial s (up below 4.5 L and
/// 3.2 L = 4.5 L / sqrt 2, back above 7.2 L: BandedLadderSwitchLengths), so
/// that the target count doubles where the density grows and the radius
/// stays in a band; counts firstCount, 2 firstCount, 4 firstCount, and the
/// same plane distance (units of L) at every level, since s stays about the
/// same.
constexpr std::array<double, 3> BandedLadderSwitchLengths{ { 4.5, 3.2, 7.2 } };
AdjustmentSettings BandedLadder(double firstCount, double planeDistance);

/// The named sets of constants, defined here once for the filter, the study
/// and the benchmark (the command-line tool's table is tested against
/// them): the paper's, and the banded ladder as measured for clean clouds
/// and for clouds with noise of about half a point spacing.
enum class AdjustmentPreset : int
{
  Paper = 0,      ///< 375, 750, 1500 neighbors; p 0.1, 0.05, 0.025 L; switches 2, 1, 4 L
  Ladder = 1,     ///< BandedLadder(375, 0.2)
  NoisyLadder = 2 ///< BandedLadder(1000, 0.6)
};

AdjustmentSettings AdjustmentConstants(AdjustmentPreset preset);

class DynamicAdjustment
{
public:
  explicit DynamicAdjustment(const AdjustmentSettings& settings = AdjustmentSettings{});

  /// Back to the initial state, as at the paper's very first point.
  void Restart();

  /// The surroundings-threshold to gather the current point's neighbors with.
  double GetSurroundingsThreshold() const { return this->Surroundings; }

  /// Index (0..2) of the current target combination.
  int GetLevel() const { return this->Level; }

  /// The current combination's target neighbor count N_t (rounded).
  int GetTargetNeighborCount() const
  {
    return static_cast<int>(this->Settings.TargetNeighborCounts[this->Level] + 0.5);
  }

  /// Takes the number of neighbors found within GetSurroundingsThreshold(),
  /// returns the plane-distance-threshold for this point and updates s and
  /// the target combination for the next point.
  double Adjust(int neighborCount);

private:
  AdjustmentSettings Settings;
  double Surroundings = 0.0;
  int Level = 0;
};

} // namespace pcurv

#endif
