// Tests of vtkPrincipalCurvatureEstimation on analytic clouds with exact
// normals and curvatures, in every fit mode, plus threads, signs, error
// paths and flagged points.
#include "AnalyticClouds.h"
#include "TestChecks.h"
#include "vtkPrincipalCurvatureEstimation.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace
{
using namespace pcurv::testing;

/// Counts error and warning events of an algorithm, so that expected
/// errors are checked rather than printed.
class EventCounter
{
public:
  explicit EventCounter(vtkObject* observed)
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback(
      [](vtkObject*, unsigned long event, void* client, void* data)
      {
        auto* self = static_cast<EventCounter*>(client);
        (event == vtkCommand::ErrorEvent ? self->Errors : self->Warnings)++;
        self->LastMessage = data ? static_cast<const char*>(data) : "";
      });
    observed->AddObserver(vtkCommand::ErrorEvent, this->Callback);
    observed->AddObserver(vtkCommand::WarningEvent, this->Callback);
  }
  int Errors = 0;
  int Warnings = 0;
  std::string LastMessage;

private:
  vtkNew<vtkCallbackCommand> Callback;
};

/// The value of a one-tuple field data array of the output (-1 if none).
vtkIdType FieldCount(vtkPolyData* output, const char* name)
{
  vtkDataArray* array = output->GetFieldData()->GetArray(name);
  return array && array->GetNumberOfTuples() == 1 ? static_cast<vtkIdType>(array->GetTuple1(0))
                                                  : -1;
}

vtkSmartPointer<vtkPolyData> Run(vtkDataObject* input, int mode, int threads = 0)
{
  vtkNew<vtkPrincipalCurvatureEstimation> filter;
  filter->SetInputData(input);
  filter->SetFitMode(mode);
  filter->SetNumberOfThreads(threads);
  filter->Update();
  auto output = vtkSmartPointer<vtkPolyData>::New();
  output->ShallowCopy(filter->GetOutput());
  return output;
}

const char* ModeName(int mode)
{
  static const char* names[] = { "Previous", "New01", "New02" };
  return names[mode];
}

/// Done-when of the foundation: mean |k - k_true| below 2 % of the largest
/// |k| and a median max-direction error below 2 degrees, in every mode.
void TestAccuracyOnShapes(Checks& checks)
{
  const Surface shapes[] = { Sphere(1.0),
    Cylinder(1.0, 6.0),
    Torus(3.0, 1.0),
    Saddle(1.0, 1.0),
    Ellipsoid(3.0, 2.0, 1.5),
    Plane(1.0) };
  for (const Surface& shape : shapes)
  {
    auto cloud = MakeCloud(Sample(shape, 20000, 42));
    for (int mode = 0; mode < 3; ++mode)
    {
      auto output = Run(cloud, mode);
      const CurvatureErrors e = MeasureErrors(output);
      std::printf("%-10s %-8s k_min %.5f k_max %.5f angle %.3f deg unestimated %.4f (%lld pts)\n",
        shape.Name.c_str(),
        ModeName(mode),
        e.MeanMinimumError,
        e.MeanMaximumError,
        e.MedianAngleDegrees,
        e.UnestimatedFraction,
        static_cast<long long>(e.Evaluated));
      char label[128];
      std::snprintf(
        label, sizeof(label), "%s %s evaluated points", shape.Name.c_str(), ModeName(mode));
      checks.True(label, e.Evaluated > 5000);
      std::snprintf(label, sizeof(label), "%s %s unestimated", shape.Name.c_str(), ModeName(mode));
      checks.Below(label, e.UnestimatedFraction, 1e-3);
      if (shape.Name == "plane")
      {
        vtkDataArray* kMin = output->GetPointData()->GetArray("Minimum_Curvature");
        vtkDataArray* kMax = output->GetPointData()->GetArray("Maximum_Curvature");
        double largest = 0.0;
        for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
        {
          largest =
            std::max({ largest, std::fabs(kMin->GetTuple1(i)), std::fabs(kMax->GetTuple1(i)) });
        }
        std::snprintf(label, sizeof(label), "plane %s largest |k|", ModeName(mode));
        checks.Below(label, largest, 1e-9);
        continue;
      }
      std::snprintf(
        label, sizeof(label), "%s %s mean k_min error", shape.Name.c_str(), ModeName(mode));
      checks.Below(label, e.MeanMinimumError, 0.02);
      std::snprintf(
        label, sizeof(label), "%s %s mean k_max error", shape.Name.c_str(), ModeName(mode));
      checks.Below(label, e.MeanMaximumError, 0.02);
      if (e.DirectionsEvaluated > 0)
      {
        std::snprintf(
          label, sizeof(label), "%s %s median angle", shape.Name.c_str(), ModeName(mode));
        checks.Below(label, e.MedianAngleDegrees, 2.0);
      }
    }
  }
}

/// Output arrays: names, types, unit directions orthogonal to the normal
/// and to each other, max >= min, mean and Gauss consistent, input arrays
/// passed, vertex cells present.
/// The curvatures and directions every estimate outputs.
const char* const CurvatureArrayNames[] = { "Minimum_Curvature",
  "Maximum_Curvature",
  "Mean_Curvature",
  "Gauss_Curvature",
  "Minimum_Curvature_Direction",
  "Maximum_Curvature_Direction" };

void TestOutputContract(Checks& checks)
{
  auto cloud = MakeCloud(Sample(Torus(3.0, 1.0), 20000, 5));
  auto output = Run(cloud, vtkPrincipalCurvatureEstimation::NEW02);
  vtkPointData* pd = output->GetPointData();
  for (const char* name : CurvatureArrayNames)
  {
    checks.True(name, pd->GetArray(name) != nullptr);
  }
  for (const char* name : { "Curvature_Valid",
         "Neighbor_Count",
         "Valid_Direction_Count",
         "Sine_Fit_RMS",
         "Surroundings_Threshold",
         "Plane_Distance_Threshold",
         "Normals",
         "Exact_Minimum_Curvature" })
  {
    checks.True(name, pd->GetArray(name) != nullptr);
  }
  checks.True("Mean_Curvature is double",
    vtkDoubleArray::SafeDownCast(pd->GetArray("Mean_Curvature")) != nullptr);
  checks.Equal("vertex cells", output->GetNumberOfVerts(), output->GetNumberOfPoints());
  vtkDataArray* kMin = pd->GetArray("Minimum_Curvature");
  vtkDataArray* kMax = pd->GetArray("Maximum_Curvature");
  vtkDataArray* mean = pd->GetArray("Mean_Curvature");
  vtkDataArray* gauss = pd->GetArray("Gauss_Curvature");
  vtkDataArray* dMin = pd->GetArray("Minimum_Curvature_Direction");
  vtkDataArray* dMax = pd->GetArray("Maximum_Curvature_Direction");
  vtkDataArray* normals = pd->GetArray("Normals");
  vtkDataArray* count = pd->GetArray("Neighbor_Count");
  int bad = 0;
  double countSum = 0.0;
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3], n[3];
    dMin->GetTuple(i, a);
    dMax->GetTuple(i, b);
    normals->GetTuple(i, n);
    const double lo = kMin->GetTuple1(i), hi = kMax->GetTuple1(i);
    bad += !(hi >= lo);
    bad += std::fabs(mean->GetTuple1(i) - 0.5 * (lo + hi)) > 1e-12;
    bad += std::fabs(gauss->GetTuple1(i) - lo * hi) > 1e-12;
    bad += std::fabs(a[0] * a[0] + a[1] * a[1] + a[2] * a[2] - 1.0) > 1e-12;
    bad += std::fabs(b[0] * b[0] + b[1] * b[1] + b[2] * b[2] - 1.0) > 1e-12;
    bad += std::fabs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) > 1e-12;
    bad += std::fabs(a[0] * n[0] + a[1] * n[1] + a[2] * n[2]) > 1e-12;
    bad += std::fabs(b[0] * n[0] + b[1] * n[1] + b[2] * n[2]) > 1e-12;
    countSum += count->GetTuple1(i);
  }
  checks.Equal("points breaking the output contract", bad, 0);
  const double meanCount = countSum / output->GetNumberOfPoints();
  std::printf("automatic radius: mean neighbor count %.1f (target 375)\n", meanCount);
  checks.Near("automatic radius gives about 375 neighbors", meanCount, 375.0, 40.0);
  checks.True("paper fits: no Fitted_Normal (directions tangent to the given normal)",
    pd->GetArray("Fitted_Normal") == nullptr);

  // OrientedCircles: the directions are tangent to the fitted surface's
  // normal, a unit vector close to the given one.
  auto oriented = Run(cloud, vtkPrincipalCurvatureEstimation::ORIENTED_CIRCLES);
  vtkPointData* od = oriented->GetPointData();
  vtkDataArray* fitted = od->GetArray("Fitted_Normal");
  checks.True(
    "OrientedCircles: Fitted_Normal, 3 components", fitted && fitted->GetNumberOfComponents() == 3);
  if (!fitted)
  {
    return;
  }
  int broken = 0;
  double largestTurn = 0.0;
  for (vtkIdType i = 0; i < oriented->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3], f[3], n[3];
    od->GetArray("Minimum_Curvature_Direction")->GetTuple(i, a);
    od->GetArray("Maximum_Curvature_Direction")->GetTuple(i, b);
    fitted->GetTuple(i, f);
    od->GetArray("Normals")->GetTuple(i, n);
    broken += std::fabs(f[0] * f[0] + f[1] * f[1] + f[2] * f[2] - 1.0) > 1e-12;
    broken += std::fabs(a[0] * f[0] + a[1] * f[1] + a[2] * f[2]) > 1e-12;
    broken += std::fabs(b[0] * f[0] + b[1] * f[1] + b[2] * f[2]) > 1e-12;
    largestTurn =
      std::max(largestTurn, std::acos(std::min(1.0, f[0] * n[0] + f[1] * n[1] + f[2] * n[2])));
  }
  checks.Equal("OrientedCircles: directions tangent to a unit Fitted_Normal", broken, 0);
  checks.True("OrientedCircles: Fitted_Normal within 2 degrees of the exact normal",
    largestTurn < 2.0 * 3.141592653589793 / 180.0);
}

/// The output-size settings: float arrays with the same values rounded,
/// and the diagnostic arrays left out; the points and the flags unchanged.
void TestOutputSize(Checks& checks)
{
  auto cloud = MakeCloud(Sample(Torus(3.0, 1.0), 5000, 8));
  vtkNew<vtkPrincipalCurvatureEstimation> full;
  full->SetInputData(cloud);
  full->Update();
  vtkNew<vtkPrincipalCurvatureEstimation> compact;
  compact->SetInputData(cloud);
  compact->SinglePrecisionOutputOn();
  compact->DiagnosticArraysOff();
  compact->Update();
  vtkPointData* a = full->GetOutput()->GetPointData();
  vtkPointData* b = compact->GetOutput()->GetPointData();
  std::vector<const char*> converted(
    std::begin(CurvatureArrayNames), std::end(CurvatureArrayNames));
  converted.insert(converted.end(), { "Shape_Index", "Curvedness" });
  for (const char* name : converted)
  {
    vtkDataArray* single = b->GetArray(name);
    vtkDataArray* reference = a->GetArray(name);
    bool same = single && vtkFloatArray::SafeDownCast(single) &&
      single->GetNumberOfValues() == reference->GetNumberOfValues();
    for (vtkIdType i = 0; same && i < reference->GetNumberOfValues(); ++i)
    {
      const double r = reference->GetVariantValue(i).ToDouble();
      const double v = single->GetVariantValue(i).ToDouble();
      same = (std::isnan(r) && std::isnan(v)) || v == static_cast<double>(static_cast<float>(r));
    }
    checks.True(
      (std::string("single precision: ") + name + " is float, the values rounded").c_str(), same);
  }
  checks.True("single precision: Curvature_Valid unchanged (unsigned char)",
    vtkUnsignedCharArray::SafeDownCast(b->GetArray("Curvature_Valid")) != nullptr);
  for (const char* name : { "Neighbor_Count",
         "Valid_Direction_Count",
         "Sine_Fit_RMS",
         "Surroundings_Threshold",
         "Plane_Distance_Threshold",
         "Curvature_Standard_Error" })
  {
    checks.True((std::string("diagnostics off: no ") + name).c_str(),
      b->GetArray(name) == nullptr && a->GetArray(name) != nullptr);
  }
  checks.True("the points are the input's",
    compact->GetOutput()->GetPoints()->GetData() == cloud->GetPoints()->GetData());
  vtkNew<vtkPolyData> cellless; // a cloud without cells gets vertex cells
  cellless->SetPoints(cloud->GetPoints());
  cellless->GetPointData()->ShallowCopy(cloud->GetPointData());
  compact->SetInputData(cellless);
  compact->Update();
  checks.Equal("a cloud without cells: vertex cells with 32-bit ids",
    compact->GetOutput()->GetVerts()->IsStorage64Bit() ? 64 : 32,
    32);
  checks.Equal("a cloud without cells: one vertex per point",
    compact->GetOutput()->GetNumberOfVerts(),
    cloud->GetNumberOfPoints());
}

/// Single precision written straight by the core: with every array on
/// (estimated normals, diagnostics, a noisy cloud whose fits are shared
/// and whose coordinates are far from the working unit), each real array
/// of the double run comes out float with its values rounded once, and
/// every other array and the field data unchanged.
void TestSinglePrecisionEveryArray(Checks& checks)
{
  // Dense enough that the fits may grow wide (up to a radian's turn of
  // the tube) and be shared.
  std::vector<SurfaceSample> torus = Sample(Torus(3000.0, 1000.0), 20000, 31);
  AddPositionNoise(torus, 0.3 * std::sqrt(4.0 * 9.8696 * 3e6 / 20000), 32);
  auto cloud = MakeCloud(torus);
  cloud->GetPointData()->SetNormals(nullptr);
  vtkSmartPointer<vtkPolyData> outputs[2];
  for (int single = 0; single < 2; ++single)
  {
    vtkNew<vtkPrincipalCurvatureEstimation> filter;
    filter->SetInputData(cloud);
    filter->SetNormalsSourceToEstimated();
    filter->SetSinglePrecisionOutput(single == 1);
    filter->Update();
    outputs[single] = filter->GetOutput();
  }
  vtkPointData* reference = outputs[0]->GetPointData();
  vtkPointData* rounded = outputs[1]->GetPointData();
  checks.Equal("single precision, every array: as many arrays",
    rounded->GetNumberOfArrays(),
    reference->GetNumberOfArrays());
  for (int a = 0; a < reference->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* r = reference->GetArray(a);
    vtkDataArray* v = rounded->GetArray(r->GetName());
    // The filter's own real arrays; the input's pass through as they are.
    const bool real =
      r->GetDataType() == VTK_DOUBLE && !cloud->GetPointData()->GetArray(r->GetName());
    bool same = v && v->GetDataType() == (real ? VTK_FLOAT : r->GetDataType()) &&
      v->GetNumberOfValues() == r->GetNumberOfValues();
    for (vtkIdType i = 0; same && i < r->GetNumberOfValues(); ++i)
    {
      const double x = r->GetVariantValue(i).ToDouble();
      const double y = v->GetVariantValue(i).ToDouble();
      same = (std::isnan(x) && std::isnan(y)) ||
        y == (real ? static_cast<double>(static_cast<float>(x)) : x);
    }
    checks.True(
      (std::string("single precision, every array: ") + r->GetName() + " rounded once").c_str(),
      same);
  }
  checks.True("single precision: the estimated normals are the output's normals, float",
    vtkFloatArray::SafeDownCast(rounded->GetNormals()) != nullptr);
  vtkDataArray* shared = outputs[1]->GetFieldData()->GetArray("Shared_Fit_Points");
  checks.True(
    "single precision, every array: the cloud shares fits", shared && shared->GetTuple1(0) > 1000);
}

/// Sphere: +1/R with outward normals, -1/R with inward ones; the same for
/// float normals; K-nearest mode works too.
void TestSignsAndNormals(Checks& checks)
{
  auto cloud = MakeCloud(Sample(Sphere(2.0), 20000, 9));
  auto meanOf = [](vtkPolyData* output, const char* name)
  {
    vtkDataArray* a = output->GetPointData()->GetArray(name);
    double sum = 0.0;
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    {
      sum += a->GetTuple1(i);
    }
    return sum / a->GetNumberOfTuples();
  };
  auto outward = Run(cloud, vtkPrincipalCurvatureEstimation::NEW01);
  checks.Near("sphere R=2 outward: mean curvature", meanOf(outward, "Mean_Curvature"), 0.5, 0.005);
  checks.Near(
    "sphere R=2 outward: Gauss curvature", meanOf(outward, "Gauss_Curvature"), 0.25, 0.005);

  vtkNew<vtkFloatArray> inward;
  inward->SetName("Inward");
  inward->SetNumberOfComponents(3);
  inward->SetNumberOfTuples(cloud->GetNumberOfPoints());
  vtkDataArray* normals = cloud->GetPointData()->GetNormals();
  for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
  {
    double n[3];
    normals->GetTuple(i, n);
    inward->SetTuple3(i, -3.0 * n[0], -3.0 * n[1], -3.0 * n[2]); // not unit on purpose
  }
  cloud->GetPointData()->AddArray(inward);
  vtkNew<vtkPrincipalCurvatureEstimation> filter;
  filter->SetInputData(cloud);
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Inward");
  filter->Update();
  checks.Near("sphere inward float normals: mean curvature",
    meanOf(filter->GetOutput(), "Mean_Curvature"),
    -0.5,
    0.005);

  vtkNew<vtkPrincipalCurvatureEstimation> knn;
  knn->SetInputData(cloud);
  knn->SetNeighborhoodModeToKNearest();
  knn->SetNumberOfNeighbors(300);
  knn->Update();
  checks.Near(
    "sphere k-nearest: mean curvature", meanOf(knn->GetOutput(), "Mean_Curvature"), 0.5, 0.005);
  checks.Near(
    "sphere k-nearest: neighbor count", meanOf(knn->GetOutput(), "Neighbor_Count"), 300.0, 0.5);

  vtkNew<vtkPrincipalCurvatureEstimation> fixed;
  fixed->SetInputData(cloud);
  fixed->AutomaticThresholdsOff();
  fixed->SetSurroundingsThreshold(0.5);
  fixed->SetPlaneDistanceThreshold(0.05);
  fixed->Update();
  checks.Near("sphere fixed thresholds: mean curvature",
    meanOf(fixed->GetOutput(), "Mean_Curvature"),
    0.5,
    0.005);
  checks.Near("fixed thresholds reported", fixed->GetUsedSurroundingsThreshold(), 0.5, 0.0);
}

/// 1 and 2 threads give bit-identical arrays.
void TestThreadIndependence(Checks& checks)
{
  auto cloud = MakeCloud(Sample(Torus(3.0, 1.0), 30000, 13));
  for (int mode = 0; mode < 3; ++mode)
  {
    auto one = Run(cloud, mode, 1);
    auto two = Run(cloud, mode, 2);
    for (const char* name : { "Minimum_Curvature",
           "Maximum_Curvature",
           "Minimum_Curvature_Direction",
           "Maximum_Curvature_Direction",
           "Sine_Fit_RMS",
           "Neighbor_Count" })
    {
      vtkDataArray* a = one->GetPointData()->GetArray(name);
      vtkDataArray* b = two->GetPointData()->GetArray(name);
      const size_t bytes = a->GetNumberOfValues() * a->GetDataTypeSize();
      char label[128];
      std::snprintf(
        label, sizeof(label), "%s %s identical with 1 and 2 threads", ModeName(mode), name);
      checks.True(label, std::memcmp(a->GetVoidPointer(0), b->GetVoidPointer(0), bytes) == 0);
    }
  }
}

/// Configuration errors are one error and a failed update; bad points are
/// flagged without harming the others.
void TestBadInput(Checks& checks)
{
  auto cloud = MakeCloud(Sample(Sphere(1.0), 5000, 21));
  {
    vtkNew<vtkPolyData> noNormals;
    noNormals->SetPoints(cloud->GetPoints());
    vtkNew<vtkPrincipalCurvatureEstimation> filter;
    EventCounter events(filter);
    filter->SetInputData(noNormals);
    filter->SetNormalsSourceToInput(); // by default they would be estimated
    filter->Update();
    checks.Equal("no normals: one error", events.Errors, 1);
    checks.Equal("no normals: empty output", filter->GetOutput()->GetNumberOfPoints(), 0);
  }
  {
    vtkNew<vtkPolyData> twoComponents;
    twoComponents->SetPoints(cloud->GetPoints());
    vtkNew<vtkDoubleArray> n2;
    n2->SetName("N2");
    n2->SetNumberOfComponents(2);
    n2->SetNumberOfTuples(cloud->GetNumberOfPoints());
    n2->Fill(1.0);
    twoComponents->GetPointData()->AddArray(n2);
    vtkNew<vtkPrincipalCurvatureEstimation> filter;
    EventCounter events(filter);
    filter->SetInputData(twoComponents);
    filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "N2");
    filter->Update();
    checks.Equal("2-component normals: one error", events.Errors, 1);
    checks.True("2-component normals: message names the array",
      events.LastMessage.find("N2") != std::string::npos);
  }
  {
    vtkNew<vtkPolyData> empty;
    vtkNew<vtkPoints> none;
    empty->SetPoints(none);
    vtkNew<vtkPrincipalCurvatureEstimation> filter;
    EventCounter events(filter);
    filter->SetInputData(empty);
    filter->Update();
    checks.Equal("empty input: no error", events.Errors + events.Warnings, 0);
    checks.Equal("empty input: empty output", filter->GetOutput()->GetNumberOfPoints(), 0);
  }
  {
    // A NaN normal and a NaN coordinate: those points are flagged, one
    // warning, the other points keep the values of the clean run.
    auto reference = Run(cloud, vtkPrincipalCurvatureEstimation::NEW01); // the paper's fit
    auto damaged = vtkSmartPointer<vtkPolyData>::New();
    damaged->DeepCopy(cloud);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    damaged->GetPointData()->GetNormals()->SetTuple3(10, nan, 0.0, 0.0);
    damaged->GetPointData()->GetNormals()->SetTuple3(11, 0.0, 0.0, 0.0);
    vtkNew<vtkPrincipalCurvatureEstimation> filter;
    EventCounter events(filter);
    filter->SetFitModeToNew01(); // its own normal only: the others unchanged
    filter->SetInputData(damaged);
    filter->Update();
    vtkPolyData* out = filter->GetOutput();
    vtkDataArray* valid = out->GetPointData()->GetArray("Curvature_Valid");
    checks.Equal("NaN normal flagged", static_cast<int>(valid->GetTuple1(10)), 0);
    checks.Equal("zero normal flagged", static_cast<int>(valid->GetTuple1(11)), 0);
    checks.True("flagged point has NaN curvature",
      std::isnan(out->GetPointData()->GetArray("Mean_Curvature")->GetTuple1(10)));
    checks.Equal("no warning for two flagged points of many", events.Warnings, 0);
    checks.Equal("count of unestimated points", filter->GetNumberOfUnestimatedPoints(), 2);
    checks.Equal(
      "field data: two points without a normal", FieldCount(out, "Unestimated_No_Normal"), 2);
    checks.Equal("field data: two points in all", FieldCount(out, "Unestimated_Points"), 2);
    vtkDataArray* a = out->GetPointData()->GetArray("Mean_Curvature");
    vtkDataArray* b = reference->GetPointData()->GetArray("Mean_Curvature");
    int changed = 0;
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      changed += (i != 10 && i != 11) && a->GetTuple1(i) != b->GetTuple1(i);
    }
    checks.Equal("other points unchanged by bad normals", changed, 0);

    damaged->GetPoints()->SetPoint(20, nan, 0.0, 0.0);
    filter->Modified();
    filter->Update();
    valid = filter->GetOutput()->GetPointData()->GetArray("Curvature_Valid");
    checks.Equal("NaN coordinate flagged", static_cast<int>(valid->GetTuple1(20)), 0);
    checks.Equal("three unestimated points", filter->GetNumberOfUnestimatedPoints(), 3);
    checks.Equal("field data: one bad coordinate",
      FieldCount(filter->GetOutput(), "Unestimated_Bad_Coordinate"),
      1);
    checks.Equal(
      "field data: three points in all", FieldCount(filter->GetOutput(), "Unestimated_Points"), 3);
  }
  {
    // The panel's "no array" entry: the normals attribute, without a warning.
    vtkNew<vtkPrincipalCurvatureEstimation> filter;
    EventCounter events(filter);
    filter->SetInputData(cloud);
    filter->SetInputArrayToProcess(
      0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "None (automatic)");
    filter->Update();
    checks.True("'None (automatic)': the normals attribute used, no warning or error",
      !filter->GetUsedEstimatedNormals() && events.Warnings == 0 && events.Errors == 0 &&
        filter->GetNumberOfUnestimatedPoints() == 0);
  }
  {
    // An unstructured grid of points is accepted.
    vtkNew<vtkUnstructuredGrid> grid;
    grid->SetPoints(cloud->GetPoints());
    grid->GetPointData()->ShallowCopy(cloud->GetPointData());
    auto output = Run(grid, vtkPrincipalCurvatureEstimation::NEW01);
    checks.Equal(
      "unstructured grid input", output->GetNumberOfPoints(), cloud->GetNumberOfPoints());
    checks.Near("unstructured grid: sphere curvature",
      output->GetPointData()->GetArray("Mean_Curvature")->GetTuple1(0),
      1.0,
      0.05);
  }
  {
    // Far too small a radius: every point flagged, one warning.
    vtkNew<vtkPrincipalCurvatureEstimation> filter;
    EventCounter events(filter);
    filter->SetInputData(cloud);
    filter->AutomaticThresholdsOff();
    filter->SetSurroundingsThreshold(1e-6);
    filter->Update();
    checks.Equal("tiny radius: all flagged",
      filter->GetNumberOfUnestimatedPoints(),
      cloud->GetNumberOfPoints());
    checks.Equal("tiny radius: one warning (most points fail)", events.Warnings, 1);
    checks.Equal("tiny radius: field data says too few neighbors",
      FieldCount(filter->GetOutput(), "Unestimated_Too_Few_Neighbors"),
      cloud->GetNumberOfPoints());
  }
}
} // namespace

int main()
{
  Checks checks;
  TestAccuracyOnShapes(checks);
  TestOutputContract(checks);
  TestOutputSize(checks);
  TestSinglePrecisionEveryArray(checks);
  TestSignsAndNormals(checks);
  TestThreadIndependence(checks);
  TestBadInput(checks);
  return checks.Summary();
}
