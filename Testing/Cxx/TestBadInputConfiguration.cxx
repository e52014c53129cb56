// Bad input, configuration: a missing or unusable normals array, an input
// that is not a point set, and settings out of range (clamped, flagged or
// warned about), one sub-test per row of docs/bad-input.md's table (see
// BadInputHelpers.h for what every sub-test also checks).
#include "BadInputHelpers.h"

#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace
{
using namespace pcurv::testing;
using namespace pcurv::testing::badinput;

void TestConfigurationErrors(Checks& checks)
{
  auto cloud = PointsOnly(Torus(2000));
  {
    const std::string row = "no normals array";
    Row(row);
    vtkNew<vtkPolyData> bare;
    bare->SetPoints(cloud->GetPoints());
    const Outcome o =
      Run(bare, [](vtkPrincipalCurvatureEstimation* f) { f->SetNormalsSourceToInput(); });
    checks.True(Label(row, "with NormalsSource Input: an error").c_str(), o.Errors >= 1);
    checks.True(Label(row, "the error says what is missing and how to estimate").c_str(),
      o.Saw("No normals: the input needs a 3-component point-data normals array") &&
        o.Saw("NormalsSource"));
    checks.Equal(Label(row, "no warning").c_str(), o.Warnings, 0);
    checks.Equal(Label(row, "empty output").c_str(), o.Points(), 0);
    const Outcome automatic = Run(bare);
    checks.Equal(Label(row, "by default: no error").c_str(), automatic.Errors, 0);
    checks.True(Label(row, "by default: normals estimated, 90 % of the points estimated").c_str(),
      automatic.Unestimated <= bare->GetNumberOfPoints() / 10);
    checks.True(Label(row, "by default: the estimated normals are the output's Normals").c_str(),
      automatic.Output->GetPointData()->GetNormals() &&
        automatic.Output->GetPointData()->GetNormals()->GetNumberOfTuples() ==
          bare->GetNumberOfPoints());
  }
  {
    // A PLY's colors: ParaView offers the first 3-component array as the
    // normals, and RGB was taken for normals (5 % of the points estimated,
    // all nonsense).
    const std::string row = "colors (unsigned char RGB) chosen as normals";
    Row(row);
    auto input = PointsOnly(cloud);
    input->GetPointData()->SetActiveNormals(nullptr);
    input->GetPointData()->RemoveArray("Normals");
    vtkNew<vtkUnsignedCharArray> rgb;
    rgb->SetName("RGB");
    rgb->SetNumberOfComponents(3);
    rgb->SetNumberOfTuples(input->GetNumberOfPoints());
    for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
    {
      rgb->SetTuple3(i, (7 * i) % 256, (13 * i) % 256, (29 * i) % 256);
    }
    input->GetPointData()->AddArray(rgb);
    auto chooseRgb = [](vtkPrincipalCurvatureEstimation* f)
    { f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "RGB"); };
    const Outcome automatic = Run(input, chooseRgb);
    checks.Equal(Label(row, "by default: no error").c_str(), automatic.Errors, 0);
    checks.True(Label(row, "by default: a warning says normals were estimated instead").c_str(),
      automatic.Saw("'RGB'") && automatic.Saw("normals were estimated instead"));
    checks.True(Label(row, "by default: 90 % of the points estimated").c_str(),
      automatic.Unestimated <= input->GetNumberOfPoints() / 10);
    const Outcome strict = Run(input,
      [&](vtkPrincipalCurvatureEstimation* f)
      {
        chooseRgb(f);
        f->SetNormalsSourceToInput();
      });
    checks.True(Label(row, "as input normals: an error naming the array and the way out").c_str(),
      strict.Errors >= 1 && strict.Saw("'RGB'") && strict.Saw("unsigned char") &&
        strict.Saw("To estimate normals instead"));
    checks.Equal(Label(row, "as input normals: empty output").c_str(), strict.Points(), 0);
  }
  {
    const std::string row = "all-zero normals";
    Row(row);
    auto input = PointsOnly(cloud);
    input->GetPointData()->GetNormals()->Fill(0.0);
    const Outcome o = Run(input);
    checks.True(Label(row, "an error of its own").c_str(),
      o.Errors >= 1 && o.Saw("all normals zero") && o.Saw("To estimate normals instead"));
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
    auto chooseMissing = [](vtkPrincipalCurvatureEstimation* f)
    { f->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "NoSuchArray"); };
    const Outcome o = Run(cloud,
      [&](vtkPrincipalCurvatureEstimation* f)
      {
        chooseMissing(f);
        f->SetNormalsSourceToInput();
      });
    checks.True(
      Label(row, "as input normals: an error").c_str(), o.Errors >= 1 && o.Saw("No normals"));
    checks.Equal(Label(row, "as input normals: empty output").c_str(), o.Points(), 0);
    const Outcome automatic = Run(cloud, chooseMissing);
    checks.True(Label(row, "by default: a warning naming it, the normals attribute used").c_str(),
      automatic.Errors == 0 && automatic.Saw("'NoSuchArray'") &&
        automatic.Points() == cloud->GetNumberOfPoints());
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
    // The grid's cells grow from the radius until they are few enough; a
    // subnormal size times 1.01 rounded back to itself and never grew (a
    // hang found by fuzzing the core's cloud-level entry point).
    const std::string row = "radius 1e-320 (subnormal)";
    Row(row);
    const Outcome o = Run(cloud,
      [](vtkPrincipalCurvatureEstimation* g)
      {
        g->AutomaticThresholdsOff();
        g->SetSurroundingsThreshold(1e-320);
      });
    checks.Equal(
      Label(row, "every point flagged").c_str(), o.Unestimated, cloud->GetNumberOfPoints());
    CheckContract(checks, row, o, normals);
  }
  {
    // No typical spacing, so a length unit of 0 and blocks of side 0: the
    // block index was a NaN cast to an integer (found by fuzzing).
    const std::string row = "dynamic adjustment on coincident points";
    Row(row);
    const auto same =
      WithExtraPoints(Torus(0), std::vector<std::array<double, 6>>(12, { 1, 2, 3, 0, 0, 1 }));
    const Outcome o =
      Run(same, [](vtkPrincipalCurvatureEstimation* g) { g->DynamicAdjustmentOn(); });
    checks.Equal(Label(row, "every point flagged").c_str(), o.Unestimated, 12);
    checks.Equal(Label(row, "no error").c_str(), o.Errors, 0);
  }
  {
    const std::string row = "plane distance 0";
    Row(row);
    const Outcome o = Run(cloud,
      [](vtkPrincipalCurvatureEstimation* g)
      {
        g->SetFitModeToNew01(); // the half planes' thickness: the paper's fits
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
    checks.Equal(Label(row, "every other point is a neighbor").c_str(),
      static_cast<long long>(o.Value("Neighbor_Count", 0)),
      cloud->GetNumberOfPoints() - 1);
    CheckContract(checks, row, o, normals);
    CheckPassedThrough(checks, row, cloud, o);
  }
  {
    const std::string row = "a neighbor count below the minimum";
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
} // namespace

int main()
{
  Checks checks;
  TestConfigurationErrors(checks);
  TestSettings(checks);
  return checks.Summary();
}
