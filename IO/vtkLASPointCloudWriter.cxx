#include "vtkLASPointCloudWriter.h"

#include "FileFormats/LasWriter.h"
#include "LasFieldData.h"

#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"

#include <set>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkLASPointCloudWriter);

namespace
{
using pcurv::las::Column;
using pcurv::las::PointSet;
using pcurv::las::ValueType;

/// The LAS value type of a VTK array type; Undocumented for the others
/// (bits, strings).
ValueType ValueTypeOf(int vtkType)
{
  switch (vtkType)
  {
    case VTK_UNSIGNED_CHAR:
      return ValueType::UInt8;
    case VTK_CHAR:
    case VTK_SIGNED_CHAR:
      return ValueType::Int8;
    case VTK_UNSIGNED_SHORT:
      return ValueType::UInt16;
    case VTK_SHORT:
      return ValueType::Int16;
    case VTK_UNSIGNED_INT:
      return ValueType::UInt32;
    case VTK_INT:
      return ValueType::Int32;
    case VTK_UNSIGNED_LONG:
      return sizeof(unsigned long) == 8 ? ValueType::UInt64 : ValueType::UInt32;
    case VTK_LONG:
      return sizeof(long) == 8 ? ValueType::Int64 : ValueType::Int32;
    case VTK_UNSIGNED_LONG_LONG:
      return ValueType::UInt64;
    case VTK_LONG_LONG:
      return ValueType::Int64;
    case VTK_ID_TYPE:
      return sizeof(vtkIdType) == 8 ? ValueType::Int64 : ValueType::Int32;
    case VTK_FLOAT:
      return ValueType::Float32;
    case VTK_DOUBLE:
      return ValueType::Float64;
    default:
      return ValueType::Undocumented;
  }
}

/// Component c of array as a column (arrays hold their tuples' values
/// interleaved).
Column ColumnOf(vtkDataArray* array, int c)
{
  Column column;
  column.Data = array->GetVoidPointer(c);
  column.Type = ValueTypeOf(array->GetDataType());
  column.Stride = static_cast<std::size_t>(array->GetNumberOfComponents());
  return column;
}

/// The standard field an array of this name fills, or null.
Column* StandardField(PointSet& points, const std::string& name)
{
  const struct
  {
    const char* Name;
    Column PointSet::*Field;
  } fields[] = { { "Intensity", &PointSet::Intensity },
    { "ReturnNumber", &PointSet::ReturnNumber },
    { "NumberOfReturns", &PointSet::NumberOfReturns },
    { "ClassFlags", &PointSet::ClassFlags },
    { "ScannerChannel", &PointSet::ScannerChannel },
    { "ScanDirectionFlag", &PointSet::ScanDirectionFlag },
    { "EdgeOfFlightLine", &PointSet::EdgeOfFlightLine },
    { "Classification", &PointSet::Classification },
    { "UserData", &PointSet::UserData },
    { "PointSourceId", &PointSet::PointSourceId },
    { "ScanAngle", &PointSet::ScanAngle },
    { "ScanAngleRank", &PointSet::ScanAngleRank },
    { "GpsTime", &PointSet::GpsTime },
    { "Red", &PointSet::Red },
    { "Green", &PointSet::Green },
    { "Blue", &PointSet::Blue },
    { "Infrared", &PointSet::Infrared } };
  for (const auto& field : fields)
  {
    if (name == field.Name)
      return &(points.*field.Field);
  }
  return nullptr;
}

/// RGB as vtkLASPointCloudReader derives it (3 unsigned chars) beside the
/// Red, Green and Blue it comes from: those fill the color fields, and RGB
/// would only repeat them, at 8 bits, as extra bytes.
bool IsDerivedColors(vtkPointData* pointData, vtkDataArray* array, const std::string& name)
{
  const bool channels =
    pointData->GetArray("Red") && pointData->GetArray("Green") && pointData->GetArray("Blue");
  return name == "RGB" && array->GetDataType() == VTK_UNSIGNED_CHAR &&
    array->GetNumberOfComponents() == 3 && channels;
}

/// name + suffix in at most 32 characters, not yet in used.
std::string DimensionName(const std::string& name,
  const std::string& suffix,
  std::set<std::string>& used)
{
  const std::size_t room = 32 - suffix.size();
  std::string unique = name.substr(0, room) + suffix;
  for (int n = 2; used.count(unique); ++n)
  {
    const std::string tag = "~" + std::to_string(n);
    unique = name.substr(0, room - tag.size()) + tag + suffix;
  }
  used.insert(unique);
  return unique;
}

/// The array's components as extra dimensions.
void AddExtras(PointSet& points,
  vtkDataArray* array,
  const std::string& name,
  std::set<std::string>& used)
{
  const int components = array->GetNumberOfComponents();
  for (int c = 0; c < components; ++c)
  {
    std::string suffix;
    if (components == 3)
      suffix = std::string("_") + "XYZ"[c];
    else if (components > 1)
      suffix = "_" + std::to_string(c);
    pcurv::las::ExtraDimension extra;
    extra.Name = DimensionName(name, suffix, used);
    extra.Description = components > 1 ? name + suffix : name;
    extra.Values = ColumnOf(array, c);
    points.Extras.push_back(extra);
  }
}

} // namespace

//------------------------------------------------------------------------------
vtkLASPointCloudWriter::vtkLASPointCloudWriter() = default;

//------------------------------------------------------------------------------
vtkLASPointCloudWriter::~vtkLASPointCloudWriter()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
int vtkLASPointCloudWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

//------------------------------------------------------------------------------
void vtkLASPointCloudWriter::WriteData()
{
  vtkPointSet* input = vtkPointSet::SafeDownCast(this->GetInput());
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No FileName to write.");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return;
  }
  if (!input || !input->GetPoints() || input->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro(<< this->FileName << ": the input has no points to write.");
    return;
  }
  vtkDataArray* coordinates = input->GetPoints()->GetData();
  PointSet points;
  points.Count = static_cast<std::uint64_t>(input->GetNumberOfPoints());
  points.X = ColumnOf(coordinates, 0);
  points.Y = ColumnOf(coordinates, 1);
  points.Z = ColumnOf(coordinates, 2);
  std::set<std::string> used;
  vtkPointData* pointData = input->GetPointData();
  for (int i = 0; i < pointData->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* array = pointData->GetArray(i);
    const std::string name = pointData->GetArrayName(i) ? pointData->GetArrayName(i) : "";
    if (!array || ValueTypeOf(array->GetDataType()) == ValueType::Undocumented)
    {
      vtkWarningMacro(<< "The array '" << name << "' is not numeric: it is not written to LAS.");
      continue;
    }
    if (name == "vtkGhostType" || IsDerivedColors(pointData, array, name))
      continue;
    Column* standard = StandardField(points, name);
    if (standard && array->GetNumberOfComponents() == 1)
      *standard = ColumnOf(array, 0);
    else
      AddExtras(points, array, name.empty() ? "Array_" + std::to_string(i) : name, used);
  }
  pcurv::las::FileSettings settings;
  pcurv::readers::KeepFileDescription(input->GetFieldData(), settings);
  std::vector<std::string> skipped;
  pcurv::readers::KeepFieldData(input->GetFieldData(), settings, skipped);
  for (const std::string& what : skipped)
  {
    vtkWarningMacro(<< this->FileName << ": not written: " << what);
  }
  const std::string error = pcurv::las::WriteFile(this->FileName, points, settings);
  if (!error.empty())
  {
    vtkErrorMacro(<< this->FileName << ": " << error);
    this->SetErrorCode(vtkErrorCode::FileFormatError);
  }
}

//------------------------------------------------------------------------------
void vtkLASPointCloudWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
