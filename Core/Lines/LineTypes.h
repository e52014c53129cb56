/**
 * @file LineTypes.h
 * @brief The curvature lines' kinds, input and settings (CurvatureLines.h
 * has the entry point). No VTK.
 */
#ifndef LineTypes_h
#define LineTypes_h

#include <cstdint>
#include <stdexcept>

namespace pcurv
{

/// What a line is an extremum of. Ridge and Valley are the dominant cases
/// of a maximum of k_max and of a minimum of k_min.
enum class LineKind : unsigned char
{
  Ridge = 0,            ///< k_max maximal along d_max, k_max > |k_min|
  Valley = 1,           ///< k_min minimal along d_min, k_min < -|k_max|
  MaximumOfMaximum = 2, ///< k_max maximal, not dominant
  MinimumOfMaximum = 3, ///< k_max minimal
  MaximumOfMinimum = 4, ///< k_min maximal
  MinimumOfMinimum = 5  ///< k_min minimal, not dominant
};
constexpr int LineKindCount = 6;

/// The kind's name, as ParaView's legend and the command-line tool's
/// summary list it ("Ridge", "Valley", ...); "Unknown" beyond the kinds.
/// Inline so that the GUI takes the names from here too.
inline const char* LineKindName(LineKind kind)
{
  constexpr const char* Names[] = {
    "Ridge", "Valley", "Max of k_max", "Min of k_max", "Max of k_min", "Min of k_min"
  };
  static_assert(sizeof(Names) / sizeof(Names[0]) == LineKindCount);
  const auto code = static_cast<int>(kind);
  return code < LineKindCount ? Names[code] : "Unknown";
}

/// The name of the lines' cell array holding the kinds.
constexpr const char* LineKindArrayName = "Line_Kind";

/// The name of the lines' field data counting the lines of each kind (one
/// tuple, a component per kind, by code).
constexpr const char* LineCountsArrayName = "Line_Counts";

/// Bit of a kind in LineSettings::Kinds.
constexpr unsigned KindBit(LineKind kind)
{
  return 1u << static_cast<unsigned>(kind);
}
constexpr unsigned RidgesAndValleys = KindBit(LineKind::Ridge) | KindBit(LineKind::Valley);
constexpr unsigned AllLineKinds = (1u << LineKindCount) - 1u;

/// The cloud and its curvatures, as the caller's arrays (xyz triplets for
/// points and vectors). Optional arrays may be null.
struct LineInput
{
  std::int64_t Count = 0;
  const double* Points = nullptr;
  const double* Normals = nullptr; ///< unit; the directions' tangent plane
  const double* MaximumCurvature = nullptr;
  const double* MinimumCurvature = nullptr;
  const double* MaximumDirection = nullptr; ///< unit, up to sign
  const double* MinimumDirection = nullptr; ///< unit, up to sign (unused: n x d_max)
  /// Optional: the curvatures' standard error; a point's extremum must
  /// stand out of it.
  const double* StandardError = nullptr;
  /// Optional: the neighborhood radius of each point (the curvature
  /// filter's Surroundings_Threshold); else the distance to the
  /// RadiusNeighbors-th nearest point.
  const double* Radius = nullptr;
  /// Optional: nonzero where the curvatures are valid.
  const unsigned char* Valid = nullptr;
  /// Optional: the typical neighborhood radius, which sets the spacing of
  /// the shared fits' anchors; 0: no shared fits, every point fits its
  /// own. A distributed caller passes the same value on every process.
  double TypicalRadius = 0.0;
  /// Optional (a distributed run): nonzero at this process's own points.
  /// The others, its halo, lend their curvatures to the fits and their
  /// derivatives to the edges of own points; only the graph edges an own
  /// point crosses (FindCrossings) give crossings here, so that each edge
  /// is crossed by one process.
  const unsigned char* Owned = nullptr;
};

struct LineSettings
{
  /// Kinds to extract (KindBit), by default the crests users mean.
  unsigned Kinds = RidgesAndValleys;
  /// Lines shorter than this many median neighborhood radii are dropped.
  double MinimumLength = 3.0;
  /// Lines whose strength (integral of |k| along them, in radians) is
  /// below this are dropped.
  double MinimumStrength = 0.0;
  /// How many standard errors an extremum's second derivative must exceed.
  double Significance = 2.0;
  /// The least second derivative |k''| of the curvature along its
  /// direction, relative to (k_max - k_min) max(|k_max|, |k_min|)^2 (the
  /// same unit, 1/length^3, whatever the scale): where the curvature is
  /// about constant along its direction (a torus, a cylinder) the zeros of
  /// its derivative are noise, not lines.
  double RelativeBend = 0.02;
  /// The radius of each point's fit of its neighbors' curvatures, in
  /// neighborhood radii.
  double FitRadius = 1.0;
  /// At most about this many neighbors per fit: wider neighborhoods are
  /// thinned evenly.
  int FitNeighbors = 500;
  /// A fit takes at least about this many points: where the curvatures'
  /// neighborhoods hold fewer (clean clouds), the fit's radius grows to
  /// hold them.
  int MinimumFitPoints = 100;
  /// Where a fit's neighborhood holds at least about this many points, one
  /// fit serves the points near its center (SharedFitReach): the
  /// neighborhoods of nearby points are then nearly the same set.
  int SharedFitPoints = 100;
  /// How far a shared fit serves, in the served point's fit radii.
  double SharedFitReach = 0.5;
  /// The side of the cells of the shared fits' anchors, in typical fit
  /// radii.
  double AnchorSpacing = 0.4;
  /// Neighbors of each point in the graph whose edges the lines cross.
  int GraphNeighbors = 8;
  /// Nearest neighbors whose distance is the radius where none is given.
  int RadiusNeighbors = 40;
};

/// Thrown on input the lines cannot be computed from.
class LineInputError : public std::invalid_argument
{
public:
  using std::invalid_argument::invalid_argument;
};

} // namespace pcurv

#endif
