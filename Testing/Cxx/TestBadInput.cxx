// Bad input, one sub-test per row of the README's table: what the user sees
// (error, warning, flag) and that nothing else in the output is harmed.
#include "AnalyticClouds.h"
#include "TestChecks.h"
#include "vtkPrincipalCurvatureEstimation.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>

namespace
{
using namespace pcurv::testing;
const double NaN = std::numeric_limits<double>::quiet_NaN();
const double Inf = std::numeric_limits<double>::infinity();

/// Runs the filter and records the errors and warnings it raised.
struct Outcome
{
  vtkSmartPointer<vtkPolyData> Output;
  int Errors = 0;
  int Warnings = 0;
  std::string Message;
  vtkIdType Unestimated = 0;

  double Value(const char* name, vtkIdType i) const
  {
    return this->Output->GetPointData()->GetArray(name)->GetComponent(i, 0);
  }
  int Valid(vtkIdType i) const { return static_cast<int>(this->Value("Curvature_Valid", i)); }
};

Outcome Run(vtkDataObject* input, void (*configure)(vtkPrincipalCurvatureEstimation*) = nullptr)
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
      o->Message = data ? static_cast<const char*>(data) : "";
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
  return outcome;
}

void FixedRadius(vtkPrincipalCurvatureEstimation* f)
{
  f->AutomaticThresholdsOff();
  f->SetSurroundingsThreshold(0.8);
  f->SetPlaneDistanceThreshold(0.08);
}

/// True when the first `count` points have the same curvature arrays: bit
/// for bit, or within `tolerance` (a change of the neighbour grid's cells
/// may reorder the sums).
bool SameFirstPoints(const Outcome& a, const Outcome& b, vtkIdType count, double tolerance = 0.0)
{
  for (const char* name :
    { "Minimum_Curvature", "Maximum_Curvature", "Maximum_Curvature_Direction" })
  {
    vtkDataArray* x = a.Output->GetPointData()->GetArray(name);
    vtkDataArray* y = b.Output->GetPointData()->GetArray(name);
    const int c = x->GetNumberOfComponents();
    if (tolerance == 0.0)
    {
      if (std::memcmp(x->GetVoidPointer(0), y->GetVoidPointer(0), count * c * sizeof(double)) != 0)
      {
        return false;
      }
      continue;
    }
    for (vtkIdType i = 0; i < count * c; ++i)
    {
      if (!(std::fabs(x->GetComponent(i / c, i % c) - y->GetComponent(i / c, i % c)) <= tolerance))
      {
        return false;
      }
    }
  }
  return true;
}

vtkSmartPointer<vtkPolyData> Torus(int n = 8000)
{
  return MakeCloud(Sample(pcurv::testing::Torus(3.0, 1.0), n, 77));
}

/// The cloud with extra points (and normals) appended at its end.
vtkSmartPointer<vtkPolyData> WithExtraPoints(vtkPolyData* cloud,
  const std::vector<std::array<double, 6>>& extra)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(cloud);
  vtkNew<vtkPolyData> fresh; // points and normals only: no stale exact arrays
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->DeepCopy(copy->GetPoints());
  vtkNew<vtkDoubleArray> normals;
  normals->DeepCopy(copy->GetPointData()->GetNormals());
  normals->SetName("Normals");
  for (const auto& e : extra)
  {
    points->InsertNextPoint(e[0], e[1], e[2]);
    normals->InsertNextTuple3(e[3], e[4], e[5]);
  }
  fresh->SetPoints(points);
  fresh->GetPointData()->SetNormals(normals);
  return fresh;
}

vtkSmartPointer<vtkPolyData> PointsOnly(vtkPolyData* cloud)
{
  return WithExtraPoints(cloud, {});
}

void Row(const char* name)
{
  std::printf("-- %s\n", name);
}

void TestConfigurationErrors(Checks& checks)
{
  auto cloud = Torus(2000);
  Row("no normals array");
  {
    vtkNew<vtkPolyData> bare;
    bare->SetPoints(cloud->GetPoints());
    const Outcome o = Run(bare);
    checks.True("no normals: an error", o.Errors >= 1);
    checks.True("no normals: message says so",
      o.Message.find("returned failure") != std::string::npos ||
        o.Message.find("ormals") != std::string::npos);
    checks.Equal("no normals: empty output", o.Output->GetNumberOfPoints(), 0);
  }
  for (const int components : { 1, 2, 4 })
  {
    Row("normals with 1, 2 or 4 components");
    auto input = PointsOnly(cloud);
    vtkNew<vtkDoubleArray> wrong;
    wrong->SetName("Wrong");
    wrong->SetNumberOfComponents(components);
    wrong->SetNumberOfTuples(input->GetNumberOfPoints());
    wrong->Fill(1.0);
    input->GetPointData()->AddArray(wrong);
    input->GetPointData()->SetActiveNormals(nullptr);
    auto choose = [](vtkPrincipalCurvatureEstimation* f)
    { f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Wrong"); };
    const Outcome o = Run(input, choose);
    char label[64];
    std::snprintf(label, sizeof(label), "%d-component normals: an error", components);
    checks.True(label, o.Errors >= 1);
    checks.Equal(label, o.Output->GetNumberOfPoints(), 0);
  }
  Row("vtkImageData (not a point set)");
  {
    vtkNew<vtkImageData> image;
    image->SetDimensions(4, 4, 4);
    const Outcome o = Run(image);
    checks.True("image data: rejected with an error", o.Errors >= 1);
  }
}

void TestFlaggedPoints(Checks& checks)
{
  auto cloud = PointsOnly(Torus());
  const vtkIdType n = cloud->GetNumberOfPoints();
  const Outcome clean = Run(cloud, FixedRadius);
  checks.Equal("clean torus: all estimated", clean.Unestimated, 0);

  Row("NaN and Inf coordinates");
  {
    auto input = WithExtraPoints(
      cloud, { { NaN, 0, 0, 0, 0, 1 }, { 0, Inf, 0, 0, 0, 1 }, { -Inf, NaN, 1, 1, 0, 0 } });
    const Outcome o = Run(input, FixedRadius);
    checks.True("non-finite points flagged",
      o.Valid(n) == 0 && o.Valid(n + 1) == 0 && o.Valid(n + 2) == 0 &&
        std::isnan(o.Value("Mean_Curvature", n)));
    checks.Equal("one warning with the count", o.Warnings, 1);
    checks.True("warning gives the count", o.Message.find("3 of") != std::string::npos);
    checks.True("other points unchanged", SameFirstPoints(o, clean, n));
  }
  Row("NaN normal, zero normal");
  {
    auto input = PointsOnly(cloud);
    input->GetPointData()->GetNormals()->SetTuple3(5, NaN, 0, 0);
    input->GetPointData()->GetNormals()->SetTuple3(6, 0, 0, 0);
    const Outcome o = Run(input, FixedRadius);
    checks.True("NaN and zero normals flagged", o.Valid(5) == 0 && o.Valid(6) == 0);
    checks.Equal("two unestimated", o.Unestimated, 2);
    int changed = 0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      changed +=
        i != 5 && i != 6 && o.Value("Mean_Curvature", i) != clean.Value("Mean_Curvature", i);
    }
    checks.Equal("other points unchanged (their neighbours' normals are not used)", changed, 0);
  }
  Row("non-unit normals");
  {
    auto input = PointsOnly(cloud);
    vtkDataArray* normals = input->GetPointData()->GetNormals();
    for (vtkIdType i = 0; i < n; ++i)
    {
      double v[3];
      normals->GetTuple(i, v);
      normals->SetTuple3(i, 7.5 * v[0], 7.5 * v[1], 7.5 * v[2]);
    }
    const Outcome o = Run(input, FixedRadius);
    double worst = 0.0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      worst =
        std::max(worst, std::fabs(o.Value("Mean_Curvature", i) - clean.Value("Mean_Curvature", i)));
    }
    checks.Below("normals of length 7.5: same curvatures", worst, 1e-12);
  }
  Row("an isolated point far from the rest");
  {
    auto input = WithExtraPoints(cloud, { { 100, 100, 100, 0, 0, 1 } });
    const Outcome o = Run(input, FixedRadius);
    checks.Equal("isolated point flagged", o.Valid(n), 0);
    checks.Equal("isolated point: 0 neighbours", static_cast<int>(o.Value("Neighbor_Count", n)), 0);
    // It widens the bounding box, hence the grid's cells and the order of
    // the sums: equal to rounding.
    checks.True("other points unchanged (to 1e-12)", SameFirstPoints(o, clean, n, 1e-12));
  }
}

void TestDegenerateClouds(Checks& checks)
{
  Row("empty input");
  {
    vtkNew<vtkPolyData> empty;
    vtkNew<vtkPoints> none;
    empty->SetPoints(none);
    const Outcome o = Run(empty);
    checks.Equal("empty: no error or warning", o.Errors + o.Warnings, 0);
    checks.Equal("empty: empty output", o.Output->GetNumberOfPoints(), 0);
  }
  auto make = [](const std::vector<std::array<double, 3>>& xyz)
  {
    vtkNew<vtkPolyData> d;
    vtkNew<vtkPoints> p;
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
    return vtkSmartPointer<vtkPolyData>(d.GetPointer());
  };
  Row("one point");
  {
    const Outcome o = Run(make({ { 1, 2, 3 } }));
    checks.True(
      "one point: flagged, one warning", o.Valid(0) == 0 && o.Warnings == 1 && o.Errors == 0);
  }
  Row("two identical points");
  {
    const Outcome o = Run(make({ { 1, 2, 3 }, { 1, 2, 3 } }));
    checks.True(
      "two identical points: both flagged", o.Valid(0) == 0 && o.Valid(1) == 0 && o.Errors == 0);
  }
  Row("points on a line");
  {
    std::vector<std::array<double, 3>> line;
    for (int i = 0; i < 500; ++i)
    {
      line.push_back({ { 0.01 * i, 0.0, 0.0 } });
    }
    const Outcome o = Run(make(line));
    checks.Equal("line: every point flagged", o.Unestimated, 500);
    checks.Equal("line: one warning", o.Warnings, 1);
  }
  Row("many duplicate points");
  {
    std::vector<SurfaceSample> samples = Sample(Sphere(1.0), 5000, 3);
    std::vector<SurfaceSample> tripled;
    for (const auto& s : samples)
    {
      tripled.insert(tripled.end(), { s, s, s });
    }
    const Outcome o = Run(MakeCloud(tripled));
    double worst = 0.0;
    for (vtkIdType i = 0; i < o.Output->GetNumberOfPoints(); ++i)
    {
      worst = std::max(worst, std::fabs(o.Value("Mean_Curvature", i) - 1.0));
    }
    checks.Equal("duplicates: all estimated", o.Unestimated, 0);
    checks.Below("duplicates: sphere curvature still 1", worst, 1e-6);
  }
}

void TestSettings(Checks& checks)
{
  auto cloud = Torus(4000);
  Row("radius 0 and negative");
  for (const double radius : { 0.0, -1.0 })
  {
    auto set = radius == 0.0 ? +[](vtkPrincipalCurvatureEstimation* f) {
      f->AutomaticThresholdsOff();
      f->SetSurroundingsThreshold(0.0);
    }
                             : +[](vtkPrincipalCurvatureEstimation* f) {
                                 f->AutomaticThresholdsOff();
                                 f->SetSurroundingsThreshold(-1.0); // clamped to 0
                               };
    const Outcome o = Run(cloud, set);
    checks.Equal("radius <= 0: every point flagged", o.Unestimated, cloud->GetNumberOfPoints());
    checks.Equal("radius <= 0: one warning, no error", o.Warnings * 10 + o.Errors, 10);
  }
  Row("radius larger than the cloud");
  {
    const Outcome o = Run(cloud,
      [](vtkPrincipalCurvatureEstimation* f)
      {
        f->AutomaticThresholdsOff();
        f->SetSurroundingsThreshold(100.0);
        f->SetPlaneDistanceThreshold(0.5);
      });
    checks.Equal("huge radius: no error", o.Errors, 0);
    checks.Equal("huge radius: every neighbour found",
      static_cast<long long>(o.Value("Neighbor_Count", 0)),
      cloud->GetNumberOfPoints() - 1);
    bool finite = true;
    for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
    {
      finite = finite && (o.Valid(i) == 0 || std::isfinite(o.Value("Mean_Curvature", i)));
    }
    checks.True("huge radius: estimates finite or flagged", finite);
  }
  Row("a neighbour count below the minimum");
  {
    vtkNew<vtkPrincipalCurvatureEstimation> f;
    f->SetNumberOfNeighbors(1);
    checks.Equal("NumberOfNeighbors clamped to 3", f->GetNumberOfNeighbors(), 3);
    f->SetMinimumPointsPerDirection(0);
    checks.Equal("MinimumPointsPerDirection clamped to 3", f->GetMinimumPointsPerDirection(), 3);
    const Outcome o = Run(cloud,
      [](vtkPrincipalCurvatureEstimation* g)
      {
        g->SetNeighborhoodModeToKNearest();
        g->SetNumberOfNeighbors(1);
      });
    checks.Equal("3 nearest neighbours: every point flagged (too few per direction)",
      o.Unestimated,
      cloud->GetNumberOfPoints());
  }
}

void TestTypesAndInputs(Checks& checks)
{
  Row("vtkUnstructuredGrid input");
  {
    auto cloud = MakeCloud(Sample(Sphere(2.0), 8000, 8));
    vtkNew<vtkUnstructuredGrid> grid;
    grid->SetPoints(cloud->GetPoints());
    grid->GetPointData()->ShallowCopy(cloud->GetPointData());
    const Outcome o = Run(grid);
    checks.Equal("unstructured grid: all estimated", o.Unestimated, 0);
    checks.Near("unstructured grid: curvature 1/2", o.Value("Mean_Curvature", 0), 0.5, 0.01);
    checks.True("input arrays passed through",
      o.Output->GetPointData()->GetArray("Exact_Minimum_Curvature") != nullptr);
    checks.Equal("vertex cells made", o.Output->GetNumberOfVerts(), o.Output->GetNumberOfPoints());
  }
  Row("integer coordinates and normals");
  {
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
    checks.Equal("integer types: all estimated", o.Unestimated, 0);
    checks.Near("integer types: sphere curvature 1/1000", mean, 1e-3, 2e-5);
  }
  Row("a cloud far from the origin, tiny and huge scales");
  {
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
          worst = std::max(worst,
            std::fabs(
              scale * o.Value("Maximum_Curvature", i) - reference.Value("Maximum_Curvature", i)));
        }
        char label[96];
        std::snprintf(label,
          sizeof(label),
          "scale %g, shift %g: curvature x scale unchanged",
          scale,
          shift * scale);
        // A shift of 1e6 spacings leaves about 1e-10 of the coordinates' precision.
        checks.Below(label, worst, shift > 0.0 ? 1e-6 : 1e-9);
      }
    }
  }
}
} // namespace

int main()
{
  Checks checks;
  TestConfigurationErrors(checks);
  TestFlaggedPoints(checks);
  TestDegenerateClouds(checks);
  TestSettings(checks);
  TestTypesAndInputs(checks);
  return checks.Summary();
}
