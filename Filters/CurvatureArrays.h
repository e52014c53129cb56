/**
 * @file CurvatureArrays.h
 * @brief The filter's output arrays and the core's view of them
 * (pcurv::CurvatureBuffers): private to vtkPrincipalCurvatureEstimation.
 */
#ifndef CurvatureArrays_h
#define CurvatureArrays_h

#include "Estimation/CurvatureOutputs.h"
#include "Estimation/OutputTable.h"
#include "Estimation/ShapeClass.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <utility>
#include <vector>

namespace pcurv
{
namespace output
{

template<typename ArrayT>
vtkSmartPointer<ArrayT> NewArray(const char* name, int components, vtkIdType tuples)
{
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  return array;
}

/// A float (`single`) or double array, and the core's buffer on it.
inline vtkSmartPointer<vtkDataArray> NewRealArray(const char* name,
  int components,
  vtkIdType tuples,
  bool single,
  pcurv::RealBuffer& buffer)
{
  if (single)
  {
    auto array = NewArray<vtkFloatArray>(name, components, tuples);
    buffer = pcurv::RealBuffer(array->GetPointer(0));
    return array;
  }
  auto array = NewArray<vtkDoubleArray>(name, components, tuples);
  buffer = pcurv::RealBuffer(array->GetPointer(0));
  return array;
}

/// The output arrays, and the core's view of them: the real ones float
/// with `single` (the core rounds each value once as it writes it: no
/// double copy of the output is ever held), double otherwise.
struct CurvatureArrays
{
  /// Each array, and whether it is a diagnostic one.
  std::vector<std::pair<vtkSmartPointer<vtkDataArray>, bool>> InOrder;
  pcurv::CurvatureBuffers Buffers;
  bool Single = false;
  vtkIdType Tuples = 0;
  bool Adjusted = false;
  bool WithStandardError = false;
  bool ForDisplay = false;

  CurvatureArrays(vtkIdType n, bool adjusted, bool standardError, bool display, bool single)
    : Single(single)
    , Tuples(n)
    , Adjusted(adjusted)
    , WithStandardError(standardError)
    , ForDisplay(display)
  {
    pcurv::CurvatureBuffers& b = this->Buffers;
    using pcurv::Output;
    b.Minimum = this->AddReal(Output::MinimumCurvature);
    b.Maximum = this->AddReal(Output::MaximumCurvature);
    b.Mean = this->AddReal(Output::MeanCurvature);
    b.Gauss = this->AddReal(Output::GaussCurvature);
    b.MinimumDirection = this->AddReal(Output::MinimumDirection);
    b.MaximumDirection = this->AddReal(Output::MaximumDirection);
    b.Valid = this->Add<vtkUnsignedCharArray>(Output::Valid);
    b.NeighborCount = this->Add<vtkIntArray>(Output::NeighborCount);
    b.ValidDirections = this->Add<vtkIntArray>(Output::ValidDirections);
    b.SineFitRms = this->AddReal(Output::SineFitRms);
    b.Surroundings = this->AddReal(Output::Surroundings);
    b.PlaneDistance = this->AddReal(Output::PlaneDistance);
    b.TargetCount = this->Add<vtkIntArray>(Output::TargetCount);
    b.ShapeIndex = this->AddReal(Output::ShapeIndex);
    b.Curvedness = this->AddReal(Output::Curvedness);
    b.ClippedMean = this->AddReal(Output::ClippedMean);
    b.StandardError = this->AddReal(Output::StandardError);
    b.Trusted = this->Add<vtkUnsignedCharArray>(Output::Trusted);
    b.ShapeClass = this->Add<vtkUnsignedCharArray>(Output::ShapeClass);
    b.FittedNormal = this->AddReal(Output::FittedNormal);
    b.Outlier = this->Add<vtkUnsignedCharArray>(Output::Outlier);
    b.SurfaceDistance = this->AddReal(Output::SurfaceDistance);
  }

  /// Whether the output of this run has the array (its table row's
  /// condition).
  bool Written(const pcurv::OutputArray& row) const
  {
    switch (row.Condition)
    {
      case pcurv::OutputCondition::DynamicAdjustment:
        return this->Adjusted;
      case pcurv::OutputCondition::Display:
        return this->ForDisplay;
      case pcurv::OutputCondition::StandardError:
        return this->WithStandardError;
      case pcurv::OutputCondition::Always:
        break;
    }
    return true;
  }

  /// A float or double array (Single), as the core's buffer; null when the
  /// run does not write it.
  pcurv::RealBuffer AddReal(pcurv::Output id)
  {
    const pcurv::OutputArray& row = pcurv::OutputOf(id);
    pcurv::RealBuffer buffer;
    if (this->Written(row))
    {
      this->InOrder.emplace_back(
        NewRealArray(row.Name, row.Components, this->Tuples, this->Single, buffer), row.Diagnostic);
    }
    return buffer;
  }

  /// An array of the table's integer type, as the core's buffer; null when
  /// the run does not write it.
  template<typename ArrayT>
  typename ArrayT::ValueType* Add(pcurv::Output id)
  {
    const pcurv::OutputArray& row = pcurv::OutputOf(id);
    if (!this->Written(row))
    {
      return nullptr;
    }
    auto array = NewArray<ArrayT>(row.Name, row.Components, this->Tuples);
    this->InOrder.emplace_back(array, row.Diagnostic);
    return array->GetPointer(0);
  }

  /// Adds the arrays to `pd`, the diagnostic ones only with `diagnostics`.
  void AddTo(vtkPointData* pd, bool diagnostics) const
  {
    for (const auto& entry : this->InOrder)
    {
      if (!entry.second || diagnostics)
      {
        pd->AddArray(entry.first);
      }
    }
  }
};

} // namespace output
} // namespace pcurv

#endif
