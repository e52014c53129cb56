/**
 * @file CurvatureArrays.h
 * @brief The filter's output arrays and the core's view of them
 * (pcurv::CurvatureBuffers): private to vtkPrincipalCurvatureEstimation.
 */
#ifndef CurvatureArrays_h
#define CurvatureArrays_h

#include "Estimation/CurvatureOutputs.h"
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

  CurvatureArrays(vtkIdType n, bool adjusted, bool standardError, bool display, bool single)
    : Single(single)
  {
    pcurv::CurvatureBuffers& b = this->Buffers;
    b.Minimum = this->AddReal("Minimum_Curvature", 1, n);
    b.Maximum = this->AddReal("Maximum_Curvature", 1, n);
    b.Mean = this->AddReal("Mean_Curvature", 1, n);
    b.Gauss = this->AddReal("Gauss_Curvature", 1, n);
    b.MinimumDirection = this->AddReal("Minimum_Curvature_Direction", 3, n);
    b.MaximumDirection = this->AddReal("Maximum_Curvature_Direction", 3, n);
    b.Valid = this->Add<vtkUnsignedCharArray>("Curvature_Valid", 1, n);
    b.NeighborCount = this->Add<vtkIntArray>("Neighbor_Count", 1, n, true);
    b.ValidDirections = this->Add<vtkIntArray>("Valid_Direction_Count", 1, n, true);
    b.SineFitRms = this->AddReal("Sine_Fit_RMS", 1, n, true);
    b.Surroundings = this->AddReal("Surroundings_Threshold", 1, n, true);
    b.PlaneDistance = this->AddReal("Plane_Distance_Threshold", 1, n, true);
    // With the dynamic adjustment only: the neighbor count it aimed at for
    // the point, to compare with Neighbor_Count.
    b.TargetCount =
      adjusted ? this->Add<vtkIntArray>("Target_Neighbor_Count", 1, n, true) : nullptr;
    b.ShapeIndex = this->AddReal("Shape_Index", 1, n);
    b.Curvedness = this->AddReal("Curvedness", 1, n);
    // For display; derived from Mean_Curvature, so left out (and not
    // computed) with the diagnostics when the output is to be small.
    b.ClippedMean = display ? this->AddReal("Mean_Curvature_Clipped", 1, n) : nullptr;
    // With the fits that give one: the standard error of the curvatures.
    b.StandardError =
      standardError ? this->AddReal("Curvature_Standard_Error", 1, n, true) : nullptr;
    // With the same fits: 1 where the curvatures are known to a third of
    // themselves, or precisely near zero (not a diagnostic: what a user
    // filters by).
    b.Trusted =
      standardError ? this->Add<vtkUnsignedCharArray>("Curvature_Trusted", 1, n) : nullptr;
    // With the same fits: the shape class (pcurv::ShapeClass), which needs
    // the standard error; Shape_Class_Names in the field data names them.
    b.ShapeClass =
      standardError ? this->Add<vtkUnsignedCharArray>(pcurv::ShapeClassArrayName, 1, n) : nullptr;
    // With the same fits: the normal their directions are tangent to.
    b.FittedNormal = standardError ? this->AddReal("Fitted_Normal", 3, n) : nullptr;
    // With the same fits: the points moved onto their neighbors' surface,
    // and every point's distance to it.
    b.Outlier = standardError ? this->Add<vtkUnsignedCharArray>("Outlier", 1, n) : nullptr;
    b.SurfaceDistance = standardError ? this->AddReal("Surface_Distance", 1, n, true) : nullptr;
  }

  /// A float or double array (Single), as the core's buffer.
  pcurv::RealBuffer AddReal(const char* name,
    int components,
    vtkIdType tuples,
    bool diagnostic = false)
  {
    pcurv::RealBuffer buffer;
    this->InOrder.emplace_back(
      NewRealArray(name, components, tuples, this->Single, buffer), diagnostic);
    return buffer;
  }

  template<typename ArrayT>
  typename ArrayT::ValueType* Add(const char* name,
    int components,
    vtkIdType tuples,
    bool diagnostic = false)
  {
    auto array = NewArray<ArrayT>(name, components, tuples);
    this->InOrder.emplace_back(array, diagnostic);
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
