#include "vtkCurvatureLines.h"

#include "ControllerCollectives.h"
#include "FilterProgress.h"
#include "Lines/CurvatureLines.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkCurvatureLines);

namespace
{

/// A point-data array as doubles, `components` per point; empty when the
/// array is missing or has another number of components.
std::vector<double> ReadArray(vtkPointData* pd, const char* name, int components)
{
  std::vector<double> values;
  vtkDataArray* array = pd->GetArray(name);
  if (!array || array->GetNumberOfComponents() != components)
  {
    return values;
  }
  const vtkIdType n = array->GetNumberOfTuples();
  values.resize(static_cast<std::size_t>(n) * components);
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int k = 0; k < components; ++k)
    {
      values[i * components + k] = array->GetComponent(i, k);
    }
  }
  return values;
}

/// The normals the directions are tangent to: the fit's, else the input's.
std::vector<double> ReadNormals(vtkPointData* pd)
{
  std::vector<double> normals = ReadArray(pd, "Fitted_Normal", 3);
  if (normals.empty() && pd->GetNormals() && pd->GetNormals()->GetNumberOfComponents() == 3)
  {
    normals = ReadArray(pd, pd->GetNormals()->GetName(), 3);
  }
  return normals.empty() ? ReadArray(pd, "Normals", 3) : normals;
}

unsigned KindMask(int kinds)
{
  switch (kinds)
  {
    case vtkCurvatureLines::RIDGES:
      return pcurv::KindBit(pcurv::LineKind::Ridge);
    case vtkCurvatureLines::VALLEYS:
      return pcurv::KindBit(pcurv::LineKind::Valley);
    case vtkCurvatureLines::ALL_EXTREMAL_LINES:
      return pcurv::AllLineKinds;
    default:
      return pcurv::RidgesAndValleys;
  }
}

/// The field data Line_Counts: the lines of each kind, by code (what a
/// legend of the drawn kinds lists).
vtkSmartPointer<vtkIdTypeArray> KindCounts(const pcurv::LineResult& result)
{
  auto counts = vtkSmartPointer<vtkIdTypeArray>::New();
  counts->SetName(pcurv::LineCountsArrayName);
  counts->SetNumberOfComponents(pcurv::LineKindCount);
  counts->SetNumberOfTuples(1);
  counts->Fill(0);
  for (const pcurv::CurvatureLine& line : result.Lines)
  {
    const int code = static_cast<int>(line.Kind);
    counts->SetTypedComponent(0, code, counts->GetTypedComponent(0, code) + 1);
  }
  return counts;
}

/// The input's point coordinates, 3 per point.
std::vector<double> ReadPoints(vtkPointSet* input)
{
  const vtkIdType n = input->GetNumberOfPoints();
  std::vector<double> xyz(3 * static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    input->GetPoint(i, &xyz[3 * i]);
  }
  return xyz;
}

/// The filter's settings for the core.
pcurv::LineSettings CoreSettings(vtkCurvatureLines* self)
{
  pcurv::LineSettings settings;
  settings.Kinds = KindMask(self->GetKinds());
  settings.MinimumLength = self->GetMinimumLength();
  settings.MinimumStrength = self->GetMinimumStrength();
  settings.Significance = self->GetSignificance();
  return settings;
}

/// The one message of a run that drew no line, with what to change.
std::string NoLinesMessage(vtkCurvatureLines* self)
{
  std::ostringstream text;
  text << "Curvature Lines drew no line: no crest of the curvatures stands out of their noise "
          "(Significance "
       << self->GetSignificance() << ") over the Minimum Length (" << self->GetMinimumLength()
       << " neighborhood radii). Lower Significance or Minimum Length, or run Principal "
          "Curvatures at a larger scale.";
  return text.str();
}

/// The core's lines as polylines with their cell and point data.
void WriteLines(const pcurv::LineResult& result, vtkPolyData* output)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  auto kind = vtkSmartPointer<vtkUnsignedCharArray>::New();
  kind->SetName("Line_Kind");
  auto strength = vtkSmartPointer<vtkDoubleArray>::New();
  strength->SetName("Line_Strength");
  auto length = vtkSmartPointer<vtkDoubleArray>::New();
  length->SetName("Line_Length");
  auto curvature = vtkSmartPointer<vtkDoubleArray>::New();
  curvature->SetName("Line_Curvature");
  for (const pcurv::CurvatureLine& line : result.Lines)
  {
    const vtkIdType count = static_cast<vtkIdType>(line.Curvature.size());
    lines->InsertNextCell(count);
    for (vtkIdType i = 0; i < count; ++i)
    {
      lines->InsertCellPoint(points->InsertNextPoint(&line.Points[3 * i]));
      curvature->InsertNextValue(line.Curvature[i]);
    }
    kind->InsertNextValue(static_cast<unsigned char>(line.Kind));
    strength->InsertNextValue(line.Strength);
    length->InsertNextValue(line.Length);
  }
  output->SetPoints(points);
  output->SetLines(lines);
  output->GetCellData()->AddArray(kind);
  output->GetCellData()->SetActiveScalars("Line_Kind");
  output->GetCellData()->AddArray(strength);
  output->GetCellData()->AddArray(length);
  output->GetPointData()->AddArray(curvature);
  output->GetFieldData()->AddArray(KindCounts(result));
}

} // namespace

vtkCurvatureLines::vtkCurvatureLines() = default;

int vtkCurvatureLines::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkCurvatureLines::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input || !output)
  {
    vtkErrorMacro("Curvature Lines needs a point set as input.");
    return 0;
  }
  const vtkIdType n = input->GetNumberOfPoints();
  WriteLines(pcurv::LineResult{}, output);
  // In a parallel run every process takes part in every collective step,
  // even with an empty piece or bad input: failures are agreed on first.
  const pcurv::ControllerCollectives processes;
  if (n == 0 && !processes.IsDistributed())
  {
    return 1;
  }
  vtkPointData* pd = input->GetPointData();
  const std::vector<double> kMax = ReadArray(pd, "Maximum_Curvature", 1);
  const std::vector<double> kMin = ReadArray(pd, "Minimum_Curvature", 1);
  const std::vector<double> dMax = ReadArray(pd, "Maximum_Curvature_Direction", 3);
  const std::vector<double> dMin = ReadArray(pd, "Minimum_Curvature_Direction", 3);
  const std::vector<double> normals = ReadNormals(pd);
  const bool arraysFound =
    n == 0 || !(kMax.empty() || kMin.empty() || dMax.empty() || normals.empty());
  if (!arraysFound)
  {
    vtkErrorMacro("Curvature Lines needs the output of Principal Curvatures: the point arrays "
                  "Maximum_Curvature, Minimum_Curvature, Maximum_Curvature_Direction (3 "
                  "components) and normals (Fitted_Normal or Normals).");
  }
  if (!processes.Min(arraysFound ? 1 : 0))
  {
    return 0;
  }
  const std::vector<double> xyz = ReadPoints(input);
  const std::vector<double> standardError = ReadArray(pd, "Curvature_Standard_Error", 1);
  const std::vector<double> radius = ReadArray(pd, "Surroundings_Threshold", 1);
  const std::vector<double> validValues = ReadArray(pd, "Curvature_Valid", 1);
  std::vector<unsigned char> valid(validValues.begin(), validValues.end());

  pcurv::LineInput in;
  in.Count = n;
  in.Points = xyz.data();
  in.Normals = normals.data();
  in.MaximumCurvature = kMax.data();
  in.MinimumCurvature = kMin.data();
  in.MaximumDirection = dMax.data();
  in.MinimumDirection = dMin.empty() ? nullptr : dMin.data();
  in.StandardError = standardError.empty() ? nullptr : standardError.data();
  in.Radius = radius.empty() ? nullptr : radius.data();
  in.Valid = valid.empty() ? nullptr : valid.data();
  const pcurv::LineSettings settings = CoreSettings(this);
  try
  {
    pcurv::SMPToolsRunner runner(0);
    // Distributed: the lines of the whole cloud, on process 0.
    const pcurv::LineResult result = pcurv::ExtractCurvatureLines(in, settings, processes, &runner);
    WriteLines(result, output);
    // Every process takes part in the sum; process 0, which holds the
    // lines, says so once.
    const std::int64_t points = processes.Sum(static_cast<std::int64_t>(n));
    if (result.Lines.empty() && processes.GetLocalProcessId() == 0 && points > 0)
    {
      vtkWarningMacro(<< NoLinesMessage(this));
    }
  }
  catch (const pcurv::LineInputError& error)
  {
    vtkErrorMacro(<< error.what());
    return 0;
  }
  return 1;
}

void vtkCurvatureLines::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Kinds: " << this->Kinds << "\n";
  os << indent << "MinimumLength: " << this->MinimumLength << "\n";
  os << indent << "MinimumStrength: " << this->MinimumStrength << "\n";
  os << indent << "Significance: " << this->Significance << "\n";
}
