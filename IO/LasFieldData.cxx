#include "LasFieldData.h"

#include "FileFormats/LasCrs.h"
#include "PointCloudReaderSupport.h"
#include "PointCloudWriterSupport.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedShortArray.h"

#include <cstdlib>
#include <string>

namespace pcurv
{
namespace readers
{
namespace
{

const char* const ProjectionPrefix = "LAS_Projection_";

/// Whether the field data array `name` is one AddFileDescription makes:
/// the file's header and standard records hold it.
bool IsFileDescription(const std::string& name)
{
  return name == "LAS_Scale" || name == "LAS_Offset" || name == "LAS_Global_Encoding" ||
    name.compare(0, std::char_traits<char>::length(ProjectionPrefix), ProjectionPrefix) == 0 ||
    name == "Coordinate_System" || name == "Length_Unit" || name == "Vertical_Unit";
}

void AddString(vtkFieldData* field, const char* name, const std::string& value)
{
  if (value.empty())
    return;
  vtkNew<vtkStringArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  field->AddArray(array);
}

void AddTriple(vtkFieldData* field, const char* name, const double values[3])
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfComponents(3);
  array->InsertNextTuple(values);
  field->AddArray(array);
}

bool GetTriple(vtkFieldData* field, const char* name, double values[3])
{
  vtkDataArray* array = field->GetArray(name);
  if (!array || array->GetNumberOfComponents() != 3 || array->GetNumberOfTuples() < 1)
    return false;
  array->GetTuple(0, values);
  return true;
}

/// The description the specification's examples give each record.
std::string RecordDescription(std::uint16_t id)
{
  switch (id)
  {
    case 34735:
      return "GeoTIFF GeoKeyDirectoryTag";
    case 34736:
      return "GeoTIFF GeoDoubleParamsTag";
    case 34737:
      return "GeoTIFF GeoAsciiParamsTag";
    case 2112:
      return "OGC coordinate system WKT";
    default:
      return std::string();
  }
}

int VtkTypeOf(const las::ExtraField& field)
{
  if (field.Scaled)
    return VTK_DOUBLE;
  static const int types[] = { VTK_VOID,
    VTK_UNSIGNED_CHAR,
    VTK_SIGNED_CHAR,
    VTK_UNSIGNED_SHORT,
    VTK_SHORT,
    VTK_UNSIGNED_INT,
    VTK_INT,
    VTK_UNSIGNED_LONG_LONG,
    VTK_LONG_LONG,
    VTK_FLOAT,
    VTK_DOUBLE };
  return types[static_cast<int>(field.Type)];
}

std::string UniqueName(vtkPointData* pointData, std::string name)
{
  if (name.empty())
    name = "Extra";
  const std::string base = name;
  for (int suffix = 2; pointData->GetAbstractArray(name.c_str()); ++suffix)
    name = base + "_" + std::to_string(suffix);
  return name;
}

/// Whether fields[i..i+2] are <name>_X, _Y, _Z of one type and scaling.
bool IsVector(const std::vector<las::ExtraField>& fields, std::size_t i)
{
  if (i + 2 >= fields.size())
    return false;
  const std::string& x = fields[i].Name;
  if (x.size() < 3 || x.compare(x.size() - 2, 2, "_X") != 0)
    return false;
  const std::string base = x.substr(0, x.size() - 2);
  for (int c = 1; c < 3; ++c)
  {
    const las::ExtraField& f = fields[i + c];
    if (f.Name != base + (c == 1 ? "_Y" : "_Z") || f.Type != fields[i].Type ||
      f.Scaled != fields[i].Scaled)
      return false;
  }
  return true;
}

} // namespace

//------------------------------------------------------------------------------
void AddFileDescription(vtkFieldData* field,
  const las::Header& header,
  const std::vector<las::Vlr>& records)
{
  AddTriple(field, "LAS_Scale", header.Scale);
  AddTriple(field, "LAS_Offset", header.Offset);
  vtkNew<vtkUnsignedShortArray> encoding;
  encoding->SetName("LAS_Global_Encoding");
  encoding->InsertNextValue(header.GlobalEncoding);
  field->AddArray(encoding);
  for (const las::Vlr& record : records)
  {
    if (record.UserId != "LASF_Projection")
      continue;
    vtkNew<vtkUnsignedCharArray> payload;
    payload->SetName((ProjectionPrefix + std::to_string(record.RecordId)).c_str());
    payload->SetNumberOfValues(static_cast<vtkIdType>(record.Data.size()));
    for (std::size_t i = 0; i < record.Data.size(); ++i)
      payload->SetValue(static_cast<vtkIdType>(i), record.Data[i]);
    field->AddArray(payload);
  }
  const las::CoordinateSystem crs = las::DescribeCoordinates(records);
  AddString(field, "Coordinate_System", crs.Description);
  AddString(field, "Length_Unit", crs.LengthUnit);
  AddString(field, "Vertical_Unit", crs.VerticalUnit);
  AddFieldTexts(las::FieldDataOf(records), field);
}

//------------------------------------------------------------------------------
void KeepFieldData(vtkFieldData* field,
  las::FileSettings& settings,
  std::vector<std::string>& skipped)
{
  vtkNew<vtkFieldData> others;
  for (int i = 0; field && i < field->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* array = field->GetAbstractArray(i);
    if (!IsFileDescription(array->GetName() ? array->GetName() : ""))
    {
      others->AddArray(array);
    }
  }
  settings.Fields = writers::FieldTextsOf(others, skipped);
  std::vector<std::string> left;
  las::FieldDataRecord(settings.Fields, &left);
  for (const std::string& name : left)
  {
    skipped.push_back("field data " + name + " (past the 65535 bytes a LAS record holds)");
  }
}

//------------------------------------------------------------------------------
void KeepFileDescription(vtkFieldData* field, las::FileSettings& settings)
{
  if (!field)
    return;
  settings.KeepScale = GetTriple(field, "LAS_Scale", settings.Scale) &&
    GetTriple(field, "LAS_Offset", settings.Offset);
  vtkDataArray* encoding = field->GetArray("LAS_Global_Encoding");
  if (encoding && encoding->GetNumberOfTuples() > 0)
    settings.GlobalEncoding = static_cast<std::uint16_t>(encoding->GetTuple1(0));
  const std::string prefix = ProjectionPrefix;
  for (int i = 0; i < field->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* array = field->GetArray(i);
    const char* name = field->GetArrayName(i);
    if (!array || !name || std::string(name).compare(0, prefix.size(), prefix) != 0)
      continue;
    const auto id = static_cast<std::uint16_t>(std::atoi(name + prefix.size()));
    las::Vlr record{ "LASF_Projection", id, RecordDescription(id), {} };
    for (vtkIdType v = 0; v < array->GetNumberOfValues(); ++v)
      record.Data.push_back(static_cast<unsigned char>(array->GetComponent(v, 0)));
    settings.CoordinateRecords.push_back(record);
  }
  vtkStringArray* crs = vtkStringArray::SafeDownCast(field->GetAbstractArray("Coordinate_System"));
  if (crs && crs->GetNumberOfValues() > 0 && crs->GetValue(0).find('[') != std::string::npos)
    settings.Wkt = crs->GetValue(0);
}

//------------------------------------------------------------------------------
std::vector<las::PointBuffers::Extra> AddExtraArrays(vtkPointData* pointData,
  const std::vector<las::ExtraField>& fields,
  vtkIdType count)
{
  std::vector<las::PointBuffers::Extra> buffers;
  for (std::size_t i = 0; i < fields.size();)
  {
    const int components = IsVector(fields, i) ? 3 : 1;
    std::string name = fields[i].Name;
    if (components == 3)
      name.resize(name.size() - 2);
    vtkSmartPointer<vtkDataArray> array =
      NewArray(VtkTypeOf(fields[i]), UniqueName(pointData, name).c_str(), components, count);
    pointData->AddArray(array);
    for (int c = 0; c < components; ++c, ++i)
    {
      const las::ExtraField& f = fields[i];
      buffers.push_back({ f.ByteOffset,
        f.Type,
        f.Scaled,
        f.Scale,
        f.Offset,
        array->GetVoidPointer(c),
        static_cast<std::size_t>(components) });
    }
    if (components == 3 && name == "Normals")
      pointData->SetNormals(array);
  }
  return buffers;
}

} // namespace readers
} // namespace pcurv
