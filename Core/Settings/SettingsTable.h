/**
 * @file SettingsTable.h
 * @brief Every user setting of the filters, once: name, default, range,
 * unit and one line of documentation. The core's settings take their
 * defaults from here, the VTK filters theirs from the core's, and
 * Testing/Python/TestSettingsAgree.py checks the filters' defaults and
 * clamps, the ParaView XML, the command-line tool and docs/settings.md
 * against it (Scripts/settings_table.py writes the docs' tables from it).
 * No VTK.
 */
#ifndef SettingsTable_h
#define SettingsTable_h

#include <array>
#include <cstddef>
#include <limits>
#include <string_view>

namespace pcurv
{

enum class SettingType
{
  Bool,
  Int,
  Enum, ///< an int whose values have names (Choices, from 0)
  Double,
  Double3
};

struct SettingSpec
{
  const char* Name;        ///< Set<Name> / Get<Name> of vtkPrincipalCurvatureEstimation
  const char* NormalsName; ///< the same setting of vtkPointCloudNormalEstimation, or null
  const char* Group;       ///< the docs' table it is listed in
  SettingType Type;
  std::array<double, 3> Default; ///< one value unless Double3
  double Minimum;
  double Maximum;
  const char* Unit;    ///< what the value counts or measures ("" for none)
  const char* Choices; ///< Enum: the values' names, "|" between them
  const char* Doc;     ///< one line (markdown)
};

namespace settings
{
constexpr double Largest = std::numeric_limits<double>::max();

// clang-format off
constexpr SettingSpec Table[] = {
  { "FitMode", nullptr, "estimate", SettingType::Enum, { 3 }, 0, 3, "",
    "Previous|New01|New02|OrientedCircles",
    "OrientedCircles (beyond the paper: positions and normals of every neighbor, [method.md](method.md) section 10), or the paper's Previous, New01, New02" },
  { "NeighborhoodMode", nullptr, "estimate", SettingType::Enum, { 2 }, 0, 2, "",
    "Radius|KNearest|Automatic",
    "Automatic (per point, from the data; with OrientedCircles and automatic thresholds, Radius otherwise), Radius (within `s`) or K Nearest" },
  { "AutomaticScaleTolerance", nullptr, "estimate", SettingType::Double, { 2.0 }, 0.1, 100.0,
    "standard errors", "",
    "Automatic: standard errors two radii's estimates may differ by for the larger to be kept" },
  { "ShareFits", nullptr, "estimate", SettingType::Bool, { 1 }, 0, 1, "", "",
    "Automatic: points near an anchor point with a wide neighborhood take its fitted surface, evaluated at their own position, instead of fitting nearly the same neighbors again ([method.md](method.md) section 10, \"Shared fits\"); off: every point fits its own, several times slower on noisy clouds" },
  { "NormalFieldFit", nullptr, "estimate", SettingType::Bool, { 0 }, 0, 1, "", "",
    "Automatic, with normals given: where the positions are noisy, the curvatures from a fit of the normal field instead of the oriented circles ([method.md](method.md) section 10, \"The normal field\"); more accurate under position noise, less smooth from point to point (Curvature Lines find fewer lines); off by default" },
  { "AutomaticThresholds", nullptr, "estimate", SettingType::Bool, { 1 }, 0, 1, "", "",
    "derive `s` and `p` from the cloud (below)" },
  { "NumberOfNeighbors", nullptr, "estimate", SettingType::Int, { 375 }, 3, 1e6, "neighbors", "",
    "target neighbor count for the automatic `s`; k in K Nearest mode (unused, and hidden in the panel, with the default automatic neighborhood of OrientedCircles)" },
  { "SurroundingsThreshold", nullptr, "estimate", SettingType::Double, { 1.0 }, 0.0, Largest,
    "length", "", "`s`, a length, when automatic is off" },
  { "PlaneDistanceThreshold", nullptr, "estimate", SettingType::Double, { 0.1 }, 0.0, Largest,
    "length", "",
    "`p`, a length, when automatic is off (the paper's fits only: OrientedCircles uses no half planes)" },
  { "PlaneDistanceRatio", nullptr, "estimate", SettingType::Double, { 0.1 }, 0.001, 1.0, "", "",
    "`p / s` when automatic is on (the paper's fits only)" },
  { "MinimumPointsPerDirection", nullptr, "estimate", SettingType::Int, { 3 }, 3, 1e6, "points",
    "", "fewest points for a circle fit" },
  { "NumberOfThreads", "NumberOfThreads", "estimate", SettingType::Int, { 0 }, 0, 4096,
    "threads", "", "0 = all cores" },
  { "SinglePrecisionOutput", nullptr, "output", SettingType::Bool, { 0 }, 0, 1, "", "",
    "float arrays instead of double (each value rounded once, with no double copy held: also less memory)" },
  { "DiagnosticArrays", nullptr, "output", SettingType::Bool, { 1 }, 0, 1, "", "",
    "the arrays that say how each point was estimated ([output-arrays.md](output-arrays.md))" },
  { "NormalsSource", nullptr, "normals", SettingType::Enum, { 0 }, 0, 2, "",
    "Automatic|Input|Estimated",
    "Automatic (real input normals if any, else estimated), Input Array (the array; an error if it is missing or not normals), Estimated (always)" },
  { "NormalOrientation", "Orientation", "normals", SettingType::Enum, { 0 }, 0, 2, "",
    "Outward|TowardsViewpoint|AlongAxis",
    "how estimated normals are signed: Outward, Towards Viewpoint, Along Axis" },
  { "Viewpoint", "Viewpoint", "normals", SettingType::Double3, { 0.0, 0.0, 0.0 }, -Largest,
    Largest, "length", "", "the scanner's position, for Towards Viewpoint" },
  { "OrientationAxis", "Axis", "normals", SettingType::Double3, { 0.0, 0.0, 1.0 }, -Largest,
    Largest, "", "", "the direction, for Along Axis" },
  { "NormalNeighbors", "NumberOfNeighbors", "normals", SettingType::Int, { 30 }, 3, 100000,
    "neighbors", "",
    "neighbors of each point's PCA plane (more where those lie on a line: [usage.md](usage.md), \"Normals\")" },
  { "DynamicAdjustment", nullptr, "adjustment", SettingType::Bool, { 0 }, 0, 1, "", "",
    "the paper's dynamic variable adjustment" },
  { "AutomaticLengthUnit", nullptr, "adjustment", SettingType::Bool, { 1 }, 0, 1, "", "",
    "derive `L` from the cloud, so that the initial `s` holds about the first target count" },
  { "LengthUnit", nullptr, "adjustment", SettingType::Double, { 1.0 }, 1e-300, Largest, "length",
    "", "`L` when `AutomaticLengthUnit` is off (1: the paper's absolute values)" },
  { "InitialSurroundingsThreshold", nullptr, "adjustment", SettingType::Double, { 4.0 }, 1e-300,
    Largest, "L", "", "`s` at the start of each block, units of `L`" },
  { "TargetNeighborCounts", nullptr, "adjustment", SettingType::Double3, { 375.0, 750.0, 1500.0 },
    1.0, 1e6, "neighbors", "",
    "the three combinations' counts (clamped to [1, 1e6] with a warning)" },
  { "TargetPlaneDistances", nullptr, "adjustment", SettingType::Double3, { 0.1, 0.05, 0.025 },
    -Largest, Largest, "L", "", "the three combinations' plane distances, units of `L`" },
  { "SwitchLengths", nullptr, "adjustment", SettingType::Double3, { 2.0, 1.0, 4.0 }, -Largest,
    Largest, "L", "",
    "to the second combination below the first, to the third below the second, one back above the third; units of `L`" },
  { "MaximumSurroundingsFactor", nullptr, "adjustment", SettingType::Double, { 4.0 }, 1.0, 1e6, "",
    "", "`s` never exceeds this times its initial value" },
  { "AdjustmentBlockLength", nullptr, "adjustment", SettingType::Double, { 8.0 }, 1e-6, 1e6, "L",
    "", "side of the adjustment's blocks, units of `L`" },
};
// clang-format on

constexpr std::size_t Count = sizeof(Table) / sizeof(Table[0]);

/// The position of setting `name` in the table; evaluated where a
/// constant is needed (PCURV_DEFAULT), a misspelled name fails the build.
constexpr std::size_t Index(std::string_view name)
{
  for (std::size_t i = 0; i < Count; ++i)
  {
    if (name == Table[i].Name)
    {
      return i;
    }
  }
  throw "no such setting";
}

template<std::size_t I>
constexpr const SettingSpec& Row()
{
  return Table[I];
}
} // namespace settings

} // namespace pcurv

/// Component `component` of the default of setting `name` (a string
/// literal), found at compile time.
#define PCURV_DEFAULT_OF(name, component)                                                          \
  (::pcurv::settings::Row<::pcurv::settings::Index(name)>().Default[component])
#define PCURV_DEFAULT(name) PCURV_DEFAULT_OF(name, 0)
/// The three components of a Double3 setting's default.
#define PCURV_DEFAULT3(name) (::pcurv::settings::Row<::pcurv::settings::Index(name)>().Default)

#endif
