// Bad input, scale and types: point sets other than vtkPolyData, integer
// and float coordinates, clouds translated and scaled far from unit size,
// near-planar and nearly umbilic neighborhoods, one sub-test per row of
// docs/bad-input.md's table (see BadInputHelpers.h for what every sub-test
// also checks); and clouds at the edges of the double range, each its own
// test (TestBadInputScale --extreme NAME, see the end).
#include "BadInputHelpers.h"

#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStructuredGrid.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace
{
using namespace pcurv::testing;
using namespace pcurv::testing::badinput;

/// The samples as a cloud with points of VTK type `pointType` and normals in
/// a `NormalsArray`; `round` rounds the coordinates, and the normals times
/// 1000, for integer types.
template<typename NormalsArray>
vtkSmartPointer<vtkPolyData> TypedCloud(const std::vector<SurfaceSample>& samples,
  int pointType,
  bool round)
{
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataType(pointType);
  vtkNew<NormalsArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  for (const auto& s : samples)
  {
    if (round)
    {
      points->InsertNextPoint(
        std::round(s.Point[0]), std::round(s.Point[1]), std::round(s.Point[2]));
      normals->InsertNextTuple3(std::round(1000 * s.Normal[0]),
        std::round(1000 * s.Normal[1]),
        std::round(1000 * s.Normal[2]));
    }
    else
    {
      points->InsertNextPoint(s.Point.data());
      normals->InsertNextTuple(s.Normal.data());
    }
  }
  cloud->SetPoints(points);
  cloud->GetPointData()->SetNormals(normals);
  return cloud;
}

/// A sphere of radius 2 came out right: curvature 1/2 (to `tolerance`) at
/// every point, the contract, and the input passed through.
void CheckSphereOfRadius2(Checks& checks,
  const std::string& row,
  vtkPointSet* input,
  const Outcome& o,
  double tolerance)
{
  vtkIdType estimated = 0;
  checks.Below(
    Label(row, "curvature 1/2").c_str(), LargestError(o, 0.5, 0.5, &estimated), tolerance);
  checks.Equal(Label(row, "all estimated").c_str(), estimated, input->GetNumberOfPoints());
  CheckContract(checks, row, o, input->GetPointData()->GetNormals());
  CheckPassedThrough(checks, row, input, o);
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
    // New01 with its fixed radius estimates every point; the automatic
    // neighborhood starts from the 16 nearest, which near the poles lie on
    // one parallel (no spread of directions), and flags the few points
    // where no radius up to its largest gives a determined fit.
    CheckSphereOfRadius2(checks,
      row + ", New01",
      grid,
      Run(grid, [](vtkPrincipalCurvatureEstimation* f) { f->SetFitModeToNew01(); }),
      0.01);
    vtkIdType estimated = 0;
    const Outcome automatic = Run(grid);
    checks.Below(Label(row, "default: curvature 1/2").c_str(),
      LargestError(automatic, 0.5, 0.5, &estimated),
      0.01);
    checks.True(
      Label(row, "default: 99 % estimated").c_str(), estimated >= 0.99 * grid->GetNumberOfPoints());
    CheckContract(checks, row, automatic, grid->GetPointData()->GetNormals());
  }
  {
    const std::string row = "integer coordinates (VTK_INT) and normals (vtkIntArray)";
    Row(row);
    // A sphere of radius 1000 rounded to integers, normals times 1000 as ints.
    auto cloud = TypedCloud<vtkIntArray>(Sample(Sphere(1000.0), 20000, 9), VTK_INT, true);
    // Integer "normals" are refused (colors are integers, normals are not);
    // the integer points are estimated with normals the filter estimates.
    const Outcome refused = Run(cloud);
    checks.True(Label(row, "integer normals: an error naming the type").c_str(),
      refused.Errors >= 1 && refused.Saw("is of type int"));
    const Outcome o =
      Run(cloud, [](vtkPrincipalCurvatureEstimation* f) { f->SetNormalsSourceToEstimated(); });
    double mean = 0.0;
    for (vtkIdType i = 0; i < cloud->GetNumberOfPoints(); ++i)
    {
      mean += o.Value("Mean_Curvature", i) / cloud->GetNumberOfPoints();
    }
    checks.Equal(Label(row, "all estimated").c_str(), o.Unestimated, 0);
    checks.Near(Label(row, "sphere curvature 1/1000").c_str(), mean, 1e-3, 2e-5);
    checks.True(Label(row, "integer points kept as such").c_str(),
      o.Output->GetPoints()->GetDataType() == VTK_INT);
    CheckContract(checks, row, o, o.Output->GetPointData()->GetNormals());
  }
  {
    const std::string row = "float coordinates and normals";
    Row(row);
    auto cloud = TypedCloud<vtkFloatArray>(Sample(Sphere(2.0), 20000, 10), VTK_FLOAT, false);
    CheckSphereOfRadius2(checks, row, cloud, Run(cloud), 1e-3);
  }
}

/// Over the points farther from the boundary than the radius used: how many
/// there are, how many are estimated, and the largest |k - exact| (both
/// curvatures, exact from the cloud's Exact_* arrays).
struct InteriorError
{
  vtkIdType Interior = 0;
  vtkIdType Estimated = 0;
  double Largest = 0.0;
};

InteriorError MeasureInterior(const Outcome& o)
{
  InteriorError e;
  const double radius = o.UsedSurroundingsThreshold;
  for (vtkIdType i = 0; i < o.Points(); ++i)
  {
    if (o.Value("Boundary_Distance", i) > radius)
    {
      ++e.Interior;
      e.Estimated += o.Valid(i) == 1;
      e.Largest = std::max({ e.Largest,
        std::fabs(o.Value("Minimum_Curvature", i) - o.Value("Exact_Minimum_Curvature", i)),
        std::fabs(o.Value("Maximum_Curvature", i) - o.Value("Exact_Maximum_Curvature", i)) });
    }
  }
  return e;
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
    // A georeferenced scan: the same cloud at UTM-like coordinates. In
    // double, the same curvatures to a millionth of the largest and no
    // warning; in float, the coordinates are rounded to a fraction of a
    // metre, and a warning says by how much. At 5e6 the doubles are
    // themselves rounded to 1e-9, a noise that a noise-free cloud's height
    // jets (of 20 neighbors) see: a point whose choice between the jet and
    // the ladder's estimate lies at the threshold may flip (one of the 8000
    // here), and then its two values differ within their reported errors.
    const std::string row = "georeferenced: translated by (600000, 5000000, 100)";
    Row(row);
    auto reference = Run(Torus(8000));
    auto moved = Torus(8000);
    vtkPoints* p = moved->GetPoints();
    for (vtkIdType i = 0; i < p->GetNumberOfPoints(); ++i)
    {
      double x[3];
      p->GetPoint(i, x);
      p->SetPoint(i, x[0] + 600000.0, x[1] + 5000000.0, x[2] + 100.0);
    }
    const Outcome o = Run(moved);
    double largest = 0.0;
    for (vtkIdType i = 0; i < p->GetNumberOfPoints(); ++i)
    {
      largest = std::max({ largest,
        std::fabs(reference.Value("Minimum_Curvature", i)),
        std::fabs(reference.Value("Maximum_Curvature", i)) });
    }
    int beyond = 0, outsideErrors = 0;
    for (vtkIdType i = 0; i < p->GetNumberOfPoints(); ++i)
    {
      double moved = 0.0;
      for (const char* name : { "Minimum_Curvature", "Maximum_Curvature" })
      {
        moved = std::max(moved, std::fabs(o.Value(name, i) - reference.Value(name, i)));
      }
      const double error = std::max(
        o.Value("Curvature_Standard_Error", i), reference.Value("Curvature_Standard_Error", i));
      beyond += moved > 1e-6 * largest;
      outsideErrors += !(moved <= error);
    }
    checks.Below(
      Label(row, "double: curvatures within 1e-6 of the largest but at 0.1 % of the points")
        .c_str(),
      beyond,
      0.001 * p->GetNumberOfPoints());
    checks.Equal(Label(row, "double: every point's curvatures within its reported error").c_str(),
      outsideErrors,
      0);
    checks.Equal(Label(row, "double: all estimated").c_str(), o.Unestimated, 0);
    checks.Equal(Label(row, "double: no warning").c_str(), o.Warnings, 0);
    vtkNew<vtkPoints> rounded;
    rounded->SetDataTypeToFloat();
    rounded->DeepCopy(p);
    moved->SetPoints(rounded);
    const Outcome f = Run(moved);
    const bool named = std::any_of(f.Messages.begin(),
      f.Messages.end(),
      [](const std::string& m)
      {
        return m.find("stored as float") != std::string::npos &&
          m.find("0.5 apart") != std::string::npos;
      });
    checks.True(
      Label(row, "float: a warning that the coordinates are rounded 0.5 apart").c_str(), named);
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
    const InteriorError e = MeasureInterior(o); // the exact curvatures are 0
    checks.Equal(Label(row, "interior points all estimated").c_str(), e.Estimated, e.Interior);
    checks.Below(Label(row, "|k| at rounding level").c_str(), e.Largest, 1e-9);
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
    const InteriorError e = MeasureInterior(o);
    checks.Equal(Label(row, "interior points all estimated").c_str(), e.Estimated, e.Interior);
    checks.Below(Label(row, "error below 1 % of the curvature").c_str(), e.Largest, 1e-6);
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

/// Clouds at the edges of the double range, each run as its own test
/// (TestBadInputScale --extreme NAME) so that a hang shows as that test's
/// timeout: flagging the points is acceptable, a hang, a crash or a wrong
/// number is not.
///  - Tiny: a torus scaled by 2^-665 (about 1.6e-200: squared distances
///    underflow);
///  - Huge: a torus scaled by 2^531 (about 5.5e159: squared distances
///    overflow).
/// Powers of two, so that the scaled clouds are exact copies: the filter
/// works in a power-of-two unit of its own and must then give the clean
/// run's numbers; with another factor, rounding moves the automatic
/// radius by an ulp and with it neighbors that lie exactly on it.
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
  TestTypesAndInputs(checks);
  TestNumericalHardening(checks);
  return checks.Summary();
}
