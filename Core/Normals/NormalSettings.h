/**
 * @file NormalSettings.h
 * @brief What the normal estimation is asked: neighbors, orientation.
 * No VTK.
 */
#ifndef NormalSettings_h
#define NormalSettings_h

#include "Settings/SettingsTable.h"

#include <array>
#include <cstdint>

namespace pcurv
{

/// How the sign of each connected part's normals is chosen.
enum class NormalOrientation : int
{
  /// Away from the part's inside: for a closed part (its normals sum to
  /// about zero) the sign for which the normals point away from its
  /// centroid on the whole; an open part whose normals share a side (a
  /// height field, an aerial scan, a bowl) points up (+z) on the whole,
  /// unless its normals are about horizontal (a wall), where the centroid
  /// decides again.
  Outward = 0,
  /// Each normal towards Viewpoint (where the scanner was), point by point.
  TowardsViewpoint = 1,
  /// Each normal with a positive component along Axis, point by point.
  AlongAxis = 2
};

struct NormalSettings
{
  /// Neighbors of the PCA plane fit (the point itself not counted).
  int NumberOfNeighbors = static_cast<int>(PCURV_DEFAULT("NormalNeighbors"));
  /// Whether each point's plane may grow beyond NumberOfNeighbors while
  /// wider planes agree with it (PlaneFitting.cxx, GrowWhileAgreeing): set
  /// by the estimation for the fit beyond the paper, not by the user; the
  /// paper's fits and the normals filter keep the k nearest's plane.
  bool ChooseScale = false;
  /// Nearest neighbors each point is joined to in the orientation graph.
  int GraphNeighbors = 8;
  NormalOrientation Orientation =
    static_cast<NormalOrientation>(PCURV_DEFAULT("NormalOrientation"));
  std::array<double, 3> Viewpoint = PCURV_DEFAULT3("Viewpoint");
  std::array<double, 3> Axis = PCURV_DEFAULT3("OrientationAxis");
};

} // namespace pcurv

#endif
