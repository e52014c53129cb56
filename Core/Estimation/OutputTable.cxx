#include "Estimation/OutputTable.h"

#include "Estimation/ShapeClass.h"

#include <array>

namespace pcurv
{
namespace
{
using V = OutputValue;
using U = OutputUnit;
using C = OutputCondition;

constexpr std::array<OutputArray, static_cast<std::size_t>(Output::Count)> Table = { {
  { Output::MinimumCurvature,
    "Minimum_Curvature",
    V::Real,
    1,
    U::PerLength,
    C::Always,
    false,
    "the smaller principal curvature" },
  { Output::MaximumCurvature,
    "Maximum_Curvature",
    V::Real,
    1,
    U::PerLength,
    C::Always,
    false,
    "the larger principal curvature" },
  { Output::MeanCurvature,
    "Mean_Curvature",
    V::Real,
    1,
    U::PerLength,
    C::Always,
    false,
    "the mean of the principal curvatures" },
  { Output::GaussCurvature,
    "Gauss_Curvature",
    V::Real,
    1,
    U::PerLengthSquared,
    C::Always,
    false,
    "the product of the principal curvatures" },
  { Output::MinimumDirection,
    "Minimum_Curvature_Direction",
    V::Real,
    3,
    U::None,
    C::Always,
    false,
    "the unit direction of the smaller principal curvature" },
  { Output::MaximumDirection,
    "Maximum_Curvature_Direction",
    V::Real,
    3,
    U::None,
    C::Always,
    false,
    "the unit direction of the larger principal curvature" },
  { Output::Valid,
    "Curvature_Valid",
    V::UnsignedChar,
    1,
    U::None,
    C::Always,
    false,
    "1 where estimated, 0 where not" },
  { Output::NeighborCount,
    "Neighbor_Count",
    V::Int,
    1,
    U::None,
    C::Always,
    true,
    "the neighbors the estimate used" },
  { Output::ValidDirections,
    "Valid_Direction_Count",
    V::Int,
    1,
    U::None,
    C::Always,
    true,
    "the half planes with a valid circle fit" },
  { Output::SineFitRms,
    "Sine_Fit_RMS",
    V::Real,
    1,
    U::PerLength,
    C::Always,
    true,
    "how far the normal curvatures are from Euler's formula" },
  { Output::Surroundings,
    "Surroundings_Threshold",
    V::Real,
    1,
    U::Length,
    C::Always,
    true,
    "the neighborhood radius at the point" },
  { Output::PlaneDistance,
    "Plane_Distance_Threshold",
    V::Real,
    1,
    U::Length,
    C::Always,
    true,
    "the half planes' distance threshold p" },
  { Output::TargetCount,
    "Target_Neighbor_Count",
    V::Int,
    1,
    U::None,
    C::DynamicAdjustment,
    true,
    "the neighbor count the dynamic adjustment aimed at" },
  { Output::ShapeIndex,
    "Shape_Index",
    V::Real,
    1,
    U::None,
    C::Always,
    false,
    "Koenderink and van Doorn's shape index, in [-1, 1]" },
  { Output::Curvedness,
    "Curvedness",
    V::Real,
    1,
    U::PerLength,
    C::Always,
    false,
    "how much the surface bends, whatever its shape" },
  { Output::ClippedMean,
    "Mean_Curvature_Clipped",
    V::Real,
    1,
    U::PerLength,
    C::Display,
    false,
    "the mean curvature clamped for display (the active scalars)" },
  { Output::StandardError,
    "Curvature_Standard_Error",
    V::Real,
    1,
    U::PerLength,
    C::StandardError,
    true,
    "the error to expect of the principal curvatures" },
  { Output::Trusted,
    "Curvature_Trusted",
    V::UnsignedChar,
    1,
    U::None,
    C::StandardError,
    false,
    "1 where the curvatures are known to what they show" },
  { Output::ShapeClass,
    ShapeClassArrayName,
    V::UnsignedChar,
    1,
    U::None,
    C::StandardError,
    false,
    "the point's shape: undetermined, flat, dome, cup, ridge, valley, saddle" },
  { Output::FittedNormal,
    "Fitted_Normal",
    V::Real,
    3,
    U::None,
    C::StandardError,
    false,
    "the unit normal of the fitted surface" },
  { Output::Outlier,
    "Outlier",
    V::UnsignedChar,
    1,
    U::None,
    C::StandardError,
    false,
    "1 where the point lies far off its neighbors' surface" },
  { Output::SurfaceDistance,
    "Surface_Distance",
    V::Real,
    1,
    U::Length,
    C::StandardError,
    true,
    "the point's distance to its neighbors' surface" },
} };

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
} // namespace

const OutputArray& OutputOf(Output id)
{
  return Table[static_cast<std::size_t>(id)];
}

const OutputArray* FindOutput(const std::string& name)
{
  for (const OutputArray& row : Table)
  {
    if (name == row.Name)
    {
      return &row;
    }
  }
  return nullptr;
}

std::string UnitText(OutputUnit unit, const std::string& lengthUnit)
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
