/**
 * @file AnalyticClouds.h
 * @brief vtkPolyData clouds from AnalyticSurfaces.h, and error measures of
 * the filter's output against the exact values (tests, demo, benchmark).
 */
#ifndef AnalyticClouds_h
#define AnalyticClouds_h

#include "AnalyticSurfaces.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace pcurv
{
namespace testing
{

/// Points with exact normals (active "Normals") and exact curvature arrays
/// (Exact_Minimum_Curvature, Exact_Maximum_Curvature,
/// Exact_Maximum_Direction, Boundary_Distance).
inline vtkSmartPointer<vtkPolyData> MakeCloud(const std::vector<SurfaceSample>& samples)
{
  const vtkIdType n = static_cast<vtkIdType>(samples.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  auto array = [n](const char* name, int components)
  {
    auto a = vtkSmartPointer<vtkDoubleArray>::New();
    a->SetName(name);
    a->SetNumberOfComponents(components);
    a->SetNumberOfTuples(n);
    return a;
  };
  auto normals = array("Normals", 3);
  auto kMin = array("Exact_Minimum_Curvature", 1);
  auto kMax = array("Exact_Maximum_Curvature", 1);
  auto dMax = array("Exact_Maximum_Direction", 3);
  auto boundary = array("Boundary_Distance", 1);
  auto ids = array("Sample_Id", 1); // to match points across runs and splits
  for (vtkIdType i = 0; i < n; ++i)
  {
    const SurfaceSample& s = samples[i];
    points->SetPoint(i, s.Point.data());
    normals->SetTuple(i, s.Normal.data());
    kMin->SetValue(i, s.MinimumCurvature);
    kMax->SetValue(i, s.MaximumCurvature);
    dMax->SetTuple(i, s.MaximumDirection.data());
    boundary->SetValue(i, std::min(s.BoundaryDistance, 1e300));
    ids->SetValue(i, static_cast<double>(i));
  }
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(points);
  // One vertex cell per point: it renders, and ParaView's redistribution
  // (which moves cells) can split it among processes.
  vtkNew<vtkCellArray> vertices;
  vertices->AllocateExact(n, n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    vertices->InsertNextCell(1, &i);
  }
  cloud->SetVerts(vertices);
  cloud->GetPointData()->SetNormals(normals);
  for (vtkDataArray* a : { static_cast<vtkDataArray*>(kMin),
         static_cast<vtkDataArray*>(kMax),
         static_cast<vtkDataArray*>(dMax),
         static_cast<vtkDataArray*>(boundary) })
  {
    cloud->GetPointData()->AddArray(a);
  }
  return cloud;
}

/// Errors of an estimate against the exact values, over the points whose
/// neighborhood lies inside the surface (boundary distance above the
/// surroundings-threshold used there).
struct CurvatureErrors
{
  double MeanMinimumError = 0.0;   ///< mean |k_min - exact| / max |exact k|
  double MeanMaximumError = 0.0;   ///< mean |k_max - exact| / max |exact k|
  double MedianAngleDegrees = 0.0; ///< max direction, where k_max - k_min is clearly non-zero
  double UnestimatedFraction = 0.0;
  double LargestExactCurvature = 0.0;
  vtkIdType Evaluated = 0;
  vtkIdType DirectionsEvaluated = 0;
};

inline CurvatureErrors MeasureErrors(vtkPolyData* output)
{
  CurvatureErrors errors;
  vtkPointData* pd = output->GetPointData();
  vtkDataArray* kMin = pd->GetArray("Minimum_Curvature");
  vtkDataArray* kMax = pd->GetArray("Maximum_Curvature");
  vtkDataArray* dMax = pd->GetArray("Maximum_Curvature_Direction");
  vtkDataArray* exactMin = pd->GetArray("Exact_Minimum_Curvature");
  vtkDataArray* exactMax = pd->GetArray("Exact_Maximum_Curvature");
  vtkDataArray* exactDirection = pd->GetArray("Exact_Maximum_Direction");
  vtkDataArray* boundary = pd->GetArray("Boundary_Distance");
  vtkDataArray* radius = pd->GetArray("Surroundings_Threshold");
  const vtkIdType n = output->GetNumberOfPoints();
  for (vtkIdType i = 0; i < n; ++i)
  {
    errors.LargestExactCurvature = std::max(errors.LargestExactCurvature,
      std::max(std::fabs(exactMin->GetTuple1(i)), std::fabs(exactMax->GetTuple1(i))));
  }
  const double scale = errors.LargestExactCurvature > 0.0 ? errors.LargestExactCurvature : 1.0;
  std::vector<double> angles;
  vtkIdType unestimated = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (boundary->GetTuple1(i) <= radius->GetTuple1(i))
    {
      continue;
    }
    ++errors.Evaluated;
    if (!std::isfinite(kMin->GetTuple1(i)))
    {
      ++unestimated;
      continue;
    }
    errors.MeanMinimumError += std::fabs(kMin->GetTuple1(i) - exactMin->GetTuple1(i));
    errors.MeanMaximumError += std::fabs(kMax->GetTuple1(i) - exactMax->GetTuple1(i));
    if (exactMax->GetTuple1(i) - exactMin->GetTuple1(i) > 0.1 * scale)
    {
      double a[3], b[3];
      dMax->GetTuple(i, a);
      exactDirection->GetTuple(i, b);
      const double cosine = std::fabs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
      angles.push_back(std::acos(std::min(1.0, cosine)) * 180.0 / Pi);
    }
  }
  const vtkIdType estimated = errors.Evaluated - unestimated;
  if (estimated > 0)
  {
    errors.MeanMinimumError /= estimated * scale;
    errors.MeanMaximumError /= estimated * scale;
  }
  errors.UnestimatedFraction =
    errors.Evaluated > 0 ? static_cast<double>(unestimated) / errors.Evaluated : 1.0;
  errors.DirectionsEvaluated = static_cast<vtkIdType>(angles.size());
  if (!angles.empty())
  {
    std::nth_element(angles.begin(), angles.begin() + angles.size() / 2, angles.end());
    errors.MedianAngleDegrees = angles[angles.size() / 2];
  }
  return errors;
}

} // namespace testing
} // namespace pcurv

#endif
