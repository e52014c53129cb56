// The plugin's PLY and CSV writers: a cloud with every kind of array
// written as PLY (binary and ascii) and read back by vtkPLYPointCloudReader
// (names, types, components, values bit for bit), the PLY header's text,
// float points kept float, faces, full-precision CSV, the errors, and the
// helper that joins the pieces of a distributed cloud; field data (a unit,
// class names, counts) through PLY, CSV and LAS and back.
#include "vtkCSVPointCloudWriter.h"
#include "vtkLASPointCloudReader.h"
#include "vtkLASPointCloudWriter.h"
#include "vtkPLYPointCloudReader.h"
#include "vtkPLYPointCloudWriter.h"
#include "vtkPointSetGather.h"

#include "ReaderTestHelpers.h"
#include "TestChecks.h"

#include "vtkCellArray.h"
#include "vtkCharArray.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkShortArray.h"
#include "vtkSignedCharArray.h"
#include "vtkStringArray.h"
#include "vtkTextPointCloudReader.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedIntArray.h"
#include "vtkUnsignedShortArray.h"

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace
{

std::string Folder = ".";

constexpr vtkIdType PointCount = 50;

/// Adds an array of the type with values from the generator (a fixed
/// seed): integers over the type's range, reals over many magnitudes.
template<typename ArrayType>
void AddArray(vtkPolyData* cloud, const char* name, int components, std::mt19937& random)
{
  using Value = typename ArrayType::ValueType;
  vtkNew<ArrayType> array;
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(PointCount);
  std::uniform_real_distribution<double> unit(0, 1);
  for (vtkIdType v = 0; v < PointCount * components; ++v)
  {
    const double u = unit(random);
    if (std::numeric_limits<Value>::is_integer)
    {
      const double low = static_cast<double>(std::numeric_limits<Value>::lowest());
      const double high = static_cast<double>(std::numeric_limits<Value>::max());
      array->SetValue(v, static_cast<Value>(std::floor(low + u * (high - low))));
    }
    else
    {
      array->SetValue(v, static_cast<Value>((u - 0.5) * std::pow(10.0, 40 * u - 20)));
    }
  }
  cloud->GetPointData()->AddArray(array);
}

/// A georeferenced cloud (coordinates near 1e6, double) with normals, RGB
/// and arrays of every type PLY holds, a vector, a 2-component array, a
/// name with a space, 64-bit ids, a string array and field data.
vtkSmartPointer<vtkPolyData> MakeCloud()
{
  std::mt19937 random(20261205);
  std::uniform_real_distribution<double> unit(0, 1);
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (vtkIdType i = 0; i < PointCount; ++i)
  {
    points->InsertNextPoint(637180.123456 + unit(random), 1e6 + unit(random), unit(random));
  }
  cloud->SetPoints(points);
  AddArray<vtkDoubleArray>(cloud, "Normals", 3, random);
  cloud->GetPointData()->SetNormals(cloud->GetPointData()->GetArray("Normals"));
  AddArray<vtkUnsignedCharArray>(cloud, "RGB", 3, random);
  cloud->GetPointData()->SetScalars(cloud->GetPointData()->GetArray("RGB"));
  AddArray<vtkSignedCharArray>(cloud, "ScanAngleRank", 1, random);
  AddArray<vtkUnsignedCharArray>(cloud, "Classification", 1, random);
  AddArray<vtkShortArray>(cloud, "Short", 1, random);
  AddArray<vtkUnsignedShortArray>(cloud, "Intensity", 1, random);
  AddArray<vtkIntArray>(cloud, "Neighbor_Count", 1, random);
  AddArray<vtkUnsignedIntArray>(cloud, "UInt", 1, random);
  AddArray<vtkFloatArray>(cloud, "Float", 1, random);
  AddArray<vtkDoubleArray>(cloud, "Mean_Curvature", 1, random);
  AddArray<vtkDoubleArray>(cloud, "Maximum_Curvature_Direction", 3, random);
  AddArray<vtkFloatArray>(cloud, "Pair", 2, random);
  AddArray<vtkDoubleArray>(cloud, "With space", 1, random);
  vtkNew<vtkIdTypeArray> ids; // written as double, exact below 2^53
  ids->SetName("Ids");
  for (vtkIdType i = 0; i < PointCount; ++i)
  {
    ids->InsertNextValue(i * 1000000007 - 7);
  }
  cloud->GetPointData()->AddArray(ids);
  // NaN (an unestimated point) and infinities must come back too.
  auto* mean = vtkDoubleArray::SafeDownCast(cloud->GetPointData()->GetArray("Mean_Curvature"));
  mean->SetValue(0, std::nan(""));
  mean->SetValue(1, std::numeric_limits<double>::infinity());
  mean->SetValue(2, -std::numeric_limits<double>::infinity());
  vtkNew<vtkStringArray> labels;
  labels->SetName("Labels");
  labels->SetNumberOfValues(PointCount);
  cloud->GetPointData()->AddArray(labels);
  vtkNew<vtkStringArray> unit_;
  unit_->SetName("Curvature_Unit");
  unit_->InsertNextValue("1/length unit of the input coordinates");
  cloud->GetFieldData()->AddArray(unit_);
  vtkNew<vtkIdTypeArray> count;
  count->SetName("Unestimated_Points");
  count->InsertNextValue(3);
  cloud->GetFieldData()->AddArray(count);
  return cloud;
}

struct Written
{
  unsigned long Code = 0;
  std::string Errors, Warnings;
};

template<typename Writer>
Written Write(vtkDataObject* data, const std::string& path, bool ascii = false)
{
  vtkNew<Writer> writer;
  vtkNew<ErrorCatcher> errors, warnings;
  writer->AddObserver(vtkCommand::ErrorEvent, errors);
  writer->AddObserver(vtkCommand::WarningEvent, warnings);
  writer->SetFileName(path.c_str());
  writer->SetInputData(data);
  if constexpr (std::is_same<Writer, vtkPLYPointCloudWriter>::value)
  {
    writer->SetFileType(ascii ? vtkPLYPointCloudWriter::ASCII : vtkPLYPointCloudWriter::BINARY);
  }
  writer->Write();
  return Written{ writer->GetErrorCode(), errors->Messages, warnings->Messages };
}

vtkSmartPointer<vtkPolyData> ReadBack(const std::string& path)
{
  vtkNew<vtkPLYPointCloudReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

/// Whether two arrays hold the same bytes (NaN's included).
bool SameBytes(vtkDataArray* a, vtkDataArray* b)
{
  const std::size_t bytes = static_cast<std::size_t>(a->GetNumberOfValues()) * a->GetDataTypeSize();
  return a->GetNumberOfValues() == b->GetNumberOfValues() &&
    std::memcmp(a->GetVoidPointer(0), b->GetVoidPointer(0), bytes) == 0;
}

void CheckSameArray(Checks& checks, vtkDataArray* original, vtkDataArray* read, int expectedType)
{
  const std::string name = original->GetName();
  checks.True((name + ": read back").c_str(), read != nullptr);
  if (!read)
  {
    return;
  }
  checks.Equal((name + ": type").c_str(), read->GetDataType(), expectedType);
  checks.Equal((name + ": components").c_str(),
    read->GetNumberOfComponents(),
    original->GetNumberOfComponents());
  if (read->GetDataType() == original->GetDataType())
  {
    checks.True((name + ": values bit for bit").c_str(), SameBytes(original, read));
    return;
  }
  bool same = read->GetNumberOfTuples() == original->GetNumberOfTuples();
  for (vtkIdType i = 0; same && i < original->GetNumberOfTuples(); ++i)
  {
    same = read->GetComponent(i, 0) == original->GetComponent(i, 0);
  }
  checks.True((name + ": values exact").c_str(), same);
}

void CheckRoundTrip(Checks& checks, bool ascii)
{
  vtkSmartPointer<vtkPolyData> cloud = MakeCloud();
  const std::string path = Folder + (ascii ? "/writer_ascii.ply" : "/writer_binary.ply");
  const Written written = Write<vtkPLYPointCloudWriter>(cloud, path, ascii);
  checks.True("written without error", written.Errors.empty() && written.Code == 0);
  checks.True("one warning names the string array",
    written.Warnings.find("Labels (not numbers)") != std::string::npos);
  vtkSmartPointer<vtkPolyData> read = ReadBack(path);
  checks.Equal("points read back", read->GetNumberOfPoints(), PointCount);
  checks.Equal("points double", read->GetPoints()->GetDataType(), VTK_DOUBLE);
  checks.True("coordinates bit for bit",
    SameBytes(cloud->GetPoints()->GetData(), read->GetPoints()->GetData()));
  vtkPointData* data = cloud->GetPointData();
  for (int i = 0; i < data->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* original = data->GetArray(i);
    if (original)
    {
      const int type =
        original->GetDataType() == VTK_ID_TYPE ? VTK_DOUBLE : original->GetDataType();
      CheckSameArray(checks, original, read->GetPointData()->GetArray(original->GetName()), type);
    }
  }
  checks.True("normals attribute", read->GetPointData()->GetNormals() != nullptr);
  checks.True("RGB the scalars",
    read->GetPointData()->GetScalars() != nullptr &&
      std::string(read->GetPointData()->GetScalars()->GetName()) == "RGB");
  checks.Equal(
    "no other arrays", read->GetPointData()->GetNumberOfArrays(), data->GetNumberOfArrays() - 1);
  auto* unit =
    vtkStringArray::SafeDownCast(read->GetFieldData()->GetAbstractArray("Curvature_Unit"));
  checks.True("field data: Curvature_Unit",
    unit && unit->GetValue(0) == "1/length unit of the input coordinates");
  vtkDataArray* count = read->GetFieldData()->GetArray("Unestimated_Points");
  checks.True("field data: a count", count && count->GetComponent(0, 0) == 3);
}

void TestBinaryRoundTrip(Checks& checks)
{
  CheckRoundTrip(checks, false);
}

void TestAsciiRoundTrip(Checks& checks)
{
  CheckRoundTrip(checks, true);
}

void TestHeader(Checks& checks)
{
  vtkSmartPointer<vtkPolyData> cloud = MakeCloud();
  const std::string path = Folder + "/writer_header.ply";
  Write<vtkPLYPointCloudWriter>(cloud, path);
  const std::string text = ReadTextFile(path);
  const std::string header = text.substr(0, text.find("end_header\n") + 11);
  std::printf("%s", header.c_str());
  const std::string expected = "ply\n"
                               "format binary_little_endian 1.0\n"
                               "comment written by the PrincipalCurvatures plugin "
                               "(vtkPLYPointCloudWriter)\n"
                               "comment field Curvature_Unit 1/length unit of the input "
                               "coordinates\n"
                               "comment field Unestimated_Points 3\n"
                               "comment array nx 3 Normals\n"
                               "comment array red 3 RGB\n"
                               "comment array Maximum_Curvature_Direction_x 3 "
                               "Maximum_Curvature_Direction\n"
                               "comment array Pair_0 2 Pair\n"
                               "comment array With_space 1 With space\n"
                               "element vertex 50\n"
                               "property double x\nproperty double y\nproperty double z\n"
                               "property double nx\nproperty double ny\nproperty double nz\n"
                               "property uchar red\nproperty uchar green\nproperty uchar blue\n"
                               "property char ScanAngleRank\n"
                               "property uchar Classification\n"
                               "property short Short\n"
                               "property ushort Intensity\n"
                               "property int Neighbor_Count\n"
                               "property uint UInt\n"
                               "property float Float\n"
                               "property double Mean_Curvature\n"
                               "property double Maximum_Curvature_Direction_x\n"
                               "property double Maximum_Curvature_Direction_y\n"
                               "property double Maximum_Curvature_Direction_z\n"
                               "property float Pair_0\nproperty float Pair_1\n"
                               "property double With_space\n"
                               "property double Ids\n"
                               "end_header\n";
  checks.True("header text", header == expected);
  // 3 x 8 + 3 x 8 + 3 + 1 + 1 + 2 + 2 + 4 + 4 + 4 + 8 + 24 + 8 + 8 + 8 bytes a vertex.
  checks.Equal("body size", static_cast<long long>(text.size() - header.size()), PointCount * 125);
}

void TestFloatPointsAndFaces(Checks& checks)
{
  vtkNew<vtkPolyData> mesh;
  vtkNew<vtkPoints> points; // float by default
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  points->InsertNextPoint(1, 1, 0);
  mesh->SetPoints(points);
  vtkNew<vtkCellArray> polys;
  const vtkIdType triangle[] = { 0, 1, 2 }, quad[] = { 0, 1, 3, 2 };
  polys->InsertNextCell(3, triangle);
  polys->InsertNextCell(4, quad);
  mesh->SetPolys(polys);
  const std::string path = Folder + "/writer_faces.ply";
  Write<vtkPLYPointCloudWriter>(mesh, path, true);
  const std::string text = ReadTextFile(path);
  checks.True("float points stay float", text.find("property float x\n") != std::string::npos);
  checks.True("faces: element and list",
    text.find("element face 2\nproperty list uchar int vertex_indices\nend_header\n") !=
      std::string::npos);
  checks.True("faces: ascii records", text.find("\n3 0 1 2\n4 0 1 3 2\n") != std::string::npos);
  vtkSmartPointer<vtkPolyData> read = ReadBack(path);
  checks.Equal("the reader reads the vertices", read->GetNumberOfPoints(), 4);
  checks.Equal("as float", read->GetPoints()->GetDataType(), VTK_FLOAT);
}

void TestOptions(Checks& checks)
{
  vtkSmartPointer<vtkPolyData> cloud = MakeCloud();
  const std::string path = Folder + "/writer_options.ply";
  vtkNew<vtkPLYPointCloudWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(cloud);
  writer->PointsAsFloatOn();
  writer->SetNormalsArray("Maximum_Curvature_Direction");
  writer->Write();
  const std::string text = ReadTextFile(path);
  checks.True("PointsAsFloat: float x y z",
    text.find("property float x\nproperty float y\n") != std::string::npos);
  checks.True("NormalsArray: that array as nx ny nz",
    text.find("comment array nx 3 Maximum_Curvature_Direction\n") != std::string::npos &&
      text.find("property double Normals_x\n") != std::string::npos);
  vtkSmartPointer<vtkPolyData> read = ReadBack(path);
  vtkDataArray* direction = read->GetPointData()->GetArray("Maximum_Curvature_Direction");
  checks.True("NormalsArray: read back as the normals, under its name",
    direction && read->GetPointData()->GetNormals() == direction &&
      SameBytes(direction, cloud->GetPointData()->GetArray("Maximum_Curvature_Direction")));
  checks.True(
    "Normals read back as an array", read->GetPointData()->GetArray("Normals") != nullptr);
}

/// Comments edited by hand or by another tool: those that do not fit the
/// properties are left out, the others still apply.
void TestCommentsThatDoNotFit(Checks& checks)
{
  const std::string path = Folder + "/writer_comments.ply";
  WriteBytes(path,
    "ply\nformat ascii 1.0\n"
    "comment array a 3 Runs_Past_The_End\n"
    "comment array nx 2 Not_Normals\n"
    "comment array nowhere 3 Missing\n"
    "comment array q 1 With space\n"
    "comment array c 2 Mixed_Types\n"
    "comment field Unit metre\n"
    "element vertex 1\n"
    "property double x\nproperty double y\nproperty double z\n"
    "property float nx\nproperty float ny\nproperty float nz\n"
    "property int q\nproperty int c\nproperty float d\nproperty uchar a\nproperty uchar b\n"
    "end_header\n1 2 3 0 0 1 7 8 9.5 10 11\n");
  vtkSmartPointer<vtkPolyData> read = ReadBack(path);
  vtkPointData* data = read->GetPointData();
  checks.True("normals kept as Normals", data->GetNormals() && data->GetArray("Normals"));
  checks.True("a run past the end: separate properties",
    data->GetArray("a") && data->GetArray("b") && !data->GetArray("Runs_Past_The_End"));
  checks.True("mixed types: separate properties", data->GetArray("c") && data->GetArray("d"));
  checks.True("a name with a space restored", data->GetArray("With space") && !data->GetArray("q"));
  auto* unit = vtkStringArray::SafeDownCast(read->GetFieldData()->GetAbstractArray("Unit"));
  checks.True("field comment: text", unit && unit->GetValue(0) == "metre");
}

/// The helper that joins the pieces gathered from MPI ranks: one piece as
/// it is, two appended with the first one's field data.
void TestGather(Checks& checks)
{
  vtkSmartPointer<vtkPolyData> first = MakeCloud(), second = MakeCloud();
  second->GetFieldData()->Initialize();
  vtkNew<vtkPointSetGather> one;
  one->AddInputData(first);
  one->Update();
  checks.True("one piece: the same polydata, field data kept",
    vtkPolyData::SafeDownCast(one->GetOutputDataObject(0)) &&
      one->GetOutput()->GetNumberOfPoints() == PointCount &&
      one->GetOutput()->GetFieldData()->GetAbstractArray("Curvature_Unit"));
  vtkNew<vtkPointSetGather> two;
  two->AddInputData(first);
  two->AddInputData(second);
  two->Update();
  vtkPointSet* joined = two->GetOutput();
  checks.True("two pieces: one polydata of both",
    vtkPolyData::SafeDownCast(joined) && joined->GetNumberOfPoints() == 2 * PointCount);
  checks.True("two pieces: the first one's points first",
    joined->GetPoint(0)[0] == first->GetPoint(0)[0] &&
      joined->GetPoint(PointCount)[0] == second->GetPoint(0)[0]);
  checks.True("two pieces: arrays and the first one's field data",
    joined->GetPointData()->GetArray("Maximum_Curvature_Direction") &&
      joined->GetFieldData()->GetAbstractArray("Curvature_Unit"));
}

void TestCsv(Checks& checks)
{
  vtkNew<vtkPolyData> cloud;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->InsertNextPoint(637180.123456, 4.1e6 + 0.1, -12.5);
  cloud->SetPoints(points);
  vtkNew<vtkCharArray> angle; // a char array: numbers, not raw bytes
  angle->SetName("ScanAngleRank");
  angle->InsertNextValue(static_cast<char>(-5));
  vtkNew<vtkFloatArray> single;
  single->SetName("Float");
  single->InsertNextValue(0.1f);
  vtkNew<vtkDoubleArray> vector;
  vector->SetName("Direction");
  vector->SetNumberOfComponents(3);
  vector->InsertNextTuple3(1.0 / 3, 0, std::nan(""));
  cloud->GetPointData()->AddArray(angle);
  cloud->GetPointData()->AddArray(single);
  cloud->GetPointData()->AddArray(vector);
  const std::string path = Folder + "/writer.csv";
  const Written written = Write<vtkCSVPointCloudWriter>(cloud, path);
  const std::string text = ReadTextFile(path);
  std::printf("%s", text.c_str());
  checks.True("csv written", written.Errors.empty() && written.Code == 0);
  checks.True("csv text",
    text ==
      "x,y,z,ScanAngleRank,Float,Direction_x,Direction_y,Direction_z\n"
      "637180.123456,4100000.1,-12.5,-5,0.1,0.3333333333333333,0,nan\n");
}

const char* const
  ClassNames[] = { "Undetermined", "Flat", "Dome", "Cup", "Ridge", "Valley", "Saddle" };

/// A 5 x 5 grid far from the origin with the filter's kinds of field data:
/// a unit, class names (seven values), a count, a triple.
vtkSmartPointer<vtkPolyData> FieldDataCloud()
{
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int i = 0; i < 25; ++i)
  {
    points->InsertNextPoint(637180.0 + i % 5, 4.1e6 + i / 5, 12.5 + 0.01 * i);
  }
  cloud->SetPoints(points);
  vtkFieldData* fields = cloud->GetFieldData();
  vtkNew<vtkStringArray> unit, names;
  unit->SetName("Curvature_Unit");
  unit->InsertNextValue("1/foot");
  names->SetName("Shape_Class_Names");
  for (const char* name : ClassNames)
  {
    names->InsertNextValue(name);
  }
  vtkNew<vtkIdTypeArray> count;
  count->SetName("Unestimated_Points");
  count->InsertNextValue(3);
  vtkNew<vtkDoubleArray> triple;
  triple->SetName("Scale Triple"); // a space: '_' in the files
  triple->SetNumberOfComponents(3);
  triple->InsertNextTuple3(0.5, 1.0 / 3, 2e-300);
  for (vtkAbstractArray* array : std::vector<vtkAbstractArray*>{ unit, names, count, triple })
  {
    fields->AddArray(array);
  }
  return cloud;
}

template<typename Reader>
vtkSmartPointer<vtkPolyData> ReadWith(const std::string& path)
{
  vtkNew<Reader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

void CheckFieldData(Checks& checks, const std::string& format, vtkPolyData* read)
{
  vtkFieldData* fields = read ? read->GetFieldData() : nullptr;
  auto* unit =
    fields ? vtkStringArray::SafeDownCast(fields->GetAbstractArray("Curvature_Unit")) : nullptr;
  checks.True((format + ": the unit").c_str(),
    unit && unit->GetNumberOfValues() == 1 && unit->GetValue(0) == "1/foot");
  auto* names =
    fields ? vtkStringArray::SafeDownCast(fields->GetAbstractArray("Shape_Class_Names")) : nullptr;
  bool same = names && names->GetNumberOfValues() == 7;
  for (int c = 0; same && c < 7; ++c)
  {
    same = names->GetValue(c) == ClassNames[c];
  }
  checks.True((format + ": the seven class names, in order").c_str(), same);
  vtkDataArray* count = fields ? fields->GetArray("Unestimated_Points") : nullptr;
  checks.True((format + ": the count").c_str(),
    count && count->GetNumberOfTuples() == 1 && count->GetTuple1(0) == 3);
  vtkDataArray* triple = fields ? fields->GetArray("Scale_Triple") : nullptr;
  checks.True((format + ": the triple, every digit").c_str(),
    triple && triple->GetNumberOfComponents() == 3 && triple->GetComponent(0, 0) == 0.5 &&
      triple->GetComponent(0, 1) == 1.0 / 3 && triple->GetComponent(0, 2) == 2e-300);
}

/// Field data written by the PLY, CSV (FieldDataComments on) and LAS
/// writers reads back as it was (a LAS file twice: its own description is
/// not repeated).
void TestFieldDataRoundTrip(Checks& checks)
{
  vtkSmartPointer<vtkPolyData> cloud = FieldDataCloud();
  const std::string ply = Folder + "/fields.ply", csv = Folder + "/fields.csv",
                    las = Folder + "/fields.las", again = Folder + "/fields_again.las";
  vtkNew<vtkCSVPointCloudWriter> comments;
  comments->SetFileName(csv.c_str());
  comments->SetInputData(cloud);
  comments->FieldDataCommentsOn();
  comments->Write();
  checks.True("written",
    Write<vtkPLYPointCloudWriter>(cloud, ply).Code == 0 && comments->GetErrorCode() == 0 &&
      Write<vtkLASPointCloudWriter>(cloud, las).Code == 0);
  CheckFieldData(checks, "PLY", ReadWith<vtkPLYPointCloudReader>(ply));
  CheckFieldData(checks, "CSV", ReadWith<vtkTextPointCloudReader>(csv));
  vtkSmartPointer<vtkPolyData> fromLas = ReadWith<vtkLASPointCloudReader>(las);
  CheckFieldData(checks, "LAS", fromLas);
  checks.True("LAS read again: written", Write<vtkLASPointCloudWriter>(fromLas, again).Code == 0);
  vtkSmartPointer<vtkPolyData> twice = ReadWith<vtkLASPointCloudReader>(again);
  CheckFieldData(checks, "LAS twice", twice);
  vtkDataArray* scale = twice->GetFieldData()->GetArray("LAS_Scale");
  checks.True("LAS twice: its own scale once, not also in the field-data record",
    scale && scale->GetNumberOfTuples() == 1);
  // A field past what a LAS record holds: named in a warning, not lost
  // silently; the others kept.
  vtkNew<vtkStringArray> huge;
  huge->SetName("Huge_Note");
  huge->InsertNextValue(std::string(70000, 'x'));
  cloud->GetFieldData()->AddArray(huge);
  const std::string tooLong = Folder + "/fields_too_long.las";
  const Written written = Write<vtkLASPointCloudWriter>(cloud, tooLong);
  checks.True("LAS: a field past 65535 bytes is named in a warning",
    written.Code == 0 && written.Warnings.find("Huge_Note") != std::string::npos);
  vtkSmartPointer<vtkPolyData> withoutHuge = ReadWith<vtkLASPointCloudReader>(tooLong);
  CheckFieldData(checks, "LAS without the field past 65535 bytes", withoutHuge);
  checks.True("LAS: that field is not in the file",
    withoutHuge->GetFieldData()->GetAbstractArray("Huge_Note") == nullptr);
  const std::string plain = Folder + "/fields_plain.csv";
  checks.True("CSV by default: the header first, no field data",
    Write<vtkCSVPointCloudWriter>(cloud, plain).Code == 0 &&
      ReadTextFile(plain).compare(0, 6, "x,y,z\n") == 0);
  const std::string text = ReadTextFile(csv);
  checks.True("CSV: the field data as comment lines before the header",
    text.compare(0, 30, "# field Curvature_Unit 1/foot\n") == 0 &&
      text.find("\nx,y,z\n") != std::string::npos);
}

void TestErrors(Checks& checks)
{
  vtkSmartPointer<vtkPolyData> cloud = MakeCloud();
  const Written noFolder =
    Write<vtkPLYPointCloudWriter>(cloud, Folder + "/no_such_folder/cloud.ply");
  std::printf("%s", noFolder.Errors.c_str());
  checks.True("no folder: the file and the reason",
    noFolder.Errors.find("no_such_folder/cloud.ply: cannot create the file: No such file") !=
      std::string::npos);
  checks.True("no folder: error code", noFolder.Code != vtkErrorCode::NoError);
  vtkNew<vtkPolyData> empty; // no points object: a file of no points
  const std::string emptyPath = Folder + "/writer_empty.ply";
  const Written none = Write<vtkPLYPointCloudWriter>(empty, emptyPath);
  checks.True("empty input: no error", none.Errors.empty() && none.Code == 0);
  checks.True("empty input: 0 vertices",
    ReadTextFile(emptyPath).find("element vertex 0\n") != std::string::npos);
  vtkNew<vtkDoubleArray> shortArray; // fewer values than points: left out
  shortArray->SetName("Short_Array");
  shortArray->InsertNextValue(1);
  cloud->GetPointData()->AddArray(shortArray);
  const Written malformed = Write<vtkPLYPointCloudWriter>(cloud, Folder + "/writer_short.ply");
  checks.True("an array shorter than the points: left out with a warning",
    malformed.Errors.empty() &&
      malformed.Warnings.find("Short_Array (1 tuples for 50 points)") != std::string::npos);
  vtkNew<vtkIdTypeArray> huge; // beyond 2^53: double rounds it, and says so
  huge->SetName("Huge_Ids");
  for (vtkIdType i = 0; i < PointCount; ++i)
  {
    huge->InsertNextValue((vtkIdType(1) << 53) + 1);
  }
  cloud->GetPointData()->AddArray(huge);
  const Written rounded = Write<vtkPLYPointCloudWriter>(cloud, Folder + "/writer_huge.ply");
  checks.True("64-bit integers beyond 2^53: a warning",
    rounded.Warnings.find("Huge_Ids rounded (64-bit integers beyond 2^53 as double)") !=
      std::string::npos);
  const Written noName = Write<vtkCSVPointCloudWriter>(cloud, "");
  checks.True("no file name",
    noName.Errors.find("No FileName") != std::string::npos &&
      noName.Code == vtkErrorCode::NoFileNameError);
}

} // namespace

int main(int argc, char* argv[])
{
  if (argc > 2)
  {
    Folder = argv[2];
  }
  return RunNamedTests(argc > 2 ? 2 : argc,
    argv,
    {
      { "BinaryRoundTrip", TestBinaryRoundTrip },
      { "AsciiRoundTrip", TestAsciiRoundTrip },
      { "Header", TestHeader },
      { "FloatPointsAndFaces", TestFloatPointsAndFaces },
      { "Options", TestOptions },
      { "CommentsThatDoNotFit", TestCommentsThatDoNotFit },
      { "Gather", TestGather },
      { "Csv", TestCsv },
      { "FieldDataRoundTrip", TestFieldDataRoundTrip },
      { "Errors", TestErrors },
    });
}
