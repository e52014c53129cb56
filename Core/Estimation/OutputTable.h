/**
 * @file OutputTable.h
 * @brief The one table of the curvature filter's output arrays: name,
 * value type, components, unit, when each is written and what it is. The
 * filter makes its arrays from it, ParaView's GUI titles color bars with
 * its units, and the OutputsAgree test checks docs/output-arrays.md and the
 * help page against it. Header only (the plugin's GUI reads it). No VTK.
 *
 * Adding an output: a row here (in the order the arrays appear), its
 * buffer in CurvatureOutputs.h, its value in ResultStore.cxx, and its row
 * in docs/output-arrays.md, which the test then requires.
 */
#ifndef OutputTable_h
#define OutputTable_h

#include "Estimation/ShapeClass.h"

#include <array>
#include <cstddef>
#include <string>

namespace pcurv
{

/// Every output array, in the table's (and the output's) order.
enum class Output : int
{
  MinimumCurvature,
  MaximumCurvature,
  MeanCurvature,
  GaussCurvature,
  MinimumDirection,
  MaximumDirection,
  Valid,
  NeighborCount,
  ValidDirections,
  SineFitRms,
  Surroundings,
  PlaneDistance,
  TargetCount,
  ShapeIndex,
  Curvedness,
  ClippedMean,
  StandardError,
  Trusted,
  ShapeClass,
  FittedNormal,
  Outlier,
  SurfaceDistance,
  Count
};

/// How an array's values are stored: Real as double, or float with
/// SinglePrecisionOutput.
enum class OutputValue
{
  Real,
  Int,
  UnsignedChar
};

/// The unit of an array's values, in terms of the input's length unit.
enum class OutputUnit
{
  None,
  Length,
  PerLength,
  PerLengthSquared
};

/// When an array is written.
enum class OutputCondition
{
  Always,
  /// With DynamicAdjustment only.
  DynamicAdjustment,
  /// Unless the output is to be small (left out with the diagnostics).
  Display,
  /// With the fits that give a standard error (OrientedCircles).
  StandardError
};

/// One row of the table.
struct OutputArray
{
  Output Id;
  const char* Name;
  OutputValue Value;
  int Components;
  OutputUnit Unit;
  OutputCondition Condition;
  /// Left out with DiagnosticArrays off.
  bool Diagnostic;
  /// One line: what the array holds.
  const char* Summary;
};

namespace output_table
{
using V = OutputValue;
using U = OutputUnit;
using C = OutputCondition;

// The rows as written, two lines each: the table reads as one.
// clang-format off
inline constexpr std::array<OutputArray, static_cast<std::size_t>(Output::Count)> Table = { {
  { Output::MinimumCurvature, "Minimum_Curvature", V::Real, 1, U::PerLength, C::Always, false,
    "the smaller principal curvature" },
  { Output::MaximumCurvature, "Maximum_Curvature", V::Real, 1, U::PerLength, C::Always, false,
    "the larger principal curvature" },
  { Output::MeanCurvature, "Mean_Curvature", V::Real, 1, U::PerLength, C::Always, false,
    "the mean of the principal curvatures" },
  { Output::GaussCurvature, "Gauss_Curvature", V::Real, 1, U::PerLengthSquared, C::Always, false,
    "the product of the principal curvatures" },
  { Output::MinimumDirection, "Minimum_Curvature_Direction", V::Real, 3, U::None, C::Always, false,
    "the unit direction of the smaller principal curvature" },
  { Output::MaximumDirection, "Maximum_Curvature_Direction", V::Real, 3, U::None, C::Always, false,
    "the unit direction of the larger principal curvature" },
  { Output::Valid, "Curvature_Valid", V::UnsignedChar, 1, U::None, C::Always, false,
    "1 where estimated, 0 where not" },
  { Output::NeighborCount, "Neighbor_Count", V::Int, 1, U::None, C::Always, true,
    "the neighbors the estimate used" },
  { Output::ValidDirections, "Valid_Direction_Count", V::Int, 1, U::None, C::Always, true,
    "the half planes with a valid circle fit" },
  { Output::SineFitRms, "Sine_Fit_RMS", V::Real, 1, U::PerLength, C::Always, true,
    "how far the normal curvatures are from Euler's formula" },
  { Output::Surroundings, "Surroundings_Threshold", V::Real, 1, U::Length, C::Always, true,
    "the neighborhood radius at the point" },
  { Output::PlaneDistance, "Plane_Distance_Threshold", V::Real, 1, U::Length, C::Always, true,
    "the half planes' distance threshold p" },
  { Output::TargetCount, "Target_Neighbor_Count", V::Int, 1, U::None, C::DynamicAdjustment, true,
    "the neighbor count the dynamic adjustment aimed at" },
  { Output::ShapeIndex, "Shape_Index", V::Real, 1, U::None, C::Always, false,
    "Koenderink and van Doorn's shape index, in [-1, 1]" },
  { Output::Curvedness, "Curvedness", V::Real, 1, U::PerLength, C::Always, false,
    "how much the surface bends, whatever its shape" },
  { Output::ClippedMean, "Mean_Curvature_Clipped", V::Real, 1, U::PerLength, C::Display, false,
    "the mean curvature clamped for display (the active scalars)" },
  { Output::StandardError, "Curvature_Standard_Error", V::Real, 1, U::PerLength, C::StandardError, true,
    "the error to expect of the principal curvatures" },
  { Output::Trusted, "Curvature_Trusted", V::UnsignedChar, 1, U::None, C::StandardError, false,
    "1 where the curvatures are known to what they show" },
  { Output::ShapeClass, ShapeClassArrayName, V::UnsignedChar, 1, U::None, C::StandardError, false,
    "the point's shape: undetermined, flat, dome, cup, ridge, valley, saddle" },
  { Output::FittedNormal, "Fitted_Normal", V::Real, 3, U::None, C::StandardError, false,
    "the unit normal of the fitted surface" },
  { Output::Outlier, "Outlier", V::UnsignedChar, 1, U::None, C::StandardError, false,
    "1 where the point lies far off its neighbors' surface" },
  { Output::SurfaceDistance, "Surface_Distance", V::Real, 1, U::Length, C::StandardError, true,
    "the point's distance to its neighbors' surface" },
} };
// clang-format on

constexpr bool InOrder()
{
  for (std::size_t i = 0; i < Table.size(); ++i)
  {
    if (static_cast<std::size_t>(Table[i].Id) != i)
    {
      return false;
    }
  }
  return true;
}
static_assert(InOrder(), "the table's rows are in the order of Output");
} // namespace output_table

/// The row of an output.
inline const OutputArray& OutputOf(Output id)
{
  return output_table::Table[static_cast<std::size_t>(id)];
}

/// The row named `name`, or null.
inline const OutputArray* FindOutput(const std::string& name)
{
  for (const OutputArray& row : output_table::Table)
  {
    if (name == row.Name)
    {
      return &row;
    }
  }
  return nullptr;
}

/// The unit as text, from the input's length unit ("foot"; empty: "length
/// unit"): "1/foot", "1/foot^2", "foot", or "" for OutputUnit::None.
inline std::string UnitText(OutputUnit unit, const std::string& lengthUnit)
{
  const std::string length = lengthUnit.empty() ? std::string("length unit") : lengthUnit;
  switch (unit)
  {
    case OutputUnit::Length:
      return length;
    case OutputUnit::PerLength:
      return "1/" + length;
    case OutputUnit::PerLengthSquared:
      return "1/" + length + "^2";
    case OutputUnit::None:
      break;
  }
  return std::string();
}

} // namespace pcurv

#endif
