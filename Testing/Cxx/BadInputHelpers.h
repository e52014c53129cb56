/**
 * @file BadInputHelpers.h
 * @brief What the bad-input tests (TestBadInput*.cxx, one sub-test per row
 * of docs/bad-input.md's table) share: one run of the filter with every
 * error and warning it raised, the checks that nothing else in the output
 * is harmed (the input's points and arrays are passed through unchanged),
 * and the clouds they start from.
 *
 * Every output is also checked against the output contract: a flagged point
 * has Curvature_Valid = 0, NaN curvatures and zero directions; an estimated
 * point has finite curvatures, max >= min, mean and Gauss consistent, and
 * unit principal directions orthogonal to each other and to its normal
 * (with OrientedCircles to Fitted_Normal instead: a unit vector on the
 * normal's side, zero at a flagged point).
 */
#ifndef BadInputHelpers_h
#define BadInputHelpers_h

#include "AnalyticClouds.h"
#include "TestChecks.h"
#include "vtkPrincipalCurvatureEstimation.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace pcurv
{
namespace testing
{
namespace badinput
{
inline const double NaN = std::numeric_limits<double>::quiet_NaN();
inline const double Inf = std::numeric_limits<double>::infinity();

using Configure = std::function<void(vtkPrincipalCurvatureEstimation*)>;

/// What one run of the filter gave: its output and every error and warning
/// it (or its executive) raised.
struct Outcome
{
  vtkSmartPointer<vtkPolyData> Output;
  int Errors = 0;
  int Warnings = 0;
  std::vector<std::string> Messages;
  vtkIdType Unestimated = 0;
  double UsedSurroundingsThreshold = 0.0;

  vtkDataArray* Array(const char* name) const
  {
    return this->Output->GetPointData()->GetArray(name);
  }
  double Value(const char* name, vtkIdType i) const
  {
    vtkDataArray* array = this->Array(name);
    return array ? array->GetComponent(i, 0) : NaN;
  }
  int Valid(vtkIdType i) const { return static_cast<int>(this->Value("Curvature_Valid", i)); }
  /// True when some error or warning contains `text`.
  bool Saw(const char* text) const
  {
    for (const std::string& message : this->Messages)
    {
      if (message.find(text) != std::string::npos)
      {
        return true;
      }
    }
    return false;
  }
  vtkIdType Points() const { return this->Output->GetNumberOfPoints(); }
};

inline Outcome Run(vtkDataObject* input, const Configure& configure = nullptr)
{
  Outcome outcome;
  vtkNew<vtkPrincipalCurvatureEstimation> filter;
  vtkNew<vtkCallbackCommand> callback;
  callback->SetClientData(&outcome);
  callback->SetCallback(
    [](vtkObject*, unsigned long event, void* client, void* data)
    {
      auto* o = static_cast<Outcome*>(client);
      (event == vtkCommand::ErrorEvent ? o->Errors : o->Warnings)++;
      o->Messages.emplace_back(data ? static_cast<const char*>(data) : "");
    });
  filter->AddObserver(vtkCommand::ErrorEvent, callback);
  filter->AddObserver(vtkCommand::WarningEvent, callback);
  filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, callback);
  if (configure)
  {
    configure(filter);
  }
  filter->SetInputData(input);
  filter->Update();
  outcome.Output = vtkSmartPointer<vtkPolyData>::New();
  outcome.Output->ShallowCopy(filter->GetOutput());
  outcome.Unestimated = filter->GetNumberOfUnestimatedPoints();
  outcome.UsedSurroundingsThreshold = filter->GetUsedSurroundingsThreshold();
  return outcome;
}

/// The three ways of choosing neighborhoods, each with its own code path
/// for the radius: automatic radius, k nearest, dynamic adjustment.
struct NeighborhoodMode
{
  const char* Name;
  Configure Set;
};
inline const NeighborhoodMode Modes[] = {
  { "automatic radius", nullptr },
  { "k nearest", [](vtkPrincipalCurvatureEstimation* f) { f->SetNeighborhoodModeToKNearest(); } },
  { "dynamic adjustment", [](vtkPrincipalCurvatureEstimation* f) { f->DynamicAdjustmentOn(); } },
};

inline std::string Label(const std::string& row, const char* what)
{
  return row + ": " + what;
}

inline bool SameValue(double a, double b)
{
  return a == b || (std::isnan(a) && std::isnan(b));
}

/// Same type, shape and values (NaN equals NaN) over the first `count`
/// tuples (all when negative); within `tolerance` when it is not 0.
inline bool SameArray(vtkDataArray* a,
  vtkDataArray* b,
  vtkIdType count = -1,
  double tolerance = 0.0)
{
  if (!a || !b || a->GetDataType() != b->GetDataType() ||
    a->GetNumberOfComponents() != b->GetNumberOfComponents())
  {
    return false;
  }
  if (count < 0)
  {
    if (a->GetNumberOfTuples() != b->GetNumberOfTuples())
    {
      return false;
    }
    count = a->GetNumberOfTuples();
  }
  if (a->GetNumberOfTuples() < count || b->GetNumberOfTuples() < count)
  {
    return false;
  }
  const int c = a->GetNumberOfComponents();
  for (vtkIdType i = 0; i < count; ++i)
  {
    for (int k = 0; k < c; ++k)
    {
      const double x = a->GetComponent(i, k), y = b->GetComponent(i, k);
      if (!SameValue(x, y) && !(tolerance > 0.0 && std::fabs(x - y) <= tolerance))
      {
        return false;
      }
    }
  }
  return true;
}

/// The input's points and point-data arrays are in the output unchanged.
inline void CheckPassedThrough(Checks& checks,
  const std::string& row,
  vtkPointSet* input,
  const Outcome& o)
{
  checks.Equal(Label(row, "as many output points as input points").c_str(),
    o.Points(),
    input->GetNumberOfPoints());
  if (input->GetPoints() && o.Output->GetPoints())
  {
    checks.True(Label(row, "input points passed through unchanged").c_str(),
      SameArray(input->GetPoints()->GetData(), o.Output->GetPoints()->GetData()));
  }
  vtkPointData* in = input->GetPointData();
  int unchanged = 0;
  for (int a = 0; a < in->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = in->GetArray(a);
    unchanged += array && array->GetName() &&
      SameArray(array, o.Output->GetPointData()->GetArray(array->GetName()));
  }
  checks.Equal(Label(row, "input point arrays passed through unchanged").c_str(),
    unchanged,
    in->GetNumberOfArrays());
}

/// The output contract at every point (see the top of this file); `normals`
/// are the input normals used (skipped when null).
inline void CheckContract(Checks& checks,
  const std::string& row,
  const Outcome& o,
  vtkDataArray* normals)
{
  vtkDataArray* dMin = o.Array("Minimum_Curvature_Direction");
  vtkDataArray* dMax = o.Array("Maximum_Curvature_Direction");
  if (!dMin || !dMax || !o.Array("Curvature_Valid"))
  {
    checks.True(Label(row, "output has the curvature arrays").c_str(), false);
    return;
  }
  auto dot = [](const double* a, const double* b)
  { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  // OrientedCircles: the directions are tangent to the fitted surface's
  // normal, a unit vector on the given normal's side.
  vtkDataArray* fitted = o.Array("Fitted_Normal");
  vtkIdType broken = 0, flagged = 0;
  for (vtkIdType i = 0; i < o.Points(); ++i)
  {
    const double kMin = o.Value("Minimum_Curvature", i), kMax = o.Value("Maximum_Curvature", i);
    const double mean = o.Value("Mean_Curvature", i), gauss = o.Value("Gauss_Curvature", i);
    double a[3], b[3];
    dMin->GetTuple(i, a);
    dMax->GetTuple(i, b);
    bool ok = true;
    if (o.Valid(i) == 0)
    {
      ++flagged;
      ok = std::isnan(kMin) && std::isnan(kMax) && std::isnan(mean) && std::isnan(gauss) &&
        std::isnan(o.Value("Sine_Fit_RMS", i)) && dot(a, a) == 0.0 && dot(b, b) == 0.0;
      if (ok && fitted)
      {
        double f[3];
        fitted->GetTuple(i, f);
        ok = dot(f, f) == 0.0;
      }
    }
    else
    {
      const double size = std::max(std::fabs(kMin), std::fabs(kMax));
      ok = o.Valid(i) == 1 && std::isfinite(kMin) && std::isfinite(kMax) && kMax >= kMin &&
        std::fabs(mean - 0.5 * (kMin + kMax)) <= 1e-12 * size &&
        // Gauss is +-Inf where kMin kMax overflows (|k| beyond 1e154).
        (gauss == kMin * kMax || std::fabs(gauss - kMin * kMax) <= 1e-12 * size * size) &&
        std::fabs(dot(a, a) - 1) < 1e-9 && std::fabs(dot(b, b) - 1) < 1e-9 &&
        std::fabs(dot(a, b)) < 1e-9 && o.Value("Valid_Direction_Count", i) >= 3 &&
        o.Value("Valid_Direction_Count", i) <= 16 && o.Value("Neighbor_Count", i) >= 3 &&
        std::isfinite(o.Value("Sine_Fit_RMS", i));
      double f[3] = { 0.0, 0.0, 0.0 };
      if (ok && fitted)
      {
        fitted->GetTuple(i, f);
        ok = std::fabs(dot(f, f) - 1) < 1e-9 && std::fabs(dot(a, f)) < 1e-9 &&
          std::fabs(dot(b, f)) < 1e-9;
      }
      // An outlier has the results of the surface point nearest to it,
      // fitted normal included: on that point's side, not its own.
      const bool outlier = o.Array("Outlier") && o.Value("Outlier", i) == 1;
      if (ok && normals && !outlier)
      {
        double n[3];
        normals->GetTuple(i, n);
        const double length = std::sqrt(dot(n, n));
        ok = fitted ? dot(f, n) > 0.0
                    : std::fabs(dot(a, n)) < 1e-9 * length && std::fabs(dot(b, n)) < 1e-9 * length;
      }
    }
    if (!ok && broken++ < 3)
    {
      std::printf("   point %lld breaks the contract: valid %d k %g %g\n",
        static_cast<long long>(i),
        o.Valid(i),
        kMin,
        kMax);
    }
  }
  checks.Equal(Label(row, "output contract holds at every point").c_str(), broken, 0);
  checks.Equal(
    Label(row, "NumberOfUnestimatedPoints = flagged points").c_str(), o.Unestimated, flagged);
  // The counts by reason in the field data add up to the flagged points.
  vtkIdType byReason = 0;
  vtkFieldData* field = o.Output->GetFieldData();
  for (int a = 0; a < field->GetNumberOfArrays(); ++a)
  {
    const std::string name = field->GetArrayName(a) ? field->GetArrayName(a) : "";
    if (name.rfind("Unestimated_", 0) == 0 && name != "Unestimated_Points")
    {
      byReason += static_cast<vtkIdType>(field->GetArray(a)->GetTuple1(0));
    }
  }
  vtkDataArray* all = field->GetArray("Unestimated_Points");
  checks.True(Label(row, "field data: Unestimated_Points = flagged points = sum by reason").c_str(),
    all && static_cast<vtkIdType>(all->GetTuple1(0)) == flagged && byReason == flagged);
  // One warning with the count when most points are flagged, none otherwise
  // (a few flagged points are normal on real scans).
  const bool most = 2 * flagged > o.Points();
  checks.Equal(Label(row, "one warning exactly when most points are flagged").c_str(),
    o.Warnings,
    most ? 1 : 0);
  if (most)
  {
    const std::string count = std::to_string(flagged) + " of " + std::to_string(o.Points());
    checks.True(Label(row, "the warning gives the count").c_str(), o.Saw(count.c_str()));
  }
}

inline vtkSmartPointer<vtkPolyData> Torus(int n = 8000)
{
  return MakeCloud(Sample(pcurv::testing::Torus(3.0, 1.0), n, 77));
}

/// Points and normals only (no exact arrays, no cells), doubles, with
/// `extra` points (x y z nx ny nz) appended at the end.
inline vtkSmartPointer<vtkPolyData> WithExtraPoints(vtkPolyData* cloud,
  const std::vector<std::array<double, 6>>& extra)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->DeepCopy(cloud->GetPoints());
  vtkNew<vtkDoubleArray> normals;
  normals->DeepCopy(cloud->GetPointData()->GetNormals());
  normals->SetName("Normals");
  for (const auto& e : extra)
  {
    points->InsertNextPoint(e[0], e[1], e[2]);
    normals->InsertNextTuple3(e[3], e[4], e[5]);
  }
  auto fresh = vtkSmartPointer<vtkPolyData>::New();
  fresh->SetPoints(points);
  fresh->GetPointData()->SetNormals(normals);
  return fresh;
}

inline vtkSmartPointer<vtkPolyData> PointsOnly(vtkPolyData* cloud)
{
  return WithExtraPoints(cloud, {});
}

/// Largest |k - exact| over the estimated points (both curvatures), and
/// how many points are estimated.
inline double LargestError(const Outcome& o, double exactMin, double exactMax, vtkIdType* estimated)
{
  double worst = 0.0;
  *estimated = 0;
  for (vtkIdType i = 0; i < o.Points(); ++i)
  {
    if (o.Valid(i) == 1)
    {
      ++*estimated;
      worst = std::max({ worst,
        std::fabs(o.Value("Minimum_Curvature", i) - exactMin),
        std::fabs(o.Value("Maximum_Curvature", i) - exactMax) });
    }
  }
  return worst;
}

/// Names the sub-test that runs next (a crash or hang shows after it).
inline void Row(const std::string& name)
{
  std::printf("-- %s\n", name.c_str());
  std::fflush(stdout);
}

} // namespace badinput
} // namespace testing
} // namespace pcurv

#endif
