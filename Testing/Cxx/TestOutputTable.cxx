// The table of output arrays (Core/Estimation/OutputTable.h) against what
// the filter writes (names, types, components, which runs have them) and
// against what the documentation says of them (docs/output-arrays.md and
// the help page's table): one place to add an output, and a failure here
// when any of them disagree.
//   TestOutputTable Arrays | Docs SOURCE_DIR
#include "vtkPrincipalCurvatureEstimation.h"

#include "AnalyticClouds.h"
#include "AnalyticSurfaces.h"
#include "Estimation/OutputTable.h"
#include "TestChecks.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
std::string SourceDir = ".";

using pcurv::Output;
using pcurv::OutputArray;
using pcurv::OutputCondition;
using pcurv::OutputValue;

std::vector<const OutputArray*> Rows()
{
  std::vector<const OutputArray*> rows;
  for (int i = 0; i < static_cast<int>(Output::Count); ++i)
  {
    rows.push_back(&pcurv::OutputOf(static_cast<Output>(i)));
  }
  return rows;
}

bool HasType(vtkDataArray* array, OutputValue value, bool single)
{
  switch (value)
  {
    case OutputValue::Real:
      return single ? vtkFloatArray::SafeDownCast(array) != nullptr
                    : array->GetDataType() == VTK_DOUBLE;
    case OutputValue::Int:
      return vtkIntArray::SafeDownCast(array) != nullptr;
    case OutputValue::UnsignedChar:
      return vtkUnsignedCharArray::SafeDownCast(array) != nullptr;
  }
  return false;
}

/// One run on a sphere; the table's rows against its point arrays.
void CheckRun(Checks& checks,
  const std::string& run,
  int fitMode,
  bool adjusted,
  bool diagnostics,
  bool single)
{
  vtkSmartPointer<vtkPolyData> cloud =
    pcurv::testing::MakeCloud(pcurv::testing::Sample(pcurv::testing::Sphere(1.0), 2000, 3));
  vtkNew<vtkPrincipalCurvatureEstimation> filter;
  filter->SetInputData(cloud);
  filter->SetFitMode(fitMode);
  filter->SetDynamicAdjustment(adjusted);
  filter->SetDiagnosticArrays(diagnostics);
  filter->SetSinglePrecisionOutput(single);
  filter->Update();
  vtkPointData* data = filter->GetOutput()->GetPointData();
  const bool standardError = fitMode == vtkPrincipalCurvatureEstimation::ORIENTED_CIRCLES;
  for (const OutputArray* row : Rows())
  {
    const bool expected = (!row->Diagnostic || diagnostics) &&
      (row->Condition != OutputCondition::DynamicAdjustment || adjusted) &&
      (row->Condition != OutputCondition::Display || diagnostics) &&
      (row->Condition != OutputCondition::StandardError || standardError);
    vtkDataArray* array = data->GetArray(row->Name);
    checks.True((run + ": " + row->Name + (expected ? " written" : " not written")).c_str(),
      (array != nullptr) == expected);
    if (array)
    {
      checks.True((run + ": " + row->Name + " has the table's type and components").c_str(),
        HasType(array, row->Value, single) && array->GetNumberOfComponents() == row->Components);
    }
  }
  for (int i = 0; i < data->GetNumberOfArrays(); ++i)
  {
    const std::string name = data->GetArrayName(i);
    const bool input = cloud->GetPointData()->GetArray(name.c_str()) != nullptr;
    checks.True((run + ": the output's " + name + " is in the table").c_str(),
      input || name == "Normals" || pcurv::FindOutput(name) != nullptr);
  }
}

void TestArrays(Checks& checks)
{
  CheckRun(
    checks, "default", vtkPrincipalCurvatureEstimation::ORIENTED_CIRCLES, false, true, false);
  CheckRun(checks, "paper, adjusted", vtkPrincipalCurvatureEstimation::NEW01, true, true, false);
  CheckRun(
    checks, "small output", vtkPrincipalCurvatureEstimation::ORIENTED_CIRCLES, false, false, true);
}

/// The names between `open` and `close` marks in `text` (backticks, or
/// a cell's tags), split at ", ".
std::vector<std::string> NamesIn(const std::string& cell, char mark)
{
  std::vector<std::string> names;
  for (std::size_t at = cell.find(mark); at != std::string::npos; at = cell.find(mark, at + 1))
  {
    const std::size_t end = cell.find(mark, at + 1);
    if (end == std::string::npos)
    {
      break;
    }
    names.push_back(cell.substr(at + 1, end - at - 1));
    at = end;
  }
  return names;
}

/// The rows "| `A`, `B` | type | meaning |" of docs/output-arrays.md, by
/// name: the type cell, then the meaning.
std::map<std::string, std::pair<std::string, std::string>> MarkdownRows(const std::string& text)
{
  std::map<std::string, std::pair<std::string, std::string>> rows;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
  {
    if (line.compare(0, 3, "| `") != 0)
    {
      continue;
    }
    const std::size_t second = line.find(" | ", 2), third = line.find(" | ", second + 3);
    if (second == std::string::npos || third == std::string::npos)
    {
      continue;
    }
    const std::string type = line.substr(second + 3, third - second - 3);
    for (const std::string& name : NamesIn(line.substr(0, second), '`'))
    {
      rows[name] = { type, line.substr(third + 3) };
    }
  }
  return rows;
}

std::string TypeWords(const OutputArray& row)
{
  const char* words[] = { "double", "int", "unsigned char" };
  return words[static_cast<int>(row.Value)] +
    (row.Components > 1 ? ", " + std::to_string(row.Components) : std::string());
}

/// The help page's rows "<tr><td>A, B</td><td>meaning</td></tr>" by name.
std::map<std::string, std::string> HelpRows(const std::string& text)
{
  std::map<std::string, std::string> rows;
  std::istringstream lines(text);
  const std::string open = "<tr><td>", middle = "</td><td>";
  for (std::string line; std::getline(lines, line);)
  {
    const std::size_t split = line.find(middle);
    if (line.compare(0, open.size(), open) != 0 || split == std::string::npos)
    {
      continue;
    }
    std::istringstream names(line.substr(open.size(), split - open.size()));
    for (std::string name; std::getline(names >> std::ws, name, ',');)
    {
      rows[name] = line.substr(split + middle.size());
    }
  }
  return rows;
}

void TestDocs(Checks& checks)
{
  const std::string markdown = ReadTextFile(SourceDir + "/docs/output-arrays.md");
  const std::string help =
    ReadTextFile(SourceDir + "/Plugin/Help/filters.PrincipalCurvatureEstimation.html");
  checks.True("docs/output-arrays.md and the help page read", !markdown.empty() && !help.empty());
  const auto documented = MarkdownRows(markdown);
  const auto helped = HelpRows(help);
  std::set<std::string> diagnostics;
  const std::string listStart = "The *diagnostic* arrays (";
  const std::size_t list = markdown.find(listStart);
  const std::size_t listEnd = markdown.find(')', list);
  if (list != std::string::npos && listEnd != std::string::npos)
  {
    const std::string names = markdown.substr(list, listEnd - list);
    for (const std::string& name : NamesIn(names, '`'))
    {
      diagnostics.insert(name);
    }
  }
  for (const OutputArray* row : Rows())
  {
    const std::string name = row->Name;
    const auto doc = documented.find(name);
    checks.True(("output-arrays.md has a row for " + name).c_str(), doc != documented.end());
    if (doc != documented.end())
    {
      checks.True(("output-arrays.md: " + name + " is " + TypeWords(*row)).c_str(),
        doc->second.first == TypeWords(*row));
      checks.True(("output-arrays.md: " + name + "'s condition").c_str(),
        (row->Condition == OutputCondition::StandardError) ==
            (doc->second.second.find("with OrientedCircles only") != std::string::npos) &&
          (row->Condition == OutputCondition::DynamicAdjustment) ==
            (doc->second.second.find("with `DynamicAdjustment` only") != std::string::npos));
    }
    checks.True(("output-arrays.md lists " + name + " as diagnostic exactly when it is").c_str(),
      diagnostics.count(name) == (row->Diagnostic ? 1u : 0u));
    const auto page = helped.find(name);
    checks.True(("the help page has a row for " + name).c_str(), page != helped.end());
    if (page != helped.end())
    {
      checks.True(("the help page: " + name + "'s condition and diagnostic mark").c_str(),
        (row->Condition == OutputCondition::StandardError) ==
            (page->second.compare(0, 15, "(OrientedCircle") == 0) &&
          row->Diagnostic ==
            (page->second.find("diagnostic)") != std::string::npos ||
              page->second.find("diagnostic,") != std::string::npos));
    }
  }
  for (const auto& entry : documented)
  {
    checks.True(("output-arrays.md's " + entry.first + " is in the table").c_str(),
      pcurv::FindOutput(entry.first) != nullptr);
  }
}

} // namespace

int main(int argc, char* argv[])
{
  if (argc > 2)
  {
    SourceDir = argv[2];
  }
  return RunNamedTests(argc > 2 ? 2 : argc,
    argv,
    {
      { "Arrays", TestArrays },
      { "Docs", TestDocs },
    });
}
