/**
 * @file OutputTable.h
 * @brief The one table of the curvature filter's output arrays: name,
 * value type, components, unit, when each is written and what it is. The
 * filter makes its arrays from it, ParaView's GUI titles color bars with
 * its units, and the OutputsAgree test checks docs/output-arrays.md and the
 * help page against it. No VTK.
 *
 * Adding an output: a row here (in the order the arrays appear), its
 * buffer in CurvatureOutputs.h, its value in ResultStore.cxx, and its row
 * in docs/output-arrays.md, which the test then requires.
 */
#ifndef OutputTable_h
#define OutputTable_h

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

/// The row of an output.
const OutputArray& OutputOf(Output id);

/// The row named `name`, or null.
const OutputArray* FindOutput(const std::string& name);

/// The unit as text, from the input's length unit ("foot"; empty: "length
/// unit"): "1/foot", "1/foot^2", "foot", or "" for OutputUnit::None.
std::string UnitText(OutputUnit unit, const std::string& lengthUnit);

} // namespace pcurv

#endif
