#include "PointCloudWriterSupport.h"

#include "FileFormats/CloudTable.h"

#include "vtkAbstractArray.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkWriter.h"

#include <cmath>
#include <new>
#include <vector>

namespace pcurv
{
namespace writers
{
namespace
{

using table::Role;
using Type = ply::Type;

/// The PLY type that holds the VTK type's values exactly; false for the
/// 64-bit integers (written as double) and the types a file cannot hold.
bool NativeType(int vtkType, Type& type)
{
  switch (vtkType)
  {
    case VTK_CHAR:
    case VTK_SIGNED_CHAR:
      type = Type::Int8;
      return true;
    case VTK_UNSIGNED_CHAR:
      type = Type::UInt8;
      return true;
    case VTK_SHORT:
      type = Type::Int16;
      return true;
    case VTK_UNSIGNED_SHORT:
      type = Type::UInt16;
      return true;
    case VTK_INT:
      type = Type::Int32;
      return true;
    case VTK_UNSIGNED_INT:
      type = Type::UInt32;
      return true;
    case VTK_FLOAT:
      type = Type::Float32;
      return true;
    case VTK_DOUBLE:
      type = Type::Float64;
      return true;
    default:
      return false;
  }
}

/// A number's components as the text of a field value ("0.5 1 2").
std::string NumbersText(vtkDataArray* numbers)
{
  std::string text;
  for (int c = 0; c < numbers->GetNumberOfComponents(); ++c)
  {
    const double value = numbers->GetComponent(0, c);
    table::Array one;
    one.Data = &value;
    text += c ? " " : "";
    table::AppendValue(one, 0, text);
  }
  return text;
}

/// The input as the core's cloud, and the converted copies of arrays that
/// the cloud points into.
class CloudBuilder
{
public:
  table::Cloud Cloud;
  std::vector<std::string> Skipped; // what the file leaves out or rounds, for one warning

  void AddArray(vtkDataArray* array, Role role, const char* name)
  {
    // A malformed data set's array may hold fewer values than points.
    if (static_cast<std::uint64_t>(array->GetNumberOfTuples()) < this->Cloud.Count)
    {
      this->Skipped.push_back(std::string(name ? name : "") + " (" +
        std::to_string(array->GetNumberOfTuples()) + " tuples for " +
        std::to_string(this->Cloud.Count) + " points)");
      return;
    }
    table::Array column;
    column.Name = name ? name : "";
    column.Kind = role;
    column.Components = array->GetNumberOfComponents();
    column.Data = this->Values(array, role == Role::Points, column.ValueType);
    this->Cloud.Arrays.push_back(column);
  }

  /// The points as float (a smaller file, for coordinates float keeps).
  void AddFloatPoints(vtkDataArray* points)
  {
    vtkSmartPointer<vtkDataArray> copy =
      vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(VTK_FLOAT));
    copy->DeepCopy(points);
    this->Held.push_back(copy);
    this->AddArray(copy, Role::Points, "Points");
  }

  void AddFields(vtkFieldData* fields)
  {
    for (auto& field : FieldTextsOf(fields, this->Skipped))
    {
      this->Cloud.Fields.push_back(std::move(field));
    }
  }

private:
  /// The array's values in a type the file holds: its own memory when it
  /// is stored as one block of a PLY type, else a converted copy (64-bit
  /// integers and bits as double, other layouts as their own type; points
  /// of a type other than float as double).
  const void* Values(vtkDataArray* array, bool points, Type& type)
  {
    int copyType = VTK_DOUBLE;
    const bool native = NativeType(array->GetDataType(), type);
    if (native && (!points || type == Type::Float32 || type == Type::Float64))
    {
      if (array->HasStandardMemoryLayout())
      {
        return array->GetVoidPointer(0);
      }
      copyType = array->GetDataType();
    }
    else
    {
      type = Type::Float64;
      this->CheckExactAsDouble(array);
    }
    vtkSmartPointer<vtkDataArray> copy =
      vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(copyType));
    copy->DeepCopy(array);
    this->Held.push_back(copy);
    return copy->GetVoidPointer(0);
  }

  /// 64-bit integers beyond 2^53 lose their last digits as double (the
  /// range, itself a double, shows them as 2^53 or more).
  void CheckExactAsDouble(vtkDataArray* array)
  {
    const double limit = 9007199254740992.0;
    double range[2];
    array->GetRange(range, -1); // the largest magnitude of the tuples
    if (array->GetDataTypeSize() == 8 && range[1] >= limit)
    {
      this->Skipped.push_back(std::string(array->GetName() ? array->GetName() : "") +
        " rounded (64-bit integers beyond 2^53 as double)");
    }
  }

  std::vector<vtkSmartPointer<vtkDataArray>> Held;
};

/// The normals: the array named, else the normals attribute, else an
/// array named Normals, with 3 floating point components.
vtkDataArray* FindNormals(vtkPointData* data, const std::string& name)
{
  vtkDataArray* normals = name.empty() ? data->GetNormals() : data->GetArray(name.c_str());
  if (!normals && name.empty())
  {
    normals = data->GetArray("Normals");
  }
  const bool real =
    normals && (normals->GetDataType() == VTK_FLOAT || normals->GetDataType() == VTK_DOUBLE);
  return real && normals->GetNumberOfComponents() == 3 ? normals : nullptr;
}

/// The colors: the scalars, else an array named RGB, of 3 unsigned chars.
vtkDataArray* FindColors(vtkPointData* data)
{
  for (vtkDataArray* colors : { data->GetScalars(), data->GetArray("RGB") })
  {
    if (colors && colors->GetDataType() == VTK_UNSIGNED_CHAR &&
      colors->GetNumberOfComponents() == 3)
    {
      return colors;
    }
  }
  return nullptr;
}

void AddPointData(vtkPointData* data, const std::string& normalsName, CloudBuilder& builder)
{
  vtkDataArray* normals = FindNormals(data, normalsName);
  vtkDataArray* colors = FindColors(data);
  if (normals)
  {
    builder.AddArray(normals, Role::Normals, normals->GetName());
  }
  if (colors)
  {
    builder.AddArray(colors, Role::Colors, colors->GetName());
  }
  for (int i = 0; i < data->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* abstract = data->GetAbstractArray(i);
    vtkDataArray* array = vtkDataArray::SafeDownCast(abstract);
    const char* name = abstract->GetName();
    if (!array)
    {
      builder.Skipped.push_back(std::string(name ? name : "") + " (not numbers)");
    }
    else if (array != normals && array != colors)
    {
      builder.AddArray(array, Role::Other, name);
    }
  }
}

/// The polygons of a polydata as faces; a warning for lines and strips,
/// and for the cells of other point sets, which a point file leaves out.
void AddFaces(vtkPointSet* input, CloudBuilder& builder)
{
  vtkPolyData* polyData = vtkPolyData::SafeDownCast(input);
  const vtkIdType cells = input->GetNumberOfCells();
  if (!polyData)
  {
    if (cells > 0)
    {
      builder.Skipped.push_back(std::to_string(cells) + " cells (points only)");
    }
    return;
  }
  const vtkIdType others = polyData->GetNumberOfLines() + polyData->GetNumberOfStrips();
  if (others > 0)
  {
    builder.Skipped.push_back(std::to_string(others) + " lines and strips (polygons only)");
  }
  vtkCellArray* polys = polyData->GetPolys();
  if (!polys || polys->GetNumberOfCells() == 0)
  {
    return;
  }
  table::Cloud& cloud = builder.Cloud;
  for (vtkIdType i = 0; i <= polys->GetNumberOfCells(); ++i)
  {
    cloud.FaceOffsets.push_back(
      static_cast<std::uint64_t>(polys->GetOffsetsArray()->GetComponent(i, 0)));
  }
  vtkDataArray* ids = polys->GetConnectivityArray();
  for (vtkIdType i = 0; i < ids->GetNumberOfValues(); ++i)
  {
    cloud.FaceIds.push_back(static_cast<std::uint64_t>(ids->GetComponent(i, 0)));
  }
}

std::string SkippedText(const std::vector<std::string>& skipped)
{
  std::string text;
  for (const std::string& item : skipped)
  {
    text += (text.empty() ? "" : "; ") + item;
  }
  return text;
}

} // namespace

//------------------------------------------------------------------------------
std::vector<std::pair<std::string, std::string>> FieldTextsOf(vtkFieldData* fields,
  std::vector<std::string>& skipped)
{
  std::vector<std::pair<std::string, std::string>> texts;
  for (int i = 0; fields && i < fields->GetNumberOfArrays(); ++i)
  {
    vtkAbstractArray* array = fields->GetAbstractArray(i);
    const std::string name = array->GetName() ? array->GetName() : "";
    vtkStringArray* text = vtkStringArray::SafeDownCast(array);
    vtkDataArray* numbers = vtkDataArray::SafeDownCast(array);
    if (text)
    {
      for (vtkIdType v = 0; v < text->GetNumberOfValues(); ++v)
      {
        texts.emplace_back(name, text->GetValue(v));
      }
    }
    else if (numbers && numbers->GetNumberOfTuples() == 1)
    {
      texts.emplace_back(name, NumbersText(numbers));
    }
    else
    {
      skipped.push_back("field data " + name + " (numbers of more than one tuple)");
    }
  }
  return texts;
}

//------------------------------------------------------------------------------
unsigned long WriteInput(vtkWriter* writer,
  const char* fileName,
  const WriteOptions& options,
  const WriteFunction& write)
{
  vtkPointSet* input = vtkPointSet::SafeDownCast(writer->GetInput());
  if (!fileName || !*fileName)
  {
    vtkErrorWithObjectMacro(writer, << "No FileName to write.");
    return vtkErrorCode::NoFileNameError;
  }
  if (!input)
  {
    vtkErrorWithObjectMacro(writer, << fileName << ": the input is not a point set");
    return vtkErrorCode::UnknownError;
  }
  // An empty output (no points object) is written as a file of no points.
  vtkNew<vtkDoubleArray> noPoints;
  noPoints->SetNumberOfComponents(3);
  vtkDataArray* points = input->GetPoints() ? input->GetPoints()->GetData() : noPoints.Get();
  std::string error;
  try
  {
    CloudBuilder builder;
    builder.Cloud.Count = static_cast<std::uint64_t>(input->GetNumberOfPoints());
    if (options.PointsAsFloat)
    {
      builder.AddFloatPoints(points);
    }
    else
    {
      builder.AddArray(points, Role::Points, "Points");
    }
    AddPointData(input->GetPointData(), options.NormalsArray, builder);
    if (options.WithFieldData)
    {
      builder.AddFields(input->GetFieldData());
    }
    if (options.WithFaces)
    {
      AddFaces(input, builder);
    }
    table::NameColumns(builder.Cloud);
    if (!builder.Skipped.empty())
    {
      vtkWarningWithObjectMacro(
        writer, << fileName << ": not written as they are: " << SkippedText(builder.Skipped));
    }
    error = write(fileName, builder.Cloud);
  }
  catch (const std::bad_alloc&)
  {
    error = "out of memory";
  }
  if (!error.empty())
  {
    vtkErrorWithObjectMacro(writer, << fileName << ": " << error);
    return vtkErrorCode::CannotOpenFileError;
  }
  return vtkErrorCode::NoError;
}

} // namespace writers
} // namespace pcurv
