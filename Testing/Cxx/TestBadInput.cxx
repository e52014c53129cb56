// Bad input, one sub-test per row of the README's table: what the user sees
// (error text, warning, flag) and that nothing else in the output is harmed
// (the other points keep the values of a clean run, the input's points and
// arrays are passed through unchanged). Then numerical hardening: positions
// far from the origin, tiny and huge units, near-planar and nearly umbilic
// neighbourhoods, one far outlier; and clouds at the edges of the double
// range, each its own test (TestBadInput --extreme NAME, see the end).
//
// Every output is also checked against the output contract: a flagged point
// has Curvature_Valid = 0, NaN curvatures and zero directions; an estimated
// point has finite curvatures, max >= min, mean and Gauss consistent, and
// unit principal directions orthogonal to each other and to its normal.
#include "AnalyticClouds.h"
#include "TestChecks.h"
#include "vtkPrincipalCurvatureEstimation.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStructuredGrid.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace
{
using namespace pcurv::testing;
const double NaN = std::numeric_limits<double>::quiet_NaN();
const double Inf = std::numeric_limits<double>::infinity();

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

Outcome Run(vtkDataObject* input, const Configure& configure = nullptr)
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

void FixedRadius(vtkPrincipalCurvatureEstimation* f)
{
  f->AutomaticThresholdsOff();
  f->SetSurroundingsThreshold(0.8);
  f->SetPlaneDistanceThreshold(0.08);
}

/// The three ways of choosing neighbourhoods, each with its own code path
/// for the radius: automatic radius, k nearest, dynamic adjustment.
struct NeighborhoodMode
{
  const char* Name;
  Configure Set;
};
const NeighborhoodMode Modes[] = {
  { "automatic radius", nullptr },
  { "k nearest", [](vtkPrincipalCurvatureEstimation* f) { f->SetNeighborhoodModeToKNearest(); } },
  { "dynamic adjustment", [](vtkPrincipalCurvatureEstimation* f) { f->DynamicAdjustmentOn(); } },
};

std::string Label(const std::string& row, const char* what)
{
  return row + ": " + what;
}

bool SameValue(double a, double b)
{
  return a == b || (std::isnan(a) && std::isnan(b));
}

/// Same type, shape and values (NaN equals NaN) over the first `count`
/// tuples (all when negative); within `tolerance` when it is not 0.
bool SameArray(vtkDataArray* a, vtkDataArray* b, vtkIdType count = -1, double tolerance = 0.0)
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

const char* const CurvatureArrays[] = { "Minimum_Curvature",
  "Maximum_Curvature",
  "Mean_Curvature",
  "Gauss_Curvature",
  "Minimum_Curvature_Direction",
  "Maximum_Curvature_Direction",
  "Curvature_Valid",
  "Neighbor_Count",
  "Valid_Direction_Count",
  "Sine_Fit_RMS",
  "Surroundings_Threshold",
  "Plane_Distance_Threshold" };

/// The first `count` points have the same output arrays in both runs: bit
/// for bit, or within `tolerance` (a change of the neighbour grid's cells
/// may reorder the sums).
bool SameFirstPoints(const Outcome& a, const Outcome& b, vtkIdType count, double tolerance = 0.0)
{
  for (const char* name : CurvatureArrays)
  {
    const bool counted = std::strstr(name, "Count") || std::strstr(name, "Valid");
    if (!SameArray(a.Array(name), b.Array(name), count, counted ? 0.0 : tolerance))
    {
      std::printf("   %s differs\n", name);
      return false;
    }
  }
  return true;
}

/// The input's points and point-data arrays are in the output unchanged.
void CheckPassedThrough(Checks& checks,
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

/// The output contract at every point (see the top of the file); `normals`
/// are the input normals used (skipped when null).
void CheckContract(Checks& checks, const std::string& row, const Outcome& o, vtkDataArray* normals)
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
      if (ok && normals)
      {
        double n[3];
        normals->GetTuple(i, n);
        const double length = std::sqrt(dot(n, n));
        ok = std::fabs(dot(a, n)) < 1e-9 * length && std::fabs(dot(b, n)) < 1e-9 * length;
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
  // One warning with the count when some point is flagged, none otherwise.
  checks.Equal(Label(row, "one warning exactly when a point is flagged").c_str(),
    o.Warnings,
    flagged > 0 ? 1 : 0);
  if (flagged > 0)
  {
    const std::string count = std::to_string(flagged) + " of " + std::to_string(o.Points());
    checks.True(Label(row, "the warning gives the count").c_str(), o.Saw(count.c_str()));
  }
}

vtkSmartPointer<vtkPolyData> Torus(int n = 8000)
{
  return MakeCloud(Sample(pcurv::testing::Torus(3.0, 1.0), n, 77));
}

/// Points and normals only (no exact arrays, no cells), doubles, with
/// `extra` points (x y z nx ny nz) appended at the end.
vtkSmartPointer<vtkPolyData> WithExtraPoints(vtkPolyData* cloud,
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

vtkSmartPointer<vtkPolyData> PointsOnly(vtkPolyData* cloud)
{
  return WithExtraPoints(cloud, {});
}

/// A cloud of the given points, all with normal +z.
vtkSmartPointer<vtkPolyData> Cloud(const std::vector<std::array<double, 3>>& xyz)
{
  auto d = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> p;
  p->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> n;
  n->SetName("Normals");
  n->SetNumberOfComponents(3);
  for (const auto& x : xyz)
  {
    p->InsertNextPoint(x.data());
    n->InsertNextTuple3(0, 0, 1);
  }
  d->SetPoints(p);
  d->GetPointData()->SetNormals(n);
  return d;
}

/// Largest |k - exact| over the estimated points (both curvatures), and
/// how many points are estimated.
double LargestError(const Outcome& o, double exactMin, double exactMax, vtkIdType* estimated)
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

void Row(const std::string& name)
{
  std::printf("-- %s\n", name.c_str());
  std::fflush(stdout);
}

void TestConfigurationErrors(Checks& checks)
{
  auto cloud = PointsOnly(Torus(2000));
  {
    const std::string row = "no normals array";
    Row(row);
    vtkNew<vtkPolyData> bare;
    bare->SetPoints(cloud->GetPoints());
    const Outcome o = Run(bare);
    checks.True(Label(row, "an error").c_str(), o.Errors >= 1);
    checks.True(Label(row, "the error says what is missing").c_str(),
      o.Saw("No normals: the input needs a 3-component point-data normals array"));
    checks.Equal(Label(row, "no warning").c_str(), o.Warnings, 0);
    checks.Equal(Label(row, "empty output").c_str(), o.Points(), 0);
  }
  for (const int components : { 1, 2, 4 })
  {
    const std::string row = "normals with " + std::to_string(components) + " components";
    Row(row);
    auto input = PointsOnly(cloud);
    vtkNew<vtkDoubleArray> wrong;
    wrong->SetName("Wrong");
    wrong->SetNumberOfComponents(components);
    wrong->SetNumberOfTuples(input->GetNumberOfPoints());
    wrong->Fill(1.0);
    input->GetPointData()->AddArray(wrong);
    input->GetPointData()->SetActiveNormals(nullptr);
    const Outcome o = Run(input,
      [](vtkPrincipalCurvatureEstimation* f)
      { f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Wrong"); });
    const std::string text = "'Wrong' has " + std::to_string(components) + " components";
    checks.True(Label(row, "an error").c_str(), o.Errors >= 1);
    checks.True(
      Label(row, "the error names the array and its components").c_str(), o.Saw(text.c_str()));
    checks.Equal(Label(row, "empty output").c_str(), o.Points(), 0);
  }
  {
    const std::string row = "normals array shorter than the points";
    Row(row);
    auto input = PointsOnly(cloud);
    vtkNew<vtkDoubleArray> shorter;
    shorter->SetName("Short");
    shorter->SetNumberOfComponents(3);
    shorter->SetNumberOfTuples(input->GetNumberOfPoints() - 1);
    shorter->Fill(0.5);
    input->GetPointData()->AddArray(shorter);
    const Outcome o = Run(input,
      [](vtkPrincipalCurvatureEstimation* f)
      { f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Short"); });
    checks.True(Label(row, "an error with the counts").c_str(),
      o.Errors >= 1 &&
        o.Saw(("'Short' has 3 components and " + std::to_string(input->GetNumberOfPoints() - 1) +
          " tuples")
                .c_str()));
    checks.Equal(Label(row, "empty output").c_str(), o.Points(), 0);
  }
  {
    const std::string row = "normals asked for by a name that is not there";
    Row(row);
    const Outcome o = Run(cloud,
      [](vtkPrincipalCurvatureEstimation* f) {
        f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "NoSuchArray");
      });
    checks.True(Label(row, "an error").c_str(), o.Errors >= 1 && o.Saw("No normals"));
    checks.Equal(Label(row, "empty output").c_str(), o.Points(), 0);
  }
  {
    const std::string row = "vtkImageData (not a point set)";
    Row(row);
    vtkNew<vtkImageData> image;
    image->SetDimensions(4, 4, 4);
    vtkNew<vtkDoubleArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(64);
    normals->Fill(1.0);
    image->GetPointData()->SetNormals(normals);
    const Outcome o = Run(image);
    checks.True(Label(row, "rejected with an error").c_str(), o.Errors >= 1);
    checks.True(
      Label(row, "the error says a vtkPointSet is required").c_str(), o.Saw("vtkPointSet"));
    checks.Equal(Label(row, "empty output").c_str(), o.Points(), 0);
  }
}

void TestFlaggedPoints(Checks& checks)
{
  auto cloud = PointsOnly(Torus());
  const vtkIdType n = cloud->GetNumberOfPoints();
  const Outcome clean = Run(cloud, FixedRadius);
  checks.Equal("clean torus: all estimated", clean.Unestimated, 0);
  CheckContract(checks, "clean torus", clean, cloud->GetPointData()->GetNormals());

  {
    const std::string row = "NaN and Inf coordinates";
    Row(row);
    auto input = WithExtraPoints(cloud,
      { { NaN, 0, 0, 0, 0, 1 },
        { 0, Inf, 0, 0, 0, 1 },
        { -Inf, NaN, 1, 1, 0, 0 },
        { 1, 1, -Inf, 0, 1, 0 } });
    const Outcome o = Run(input, FixedRadius);
    checks.True(Label(row, "those points flagged").c_str(),
      o.Valid(n) == 0 && o.Valid(n + 1) == 0 && o.Valid(n + 2) == 0 && o.Valid(n + 3) == 0);
    checks.Equal(Label(row, "they have no neighbours").c_str(),
      static_cast<long long>(o.Value("Neighbor_Count", n) + o.Value("Neighbor_Count", n + 3)),
      0);
    checks.True(Label(row, "other points bit-identical (left out of every neighbourhood)").c_str(),
      SameFirstPoints(o, clean, n));
    CheckContract(checks, row, o, input->GetPointData()->GetNormals());
    CheckPassedThrough(checks, row, input, o);
    for (const NeighborhoodMode& mode : Modes)
    {
      const std::string modeRow = row + ", " + mode.Name;
      const Outcome a = Run(cloud, mode.Set);
      const Outcome b = Run(input, mode.Set);
      checks.True(Label(modeRow, "other points bit-identical").c_str(), SameFirstPoints(b, a, n));
      CheckContract(checks, modeRow, b, input->GetPointData()->GetNormals());
    }
  }
  {
    const std::string row = "NaN, Inf and zero normals";
    Row(row);
    auto input = PointsOnly(cloud);
    vtkDataArray* normals = input->GetPointData()->GetNormals();
    normals->SetTuple3(5, NaN, 0, 0);
    normals->SetTuple3(6, 0, 0, 0);
    normals->SetTuple3(7, 0, -Inf, 0);
    normals->SetTuple3(8, 1, NaN, 1);
    const Outcome o = Run(input, FixedRadius);
    checks.True(Label(row, "those points flagged").c_str(),
      o.Valid(5) == 0 && o.Valid(6) == 0 && o.Valid(7) == 0 && o.Valid(8) == 0);
    checks.Equal(Label(row, "four unestimated").c_str(), o.Unestimated, 4);
    // Only the point's own normal is used, so the others are bit-identical.
    const Outcome& reference = clean;
    int changed = 0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      if (i < 5 || i > 8)
      {
        for (const char* name : CurvatureArrays)
        {
          vtkDataArray* x = o.Array(name);
          vtkDataArray* y = reference.Array(name);
          for (int k = 0; k < x->GetNumberOfComponents(); ++k)
          {
            changed += !SameValue(x->GetComponent(i, k), y->GetComponent(i, k));
          }
        }
      }
    }
    checks.Equal(Label(row, "other points bit-identical").c_str(), changed, 0);
    CheckContract(checks, row, o, normals);
    CheckPassedThrough(checks, row, input, o);
  }
  {
    const std::string row = "non-unit normals (length 7.5)";
    Row(row);
    auto input = PointsOnly(cloud);
    vtkDataArray* normals = input->GetPointData()->GetNormals();
    for (vtkIdType i = 0; i < n; ++i)
    {
      double v[3];
      normals->GetTuple(i, v);
      normals->SetTuple3(i, 7.5 * v[0], 7.5 * v[1], 7.5 * v[2]);
    }
    const Outcome o = Run(input, FixedRadius);
    checks.True(Label(row, "same results as unit normals (1e-12)").c_str(),
      SameFirstPoints(o, clean, n, 1e-12));
    CheckContract(checks, row, o, normals);
    CheckPassedThrough(checks, row, input, o);
  }
  for (const double length : { 1e-170, 1e170 })
  {
    // Finite and not zero, so the README promises an estimate; but the
    // squared length under- or overflows.
    char row[64];
    std::snprintf(row, sizeof(row), "normals of length %g", length);
    Row(row);
    auto input = PointsOnly(cloud);
    vtkDataArray* normals = input->GetPointData()->GetNormals();
    for (vtkIdType i = 0; i < n; ++i)
    {
      double v[3];
      normals->GetTuple(i, v);
      normals->SetTuple3(i, length * v[0], length * v[1], length * v[2]);
    }
    const Outcome o = Run(input, FixedRadius);
    checks.Equal(Label(row, "no point flagged").c_str(), o.Unestimated, 0);
    checks.True(Label(row, "same results as unit normals (1e-12)").c_str(),
      SameFirstPoints(o, clean, n, 1e-12));
    CheckPassedThrough(checks, row, input, o);
  }
  {
    const std::string row = "an isolated point far from the rest";
    Row(row);
    auto input = WithExtraPoints(cloud, { { 100, 100, 100, 0, 0, 1 } });
    const Outcome o = Run(input, FixedRadius);
    checks.Equal(Label(row, "flagged").c_str(), o.Valid(n), 0);
    checks.Equal(
      Label(row, "0 neighbours").c_str(), static_cast<int>(o.Value("Neighbor_Count", n)), 0);
    // It widens the bounding box, hence the grid's cells and the order of
    // the sums: equal to rounding.
    checks.True(
      Label(row, "other points unchanged (1e-12)").c_str(), SameFirstPoints(o, clean, n, 1e-12));
    CheckContract(checks, row, o, input->GetPointData()->GetNormals());
    CheckPassedThrough(checks, row, input, o);
  }
}

void TestDegenerateClouds(Checks& checks)
{
  {
    const std::string row = "empty input";
    Row(row);
    vtkNew<vtkPolyData> empty;
    vtkNew<vtkPoints> none;
    empty->SetPoints(none);
    const Outcome o = Run(empty);
    checks.Equal(Label(row, "no error or warning").c_str(), o.Errors + o.Warnings, 0);
    checks.Equal(Label(row, "empty output").c_str(), o.Points(), 0);
    vtkNew<vtkPolyData> nothing; // not even a points object
    const Outcome p = Run(nothing);
    checks.Equal(
      Label(row, "no points object: no error or warning").c_str(), p.Errors + p.Warnings, 0);
    checks.Equal(Label(row, "no points object: empty output").c_str(), p.Points(), 0);
  }
  std::vector<std::array<double, 3>> same(500, { { 1, 2, 3 } });
  std::vector<std::array<double, 3>> line;
  for (int i = 0; i < 500; ++i)
  {
    line.push_back({ { 0.01 * i, 0.0, 0.0 } });
  }
  const struct
  {
    const char* Name;
    std::vector<std::array<double, 3>> Points;
  } clouds[] = {
    { "one point", { { 1, 2, 3 } } },
    { "two identical points", { { 1, 2, 3 }, { 1, 2, 3 } } },
    { "500 copies of one point", same },
    { "points on a line (no surface)", line },
  };
  for (const auto& c : clouds)
  {
    for (const NeighborhoodMode& mode : Modes)
    {
      const std::string row = std::string(c.Name) + ", " + mode.Name;
      Row(row);
      auto input = Cloud(c.Points);
      const Outcome o = Run(input, mode.Set);
      checks.Equal(Label(row, "no error").c_str(), o.Errors, 0);
      checks.Equal(Label(row, "every point flagged").c_str(),
        o.Unestimated,
        static_cast<vtkIdType>(c.Points.size()));
      CheckContract(checks, row, o, input->GetPointData()->GetNormals());
      CheckPassedThrough(checks, row, input, o);
    }
  }
  {
    std::vector<SurfaceSample> samples = Sample(Sphere(1.0), 5000, 3);
    std::vector<SurfaceSample> tripled;
    for (const auto& s : samples)
    {
      tripled.insert(tripled.end(), { s, s, s });
    }
    auto input = MakeCloud(tripled);
    for (const NeighborhoodMode& mode : Modes)
    {
      const std::string row =
        std::string("many duplicate points (sphere, every point three times), ") + mode.Name;
      Row(row);
      const Outcome o = Run(input, mode.Set);
      vtkIdType estimated = 0;
      const double error = LargestError(o, 1.0, 1.0, &estimated);
      if (mode.Set && std::strstr(mode.Name, "adjustment"))
      {
        // The adjustment counts every copy towards its target, so it works
        // with a third of the distinct points, in planes of s/40: some
        // points have too few directions and are flagged (about 10 %).
        std::printf("   %lld of %lld estimated, largest error %g\n",
          static_cast<long long>(estimated),
          static_cast<long long>(o.Points()),
          error);
        checks.Below(Label(row, "estimated points have 1/R").c_str(), error, 1e-4);
        checks.True(Label(row, "most points estimated").c_str(), estimated > 0.8 * o.Points());
      }
      else
      {
        checks.Below(Label(row, "curvature still 1/R").c_str(), error, 1e-6);
        checks.Equal(Label(row, "all estimated").c_str(), estimated, input->GetNumberOfPoints());
      }
      CheckContract(checks, row, o, input->GetPointData()->GetNormals());
      CheckPassedThrough(checks, row, input, o);
    }
  }
}

void TestSettings(Checks& checks)
{
  auto cloud = Torus(4000);
  vtkDataArray* normals = cloud->GetPointData()->GetNormals();
  for (const double radius : { 0.0, -1.0 })
  {
    const std::string row = radius == 0.0 ? "radius 0" : "radius -1 (clamped to 0)";
    Row(row);
    vtkNew<vtkPrincipalCurvatureEstimation> f;
    f->SetSurroundingsThreshold(radius);
    checks.Near(Label(row, "the setter keeps 0").c_str(), f->GetSurroundingsThreshold(), 0.0, 0.0);
    const Outcome o = Run(cloud,
      [radius](vtkPrincipalCurvatureEstimation* g)
      {
        g->AutomaticThresholdsOff();
        g->SetSurroundingsThreshold(radius);
      });
    checks.Equal(
      Label(row, "every point flagged").c_str(), o.Unestimated, cloud->GetNumberOfPoints());
    checks.Equal(Label(row, "no error").c_str(), o.Errors, 0);
    checks.True(Label(row, "the warning says why").c_str(), o.Saw("could not be estimated"));
    CheckContract(checks, row, o, normals);
    CheckPassedThrough(checks, row, cloud, o);
  }
  for (const double radius : { NaN, Inf })
  {
    const std::string row =
      std::isnan(radius) ? "radius NaN" : "radius Inf (clamped to the largest double)";
    Row(row);
    const Outcome o = Run(cloud,
      [radius](vtkPrincipalCurvatureEstimation* g)
      {
        g->AutomaticThresholdsOff();
        g->SetSurroundingsThreshold(radius);
      });
    checks.Equal(Label(row, "no error").c_str(), o.Errors, 0);
    CheckContract(checks, row, o, normals);
    CheckPassedThrough(checks, row, cloud, o);
  }
  {
    const std::string row = "plane distance 0";
    Row(row);
    const Outcome o = Run(cloud,
      [](vtkPrincipalCurvatureEstimation* g)
      {
        g->AutomaticThresholdsOff();
        g->SetSurroundingsThreshold(0.8);
        g->SetPlaneDistanceThreshold(0.0);
      });
    checks.Equal(
      Label(row, "every point flagged").c_str(), o.Unestimated, cloud->GetNumberOfPoints());
    CheckContract(checks, row, o, normals);
  }
  {
    const std::string row = "radius larger than the cloud";
    Row(row);
    const Outcome o = Run(cloud,
      [](vtkPrincipalCurvatureEstimation* f)
      {
        f->AutomaticThresholdsOff();
        f->SetSurroundingsThreshold(100.0);
        f->SetPlaneDistanceThreshold(0.5);
      });
    checks.Equal(Label(row, "no error").c_str(), o.Errors, 0);
    checks.Equal(Label(row, "every other point is a neighbour").c_str(),
      static_cast<long long>(o.Value("Neighbor_Count", 0)),
      cloud->GetNumberOfPoints() - 1);
    CheckContract(checks, row, o, normals);
    CheckPassedThrough(checks, row, cloud, o);
  }
  {
    const std::string row = "a neighbour count below the minimum";
    Row(row);
    vtkNew<vtkPrincipalCurvatureEstimation> f;
    f->SetNumberOfNeighbors(1);
    checks.Equal(
      Label(row, "NumberOfNeighbors clamped to 3").c_str(), f->GetNumberOfNeighbors(), 3);
    f->SetNumberOfNeighbors(-5);
    checks.Equal(Label(row, "negative clamped to 3").c_str(), f->GetNumberOfNeighbors(), 3);
    f->SetMinimumPointsPerDirection(0);
    checks.Equal(Label(row, "MinimumPointsPerDirection clamped to 3").c_str(),
      f->GetMinimumPointsPerDirection(),
      3);
    for (const NeighborhoodMode& mode : Modes)
    {
      const std::string modeRow = row + ", " + mode.Name;
      const Outcome o = Run(cloud,
        [&mode](vtkPrincipalCurvatureEstimation* g)
        {
          if (mode.Set)
          {
            mode.Set(g);
          }
          g->SetNumberOfNeighbors(1);
        });
      checks.Equal(Label(modeRow, "no error").c_str(), o.Errors, 0);
      CheckContract(checks, modeRow, o, normals);
    }
    const Outcome o = Run(cloud,
      [](vtkPrincipalCurvatureEstimation* g)
      {
        g->SetNeighborhoodModeToKNearest();
        g->SetNumberOfNeighbors(1);
      });
    checks.Equal(Label(row, "3 nearest: every point flagged (too few per direction)").c_str(),
      o.Unestimated,
      cloud->GetNumberOfPoints());
  }
  for (const double huge : { 0.0, 1e300 })
  {
    const std::string row = huge > 0.0 ? "huge adjustment target counts (1e300)"
                                       : "nonsense adjustment targets (0, negative, NaN)";
    Row(row);
    Outcome o = Run(cloud,
      [huge](vtkPrincipalCurvatureEstimation* g)
      {
        g->DynamicAdjustmentOn();
        g->SetTargetNeighborCounts(huge, huge > 0.0 ? huge : -5.0, huge > 0.0 ? huge : NaN);
        g->SetTargetPlaneDistances(-1.0, 0.0, NaN);
      });
    checks.Equal(Label(row, "no error").c_str(), o.Errors, 0);
    checks.True(Label(row, "a warning names the clamped counts").c_str(),
      o.Saw("TargetNeighborCounts must lie within [1, 1e6]"));
    --o.Warnings; // that warning; the contract counts the flagged points' one
    CheckContract(checks, row, o, normals);
  }
  {
    const std::string row = "nonsense adjustment targets, adjustment off";
    Row(row);
    const Outcome o = Run(cloud,
      [](vtkPrincipalCurvatureEstimation* g) { g->SetTargetNeighborCounts(NaN, -5.0, 1e300); });
    checks.Equal(Label(row, "no error").c_str(), o.Errors, 0);
    checks.True(
      Label(row, "unused settings: no warning about them").c_str(), !o.Saw("TargetNeighborCounts"));
    CheckContract(checks, row, o, normals);
  }
}

void TestTypesAndInputs(Checks& checks)
{
  {
    auto cloud = MakeCloud(Sample(Sphere(2.0), 8000, 8));
    for (const bool withCells : { false, true })
    {
      const std::string row =
        withCells ? "vtkUnstructuredGrid with vertex cells" : "vtkUnstructuredGrid without cells";
      Row(row);
      vtkNew<vtkUnstructuredGrid> grid;
      grid->SetPoints(cloud->GetPoints());
      grid->GetPointData()->ShallowCopy(cloud->GetPointData());
      if (withCells)
      {
        grid->Allocate(cloud->GetNumberOfPoints());
        for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
        {
          grid->InsertNextCell(VTK_VERTEX, 1, &i);
        }
      }
      const Outcome o = Run(grid);
      vtkIdType estimated = 0;
      checks.Below(
        Label(row, "curvature 1/2").c_str(), LargestError(o, 0.5, 0.5, &estimated), 0.01);
      checks.Equal(Label(row, "all estimated").c_str(), estimated, cloud->GetNumberOfPoints());
      checks.Equal(
        Label(row, "vertex cells made").c_str(), o.Output->GetNumberOfVerts(), o.Points());
      CheckContract(checks, row, o, cloud->GetPointData()->GetNormals());
      CheckPassedThrough(checks, row, grid, o);
    }
  }
  {
    // A latitude-longitude grid on a sphere: a structured point set with
    // coincident points along the seam and at the poles.
    const std::string row = "vtkStructuredGrid (latitude-longitude sphere)";
    Row(row);
    const int nu = 241, nv = 121;
    const double r = 2.0;
    vtkNew<vtkStructuredGrid> grid;
    grid->SetDimensions(nu, nv, 1);
    vtkNew<vtkPoints> points;
    vtkNew<vtkDoubleArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    for (int j = 0; j < nv; ++j)
    {
      for (int i = 0; i < nu; ++i)
      {
        const double u = 2.0 * Pi * i / (nu - 1), v = Pi * j / (nv - 1);
        const double n[3] = { std::cos(u) * std::sin(v), std::sin(u) * std::sin(v), std::cos(v) };
        points->InsertNextPoint(r * n[0], r * n[1], r * n[2]);
        normals->InsertNextTuple(n);
      }
    }
    grid->SetPoints(points);
    grid->GetPointData()->SetNormals(normals);
    const Outcome o = Run(grid);
    vtkIdType estimated = 0;
    checks.Below(Label(row, "curvature 1/2").c_str(), LargestError(o, 0.5, 0.5, &estimated), 0.01);
    checks.Equal(Label(row, "all estimated").c_str(), estimated, grid->GetNumberOfPoints());
    CheckContract(checks, row, o, normals);
    CheckPassedThrough(checks, row, grid, o);
  }
  {
    const std::string row = "integer coordinates (VTK_INT) and normals (vtkIntArray)";
    Row(row);
    // A sphere of radius 1000 rounded to integers, normals times 1000 as ints.
    const auto samples = Sample(Sphere(1000.0), 20000, 9);
    vtkNew<vtkPolyData> cloud;
    vtkNew<vtkPoints> points;
    points->SetDataTypeToInt();
    vtkNew<vtkIntArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    for (const auto& s : samples)
    {
      points->InsertNextPoint(
        std::round(s.Point[0]), std::round(s.Point[1]), std::round(s.Point[2]));
      normals->InsertNextTuple3(std::round(1000 * s.Normal[0]),
        std::round(1000 * s.Normal[1]),
        std::round(1000 * s.Normal[2]));
    }
    cloud->SetPoints(points);
    cloud->GetPointData()->SetNormals(normals);
    const Outcome o = Run(cloud);
    double mean = 0.0;
    for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
    {
      mean += o.Value("Mean_Curvature", i) / cloud->GetNumberOfPoints();
    }
    checks.Equal(Label(row, "all estimated").c_str(), o.Unestimated, 0);
    checks.Near(Label(row, "sphere curvature 1/1000").c_str(), mean, 1e-3, 2e-5);
    checks.True(Label(row, "integer points kept as such").c_str(),
      o.Output->GetPoints()->GetDataType() == VTK_INT);
    CheckContract(checks, row, o, normals);
    CheckPassedThrough(checks, row, cloud, o);
  }
  {
    const std::string row = "float coordinates and normals";
    Row(row);
    const auto samples = Sample(Sphere(2.0), 20000, 10);
    vtkNew<vtkPolyData> cloud;
    vtkNew<vtkPoints> points;
    points->SetDataTypeToFloat();
    vtkNew<vtkFloatArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    for (const auto& s : samples)
    {
      points->InsertNextPoint(s.Point.data());
      normals->InsertNextTuple(s.Normal.data());
    }
    cloud->SetPoints(points);
    cloud->GetPointData()->SetNormals(normals);
    const Outcome o = Run(cloud);
    vtkIdType estimated = 0;
    checks.Below(Label(row, "curvature 1/2").c_str(), LargestError(o, 0.5, 0.5, &estimated), 1e-3);
    checks.Equal(Label(row, "all estimated").c_str(), estimated, cloud->GetNumberOfPoints());
    CheckContract(checks, row, o, normals);
    CheckPassedThrough(checks, row, cloud, o);
  }
}

void TestNumericalHardening(Checks& checks)
{
  {
    const std::string row = "a cloud translated by 1e6, scaled by 1e-6 and 1e6";
    Row(row);
    auto reference = Run(Torus(8000));
    for (const double scale : { 1e-6, 1.0, 1e6 })
    {
      for (const double shift : { 0.0, 1e6 })
      {
        auto moved = Torus(8000);
        vtkPoints* p = moved->GetPoints();
        for (vtkIdType i = 0; i < p->GetNumberOfPoints(); ++i)
        {
          double x[3];
          p->GetPoint(i, x);
          p->SetPoint(i, scale * x[0] + shift * scale, scale * x[1], scale * x[2]);
        }
        const Outcome o = Run(moved);
        double worst = 0.0;
        for (vtkIdType i = 0; i < p->GetNumberOfPoints(); ++i)
        {
          for (const char* name : { "Minimum_Curvature", "Maximum_Curvature" })
          {
            worst = std::max(worst, std::fabs(scale * o.Value(name, i) - reference.Value(name, i)));
          }
        }
        char label[128];
        std::snprintf(label,
          sizeof(label),
          "scale %g, shift %g: curvature x scale unchanged",
          scale,
          shift * scale);
        // A shift of 1e6 spacings leaves about 1e-10 of the coordinates' precision.
        checks.Below(label, worst, shift > 0.0 ? 1e-6 : 1e-9);
        std::snprintf(label, sizeof(label), "scale %g, shift %g", scale, shift * scale);
        checks.Equal(Label(label, "all estimated").c_str(), o.Unestimated, 0);
        CheckContract(checks, label, o, moved->GetPointData()->GetNormals());
      }
    }
  }
  {
    // A tilted plane: heights are rounding noise around 0.
    const std::string row = "near-planar: a tilted plane";
    Row(row);
    auto cloud = MakeCloud(Sample(Plane(1.0), 20000, 11));
    const double c = std::cos(0.3), s = std::sin(0.3);
    vtkPoints* p = cloud->GetPoints();
    vtkDataArray* normals = cloud->GetPointData()->GetNormals();
    for (vtkIdType i = 0; i < p->GetNumberOfPoints(); ++i)
    {
      double x[3], n[3];
      p->GetPoint(i, x);
      normals->GetTuple(i, n);
      p->SetPoint(i, c * x[0] - s * x[2] + 10.0, x[1] - 3.0, s * x[0] + c * x[2] + 7.0);
      normals->SetTuple3(i, c * n[0] - s * n[2], n[1], s * n[0] + c * n[2]);
    }
    const Outcome o = Run(cloud);
    const double radius = o.UsedSurroundingsThreshold;
    double worst = 0.0;
    vtkIdType interior = 0, estimated = 0;
    for (vtkIdType i = 0; i < o.Points(); ++i)
    {
      if (o.Value("Boundary_Distance", i) > radius)
      {
        ++interior;
        estimated += o.Valid(i) == 1;
        worst = std::max({ worst,
          std::fabs(o.Value("Minimum_Curvature", i)),
          std::fabs(o.Value("Maximum_Curvature", i)) });
      }
    }
    checks.Equal(Label(row, "interior points all estimated").c_str(), estimated, interior);
    checks.Below(Label(row, "|k| at rounding level").c_str(), worst, 1e-9);
    CheckContract(checks, row, o, normals);
  }
  {
    // z = (x^2 + y^2) / (2 a), a = 1e4 on [-1, 1]^2: heights of at most
    // 1e-4, curvature about 1e-4 (in the output sign, -1e-4: the bowl opens
    // towards the normal).
    const std::string row = "near-planar: a paraboloid of curvature 1e-4";
    Row(row);
    auto cloud = MakeCloud(Sample(Paraboloid(1.0, 1e4), 20000, 12));
    const Outcome o = Run(cloud);
    const double radius = o.UsedSurroundingsThreshold;
    double worst = 0.0;
    vtkIdType interior = 0, estimated = 0;
    for (vtkIdType i = 0; i < o.Points(); ++i)
    {
      if (o.Value("Boundary_Distance", i) > radius)
      {
        ++interior;
        estimated += o.Valid(i) == 1;
        worst = std::max({ worst,
          std::fabs(o.Value("Minimum_Curvature", i) - o.Value("Exact_Minimum_Curvature", i)),
          std::fabs(o.Value("Maximum_Curvature", i) - o.Value("Exact_Maximum_Curvature", i)) });
      }
    }
    checks.Equal(Label(row, "interior points all estimated").c_str(), estimated, interior);
    checks.Below(Label(row, "error below 1 % of the curvature").c_str(), worst, 1e-6);
    CheckContract(checks, row, o, cloud->GetPointData()->GetNormals());
  }
  for (const double flattening : { 0.0, 1e-3 })
  {
    // Umbilic (a sphere) or nearly (an ellipsoid with axes 2, 2, 2.002):
    // the directions are arbitrary or ill-determined, the curvatures are not.
    const std::string row =
      flattening == 0.0 ? "umbilic: a sphere of radius 2" : "nearly umbilic: ellipsoid 2, 2, 2.002";
    Row(row);
    auto cloud = MakeCloud(Sample(Ellipsoid(2.0, 2.0, 2.0 * (1.0 + flattening)), 20000, 13));
    for (const NeighborhoodMode& mode : Modes)
    {
      const std::string modeRow = row + ", " + mode.Name;
      const Outcome o = Run(cloud, mode.Set);
      double worst = 0.0;
      for (vtkIdType i = 0; i < o.Points(); ++i)
      {
        if (o.Valid(i) == 1)
        {
          worst = std::max({ worst,
            std::fabs(o.Value("Minimum_Curvature", i) - o.Value("Exact_Minimum_Curvature", i)),
            std::fabs(o.Value("Maximum_Curvature", i) - o.Value("Exact_Maximum_Curvature", i)) });
        }
      }
      // The adjustment's thin planes (s/40) leave a rare point with its
      // valid directions inside one half-turn: flagged, as it should be.
      const bool adjusted = mode.Set && std::strstr(mode.Name, "adjustment");
      checks.True(Label(modeRow, "all estimated (adjustment: all but 1 in 5000)").c_str(),
        adjusted ? o.Unestimated * 5000 <= o.Points() : o.Unestimated == 0);
      checks.Below(Label(modeRow, "curvatures within 1 % of 1/2").c_str(), worst, 0.005);
      CheckContract(checks, modeRow, o, cloud->GetPointData()->GetNormals());
    }
  }
}

/// One far outlier, as a "missing value" sentinel in a file makes: the
/// torus must keep its estimates (as in a clean run, to the accuracy of the
/// method) and the outlier is flagged, in every neighbourhood mode. At 1e110
/// the neighbour grid would need more cells than a double counts.
void TestFarOutlier(Checks& checks)
{
  auto cloud = PointsOnly(Torus());
  const vtkIdType n = cloud->GetNumberOfPoints();
  auto exact = Torus();
  for (const double far : { 1e7, -1e7, 1e110 })
  {
    auto input = WithExtraPoints(cloud, { { far, far, far, 0, 0, 1 } });
    for (const NeighborhoodMode& mode : Modes)
    {
      char row[128];
      std::snprintf(row, sizeof(row), "one outlier at (%g, %g, %g), %s", far, far, far, mode.Name);
      Row(row);
      const Outcome clean = Run(cloud, mode.Set);
      const Outcome o = Run(input, mode.Set);
      // Mean |k - exact| over the torus, relative to max |k| = 1.
      auto meanError = [&](const Outcome& r, vtkIdType* estimated)
      {
        double sum = 0.0;
        *estimated = 0;
        for (vtkIdType i = 0; i < n; ++i)
        {
          if (r.Valid(i) == 1)
          {
            ++*estimated;
            sum += std::fabs(r.Value("Maximum_Curvature", i) -
                     exact->GetPointData()->GetArray("Exact_Maximum_Curvature")->GetTuple1(i)) +
              std::fabs(r.Value("Minimum_Curvature", i) -
                exact->GetPointData()->GetArray("Exact_Minimum_Curvature")->GetTuple1(i));
          }
        }
        return *estimated > 0 ? sum / (2.0 * *estimated) : NaN;
      };
      vtkIdType cleanEstimated = 0, estimated = 0;
      const double cleanError = meanError(clean, &cleanEstimated);
      const double error = meanError(o, &estimated);
      std::printf("   torus points estimated %lld (clean %lld), mean error %.4f (clean %.4f), "
                  "s %g\n",
        static_cast<long long>(estimated),
        static_cast<long long>(cleanEstimated),
        error,
        cleanError,
        o.Value("Surroundings_Threshold", 0));
      checks.Equal(Label(row, "the outlier is flagged").c_str(), o.Valid(n), 0);
      checks.True(Label(row, "the torus points are estimated as in a clean run").c_str(),
        estimated >= cleanEstimated - n / 1000);
      checks.True(Label(row, "and as accurately").c_str(), error <= 1.5 * cleanError + 0.005);
      CheckContract(checks, row, o, input->GetPointData()->GetNormals());
      CheckPassedThrough(checks, row, input, o);
    }
  }
}

/// Clouds at the edges of the double range, each run as its own test
/// (TestBadInput --extreme NAME) so that a hang shows as that test's
/// timeout: flagging the points is acceptable, a hang, a crash or a wrong
/// number is not.
///  - Tiny: a torus scaled by 2^-665 (about 1.6e-200: squared distances
///    underflow);
///  - Huge: a torus scaled by 2^531 (about 5.5e159: squared distances
///    overflow).
/// Powers of two, so that the scaled clouds are exact copies: the filter
/// works in a power-of-two unit of its own and must then give the clean
/// run's numbers; with another factor, rounding moves the automatic
/// radius by an ulp and with it neighbours that lie exactly on it.
///  - FarApart: a torus and one point 1e300 away;
///  - FullRange: a torus and two points at -1e308 and +1e308 (the box's
///    extent overflows).
bool TestExtremeMagnitudes(Checks& checks, const std::string& name)
{
  double scale = 1.0;
  std::vector<std::array<double, 6>> extra;
  if (name == "Tiny")
  {
    scale = std::ldexp(1.0, -665);
  }
  else if (name == "Huge")
  {
    scale = std::ldexp(1.0, 531);
  }
  else if (name == "FarApart")
  {
    extra = { { 1e300, 0, 0, 0, 0, 1 } };
  }
  else if (name == "FullRange")
  {
    extra = { { -1e308, 0, 0, 0, 0, 1 }, { 1e308, 1e308, 0, 0, 0, 1 } };
  }
  else
  {
    std::printf("unknown extreme cloud '%s' (Tiny, Huge, FarApart, FullRange)\n", name.c_str());
    return false;
  }
  auto torus = PointsOnly(Torus(4000));
  const vtkIdType n = torus->GetNumberOfPoints();
  auto cloud = WithExtraPoints(torus, extra);
  vtkPoints* p = cloud->GetPoints();
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    p->GetPoint(i, x);
    p->SetPoint(i, scale * x[0], scale * x[1], scale * x[2]);
  }
  for (const NeighborhoodMode& mode : Modes)
  {
    const std::string row = "extreme cloud " + name + ", " + mode.Name;
    Row(row);
    const Outcome clean = Run(torus, mode.Set);
    const Outcome o = Run(cloud, mode.Set);
    checks.Equal(Label(row, "no error").c_str(), o.Errors, 0);
    CheckContract(checks, row, o, cloud->GetPointData()->GetNormals());
    CheckPassedThrough(checks, row, cloud, o);
    vtkIdType wrong = 0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      wrong += o.Valid(i) == 1 &&
        !(std::fabs(scale * o.Value("Maximum_Curvature", i) - clean.Value("Maximum_Curvature", i)) <
          1e-6);
    }
    checks.Equal(Label(row, "estimated torus points right (else flagged)").c_str(), wrong, 0);
    for (vtkIdType i = n; i < o.Points(); ++i)
    {
      checks.Equal(Label(row, "the far points are flagged").c_str(), o.Valid(i), 0);
    }
  }
  return true;
}
} // namespace

int main(int argc, char* argv[])
{
  Checks checks;
  if (argc == 3 && std::string(argv[1]) == "--extreme")
  {
    return TestExtremeMagnitudes(checks, argv[2]) ? checks.Summary() : EXIT_FAILURE;
  }
  TestConfigurationErrors(checks);
  TestFlaggedPoints(checks);
  TestFarOutlier(checks);
  TestDegenerateClouds(checks);
  TestSettings(checks);
  TestTypesAndInputs(checks);
  TestNumericalHardening(checks);
  return checks.Summary();
}
