// vtkCurvatureLines, the VTK glue: behind vtkPrincipalCurvatureEstimation
// on an ellipsoid it gives polylines on the principal ellipses with their
// arrays and the count of each kind; an input without curvature arrays is
// one clear error; an empty input gives an empty output; a plane, no line
// and one warning saying what to change.
#include "AnalyticClouds.h"
#include "TestChecks.h"
#include "vtkCurvatureLines.h"
#include "vtkPrincipalCurvatureEstimation.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <cmath>
#include <cstdlib>
#include <string>

namespace
{
using namespace pcurv::testing;

/// Counts the errors a filter (or its executive) raises.
struct ErrorCount
{
  int Errors = 0;
  std::string Last; // every message, one after another
};

void Observe(vtkAlgorithm* filter,
  vtkCallbackCommand* callback,
  ErrorCount& count,
  unsigned long event = vtkCommand::ErrorEvent)
{
  callback->SetClientData(&count);
  callback->SetCallback(
    [](vtkObject*, unsigned long, void* client, void* data)
    {
      auto* c = static_cast<ErrorCount*>(client);
      ++c->Errors;
      c->Last += data ? static_cast<const char*>(data) : "";
    });
  filter->AddObserver(event, callback);
  filter->GetExecutive()->AddObserver(event, callback);
}

/// Largest distance of the lines' points to the ellipsoid's three
/// principal planes' sections: each point lies in one of the planes.
double LargestPlaneDistance(vtkPolyData* lines)
{
  double largest = 0.0;
  for (vtkIdType i = 0; i < lines->GetNumberOfPoints(); ++i)
  {
    double x[3];
    lines->GetPoint(i, x);
    largest = std::max(largest, std::min({ std::fabs(x[0]), std::fabs(x[1]), std::fabs(x[2]) }));
  }
  return largest;
}

} // namespace

int main(int, char*[])
{
  Checks checks;
  const int n = 30000;
  vtkSmartPointer<vtkPolyData> cloud = MakeCloud(Sample(Ellipsoid(3.0, 2.0, 1.0), n, 83));
  vtkNew<vtkPrincipalCurvatureEstimation> curvatures;
  curvatures->SetInputData(cloud);
  vtkNew<vtkCurvatureLines> lines;
  lines->SetInputConnection(curvatures->GetOutputPort());
  lines->SetKinds(vtkCurvatureLines::ALL_EXTREMAL_LINES);
  lines->Update();
  vtkPolyData* out = lines->GetOutput();
  const double spacing = std::sqrt(4.0 * Pi * 4.0 / n);
  std::printf("ellipsoid: %lld lines, %lld points, farthest %.3f spacings from the planes\n",
    static_cast<long long>(out->GetNumberOfLines()),
    static_cast<long long>(out->GetNumberOfPoints()),
    LargestPlaneDistance(out) / spacing);
  checks.True("ellipsoid: lines", out->GetNumberOfLines() >= 3);
  checks.True("ellipsoid: on the principal planes", LargestPlaneDistance(out) < 2.0 * spacing);
  checks.True("cell arrays",
    out->GetCellData()->GetArray("Line_Kind") && out->GetCellData()->GetArray("Line_Strength") &&
      out->GetCellData()->GetArray("Line_Length"));
  checks.True("point array", out->GetPointData()->GetArray("Line_Curvature") != nullptr);
  // Line_Counts: the lines of each kind, as the cells say.
  vtkDataArray* counts = out->GetFieldData()->GetArray("Line_Counts");
  vtkDataArray* kinds = out->GetCellData()->GetArray("Line_Kind");
  bool countsAgree = counts && kinds && counts->GetNumberOfComponents() == 6;
  for (int code = 0; countsAgree && code < 6; ++code)
  {
    vtkIdType cells = 0;
    for (vtkIdType c = 0; c < kinds->GetNumberOfTuples(); ++c)
    {
      cells += kinds->GetComponent(c, 0) == code ? 1 : 0;
    }
    countsAgree = counts->GetComponent(0, code) == cells;
  }
  checks.True("Line_Counts: each kind's lines", countsAgree);

  // A plane: no line, and one warning that says what to change.
  vtkNew<vtkPrincipalCurvatureEstimation> flatCurvatures;
  flatCurvatures->SetInputData(MakeCloud(Sample(Plane(1.0), 4000, 5)));
  vtkNew<vtkCurvatureLines> flat;
  vtkNew<vtkCallbackCommand> warningCallback;
  ErrorCount warnings;
  Observe(flat, warningCallback, warnings, vtkCommand::WarningEvent);
  flat->SetInputConnection(flatCurvatures->GetOutputPort());
  flat->Update();
  std::printf("plane: %lld lines, warnings: %s\n",
    static_cast<long long>(flat->GetOutput()->GetNumberOfLines()),
    warnings.Last.c_str());
  checks.True("plane: no line, one warning saying so and what to lower",
    flat->GetOutput()->GetNumberOfLines() == 0 && warnings.Errors == 1 &&
      warnings.Last.find("drew no line") != std::string::npos &&
      warnings.Last.find("Significance") != std::string::npos);
  vtkNew<vtkCallbackCommand> quietCallback;
  ErrorCount quiet;
  Observe(lines, quietCallback, quiet, vtkCommand::WarningEvent);
  lines->Modified();
  lines->Update();
  checks.True("ellipsoid: no warning", quiet.Errors == 0);

  // The raw cloud (no curvatures): one error naming what is missing.
  vtkNew<vtkCurvatureLines> bare;
  vtkNew<vtkCallbackCommand> callback;
  ErrorCount count;
  Observe(bare, callback, count);
  bare->SetInputData(cloud);
  bare->Update();
  checks.True("no curvature arrays: an error naming them",
    count.Errors >= 1 && count.Last.find("Maximum_Curvature") != std::string::npos);
  checks.True("no curvature arrays: no lines", bare->GetOutput()->GetNumberOfLines() == 0);

  vtkNew<vtkPolyData> empty;
  vtkNew<vtkCurvatureLines> none;
  ErrorCount emptyCount;
  vtkNew<vtkCallbackCommand> emptyCallback;
  Observe(none, emptyCallback, emptyCount);
  none->SetInputData(empty);
  none->Update();
  checks.True("empty input: no error, no lines",
    emptyCount.Errors == 0 && none->GetOutput()->GetNumberOfLines() == 0);
  return checks.Summary();
}
