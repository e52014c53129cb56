// Bad input, points: NaN, Inf, zero and badly scaled normals and
// coordinates, an isolated point, one far outlier, and degenerate clouds
// (empty, one point, duplicates, a line), one sub-test per row of
// docs/bad-input.md's table (see BadInputHelpers.h for what every sub-test
// also checks).
#include "BadInputHelpers.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace
{
using namespace pcurv::testing;
using namespace pcurv::testing::badinput;

void FixedRadius(vtkPrincipalCurvatureEstimation* f)
{
  f->AutomaticThresholdsOff();
  f->SetSurroundingsThreshold(0.8);
  f->SetPlaneDistanceThreshold(0.08);
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
/// for bit, or within `tolerance` (a change of the neighbor grid's cells
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

/// Every normal times `factor`.
void ScaleNormals(vtkDataArray* normals, double factor)
{
  for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
  {
    double v[3];
    normals->GetTuple(i, v);
    normals->SetTuple3(i, factor * v[0], factor * v[1], factor * v[2]);
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
    checks.Equal(Label(row, "they have no neighbors").c_str(),
      static_cast<long long>(o.Value("Neighbor_Count", n) + o.Value("Neighbor_Count", n + 3)),
      0);
    checks.True(Label(row, "other points bit-identical (left out of every neighborhood)").c_str(),
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
    const Outcome flagged = Run(input, FixedRadius);
    checks.True(Label(row, "those points flagged").c_str(),
      flagged.Valid(5) == 0 && flagged.Valid(6) == 0 && flagged.Valid(7) == 0 &&
        flagged.Valid(8) == 0);
    checks.Equal(Label(row, "four unestimated").c_str(), flagged.Unestimated, 4);
    CheckContract(checks, row, flagged, normals);
    // The paper's fits use only the point's own normal, so the others are
    // bit-identical there (OrientedCircles also uses the neighbors'
    // normals: a bad one then just adds no normal row to their fits).
    const auto paperFixed = [](vtkPrincipalCurvatureEstimation* f)
    {
      FixedRadius(f);
      f->SetFitModeToNew01();
    };
    const Outcome o = Run(input, paperFixed);
    checks.Equal(Label(row, "New01: four unestimated").c_str(), o.Unestimated, 4);
    const Outcome reference = Run(cloud, paperFixed);
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
    ScaleNormals(normals, 7.5);
    const Outcome o = Run(input, FixedRadius);
    checks.True(Label(row, "same results as unit normals (1e-12)").c_str(),
      SameFirstPoints(o, clean, n, 1e-12));
    CheckContract(checks, row, o, normals);
    CheckPassedThrough(checks, row, input, o);
  }
  for (const double length : { 1e-170, 1e170 })
  {
    // Finite and not zero, so docs/bad-input.md promises an estimate; but the
    // squared length under- or overflows.
    char row[64];
    std::snprintf(row, sizeof(row), "normals of length %g", length);
    Row(row);
    auto input = PointsOnly(cloud);
    ScaleNormals(input->GetPointData()->GetNormals(), length);
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
    // An outlier: the curvatures of the surface nearest to it, flagged.
    checks.Equal(Label(row, "an outlier").c_str(), static_cast<int>(o.Value("Outlier", n)), 1);
    checks.Equal(Label(row, "estimated").c_str(), o.Valid(n), 1);
    checks.True(
      Label(row, "its distance to the torus").c_str(), o.Value("Surface_Distance", n) > 100.0);
    checks.True(Label(row, "no other outlier").c_str(), o.Value("Outlier", 0) == 0);
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

/// One far outlier, as a "missing value" sentinel in a file makes: the
/// torus must keep its estimates, bit for bit, and the outlier is flagged,
/// in every neighborhood mode, with or without given normals. At 1e110 the
/// neighbor grid would need more cells than a double counts; at 1e300 a
/// working unit taken from the largest coordinate would make the torus's
/// squared distances underflow.
void TestFarOutlier(Checks& checks)
{
  auto exact = Torus();
  const vtkIdType n = exact->GetNumberOfPoints();
  for (const double far : { 1e7, -1e7, 1e110, 1e300 })
  {
    for (const bool given : { true, false })
    {
      auto cloud = PointsOnly(exact);
      auto input = WithExtraPoints(cloud, { { far, far, far, 0, 0, 1 } });
      if (!given)
      {
        cloud->GetPointData()->SetNormals(nullptr);
        input->GetPointData()->SetNormals(nullptr);
      }
      for (const NeighborhoodMode& mode : Modes)
      {
        char row[160];
        std::snprintf(row,
          sizeof(row),
          "one outlier at (%g, %g, %g), %s, %s",
          far,
          far,
          far,
          given ? "given normals" : "no normals",
          mode.Name);
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
        checks.True(Label(row, "bit for bit").c_str(), SameFirstPoints(o, clean, n));
        CheckContract(checks, row, o, input->GetPointData()->GetNormals());
        CheckPassedThrough(checks, row, input, o);
      }
    }
  }
}
} // namespace

int main()
{
  Checks checks;
  TestFlaggedPoints(checks);
  TestFarOutlier(checks);
  TestDegenerateClouds(checks);
  return checks.Summary();
}
