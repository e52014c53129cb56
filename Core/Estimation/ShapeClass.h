/**
 * @file ShapeClass.h
 * @brief What a point's estimate says of its shape, judged against its
 * standard error: the shape classes (codes and names, in one place), and
 * whether an estimate is trusted. Pointwise rules, no VTK.
 */
#ifndef ShapeClass_h
#define ShapeClass_h

#include <cstdint>

namespace pcurv
{

/// The shape class of a point (the values of the Shape_Class array). A
/// principal curvature is significant when it differs from zero by more
/// than ShapeSignificance standard errors; the class follows the signs of
/// the significant ones (the output's sign: positive where the surface
/// bends away from the normal).
enum class ShapeClass : std::uint8_t
{
  /// Not estimated, an outlier (its values are the nearest surface's), or
  /// neither curvature significant while the estimate is too imprecise to
  /// call the point flat (FlatBending).
  Undetermined = 0,
  /// Neither curvature significant, and flatness known (FlatBending).
  Flat = 1,
  /// Both significant and positive (a sphere with outward normals).
  Dome = 2,
  /// Both significant and negative (a sphere with inward normals).
  Cup = 3,
  /// k_max significant and positive, k_min not (a cylinder, outward).
  Ridge = 4,
  /// k_min significant and negative, k_max not (a cylinder, inward).
  Valley = 5,
  /// Both significant, of opposite signs.
  Saddle = 6,
  Count = 7
};

/// The class's name, as the Shape_Class_Names field data and ParaView's
/// legend list it ("Undetermined", "Flat", "Dome", ...); "Unknown" beyond
/// the classes. Inline so that the GUI takes the names from here too.
inline const char* ShapeClassName(ShapeClass shapeClass)
{
  constexpr const char* Names[] = {
    "Undetermined", "Flat", "Dome", "Cup", "Ridge", "Valley", "Saddle"
  };
  static_assert(sizeof(Names) / sizeof(Names[0]) == static_cast<int>(ShapeClass::Count));
  const auto code = static_cast<int>(shapeClass);
  return code < static_cast<int>(ShapeClass::Count) ? Names[code] : "Unknown";
}

/// The name of the point array holding the classes.
constexpr const char* ShapeClassArrayName = "Shape_Class";

/// How many standard errors a curvature must differ from zero by to
/// count as a feature rather than noise.
constexpr double ShapeSignificance = 2.0;

/// A point is Flat only when flatness is known: a curvature of twice its
/// standard error turns the surface by at most this many radians (about
/// 57 degrees) across the point's neighborhood radius. Where it could turn
/// more, "not significantly curved" says nothing of the shape (a tree
/// crown's sparse, noisy points), and the point is Undetermined rather than
/// Flat; ground and roofs, even of sparse airborne scans, are known far
/// better than that.
constexpr double FlatBending = 1.0;

/// The class of an estimate of neighborhood radius `radius`: `valid`
/// false, `outlier` true or a standard error not finite give Undetermined.
ShapeClass ClassifyShape(bool valid,
  bool outlier,
  double minimumCurvature,
  double maximumCurvature,
  double standardError,
  double radius);

/// A trusted curvature is known to this share of its own magnitude (twice
/// its standard error within it): its sign beyond doubt and its size to a
/// third, as a crest needs.
constexpr double TrustedRelativeError = 1.0 / 3.0;
/// Or, on nearly flat ground, to this share of the cloud's curvature scale.
constexpr double TrustedScaleShare = 0.1;

/// Whether an estimate is trusted: estimated, not an outlier, and twice
/// its standard error within TrustedRelativeError of its largest
/// |curvature| or within TrustedScaleShare of the cloud's curvature scale
/// (EstimationSummary::TrustedCurvatureScale).
bool IsTrusted(bool valid,
  bool outlier,
  double minimumCurvature,
  double maximumCurvature,
  double standardError,
  double cloudCurvatureScale);

} // namespace pcurv

#endif
