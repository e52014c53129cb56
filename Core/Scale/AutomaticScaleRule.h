/**
 * @file AutomaticScaleRule.h
 * @brief The constants of the automatic scale and of shared fits, as the
 * estimation chooses them for a cloud. No VTK.
 */
#ifndef AutomaticScaleRule_h
#define AutomaticScaleRule_h

#include "Settings/SettingsTable.h"

#include <array>
#include <cmath>

namespace pcurv
{

/// When a point may take an anchor's fit instead of its own.
struct SharingRule
{
  /// The lattice's cell side, in units of the cloud's typical radius of
  /// the automatic scale's first level.
  double CellFactor = 2.0;
  /// The point's distance from the anchor at most this fraction of the
  /// anchor's radius.
  double OffsetFraction = 0.15;
  /// Only anchors whose radius is at least this (a length) are shared:
  /// small radii cost little, and there the circles' exactness on a sphere
  /// or a cylinder beats any polynomial surface evaluated off its center.
  double MinimumRadius = 0.0;
  /// The point's normal within this cosine of the fitted surface's there.
  double MinimumNormalCosine = 0.866;
  /// The point's height off the fitted surface within this many noise
  /// standard deviations (and a hundredth of the anchor's radius): a point
  /// on another sheet does not share.
  double HeightDeviations = 4.0;
};

/// NeighborhoodMode::Automatic: the radii tried at each point and the rule
/// that picks one (AutomaticScaleEstimator).
struct AutomaticScaleRule
{
  int BaseCount = 16;      // the first radius holds this many neighbors
  int Levels = 8;          // radii base 2^(i/2), i < Levels: about 2000 neighbors at most
  double Precision = 1e-3; // a standard error this small (times the curvature) ends the growth
  int MinimumCount = 12;   // fewer neighbors give no estimate to compare
  /// Standard errors two estimates may differ by.
  double Tolerance = PCURV_DEFAULT("AutomaticScaleTolerance");
  double LargestRadius = 0; // no radius beyond this (a length)
  double TypicalRadius = 0; // the cloud's typical first radius (a length)
  bool ShareFits = false;   // points near an anchor take its fit (SharedFits.h)
  /// The normals were estimated from the positions: the third and fourth
  /// orders are told apart by the positions' standard errors, since the
  /// neighbors' normals share their errors.
  bool EstimatedNormals = false;
  /// Where the normals were estimated: whether they follow the surface
  /// closely enough for the wide radii to fit the fourth order too
  /// (AutomaticScaleEstimator::NormalFollowsSurface). Given normals fit it
  /// from the first radius.
  bool FourthOrder = false;
  /// The normals were given: the ladder fits the normal field
  /// (AutomaticScaleEstimator::EstimateNormalField).
  bool NormalField = false;
  /// Levels where the normals were estimated: one radius more, about 4000
  /// neighbors. Normals estimated from the positions add nothing the
  /// positions do not hold, so the ladder's band is the estimate's own and
  /// shows the bias of a wider radius; where given normals follow the
  /// surface the combined fit is far more precise than that band, which
  /// hides the bias a wider radius adds.
  int WideLevels = 9;
  /// The coordinates' lattice step per axis (CoordinateSteps; 0: none):
  /// rounding to it is noise the positions' residual need not show (where
  /// a few neighbors round to one plane), so it floors their variance.
  std::array<double, 3> CoordinateStep{};
  SharingRule Sharing;

  /// The last radius of a ladder of `levels` radii from TypicalRadius.
  double LargestRadiusOf(int levels) const
  {
    return this->TypicalRadius * std::pow(2.0, 0.5 * (levels - 1));
  }

  /// A ladder of `levels` radii: Levels and the LargestRadius it reaches.
  void SetLevels(int levels)
  {
    this->Levels = levels;
    this->LargestRadius = this->LargestRadiusOf(levels);
  }
};

} // namespace pcurv

#endif
