// vtkLASPointCloudWriter and the LAS reader's units: a cloud with every
// dimension the reader makes and curvature-like arrays written and read
// back (every value equal; coordinates within the scale); the header and
// the Extra Bytes record checked byte by byte against LAS 1.4 R15; the
// scale chosen for a cloud that did not come from LAS; ScanAngleRank of a
// legacy file; the coordinate system and length unit of GeoTIFF keys and
// WKT; bad input, each with its message and no file.
#include "LasTestFiles.h"
#include "ReaderTestHelpers.h"
#include "TestChecks.h"
#include "vtkLASPointCloudReader.h"
#include "vtkLASPointCloudWriter.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkLongLongArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkShortArray.h"
#include "vtkSignedCharArray.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedShortArray.h"

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace
{

std::string Folder = ".";
const char* const UniqueCut = "A_Name_Much_Longer_Than_The_32~2";
constexpr int Count = 50;

template<typename ArrayType>
void AddArray(vtkPolyData* cloud, const char* name, int components, double (*value)(int, int))
{
  vtkNew<ArrayType> array;
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(Count);
  for (int i = 0; i < Count; ++i)
    for (int c = 0; c < components; ++c)
      array->SetComponent(i, c, value(i, c));
  cloud->GetPointData()->AddArray(array);
}

void AddString(vtkFieldData* field, const char* name, const std::string& value)
{
  vtkNew<vtkStringArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  field->AddArray(array);
}

void AddTriple(vtkFieldData* field, const char* name, double a, double b, double c)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfComponents(3);
  array->InsertNextTuple3(a, b, c);
  field->AddArray(array);
}

/// A georeferenced cloud with the arrays the LAS reader makes (format 8's)
/// and the filter's kinds of arrays.
vtkSmartPointer<vtkPolyData> MakeCloud(bool colors, bool lasField)
{
  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int i = 0; i < Count; ++i)
    points->InsertNextPoint(637180.123 + 0.731 * i, 852000.5 - 1.25 * i, 12.345 + 0.01 * i * i);
  cloud->SetPoints(points);
  AddArray<vtkUnsignedShortArray>(cloud, "Intensity", 1, [](int i, int) { return 1000.0 * i; });
  AddArray<vtkUnsignedCharArray>(cloud, "ReturnNumber", 1, [](int i, int) { return 1.0 + i % 15; });
  AddArray<vtkUnsignedCharArray>(cloud, "NumberOfReturns", 1, [](int, int) { return 15.0; });
  AddArray<vtkUnsignedCharArray>(cloud, "ClassFlags", 1, [](int i, int) { return i % 16 * 1.0; });
  AddArray<vtkUnsignedCharArray>(
    cloud, "ScannerChannel", 1, [](int i, int) { return i % 4 * 1.0; });
  AddArray<vtkUnsignedCharArray>(
    cloud, "ScanDirectionFlag", 1, [](int i, int) { return i % 2 * 1.0; });
  AddArray<vtkUnsignedCharArray>(
    cloud, "EdgeOfFlightLine", 1, [](int i, int) { return i / 25 * 1.0; });
  AddArray<vtkUnsignedCharArray>(cloud, "Classification", 1, [](int i, int) { return 5.0 * i; });
  AddArray<vtkUnsignedCharArray>(cloud, "UserData", 1, [](int i, int) { return 255.0 - i; });
  AddArray<vtkUnsignedShortArray>(
    cloud, "PointSourceId", 1, [](int i, int) { return 65535.0 - i; });
  AddArray<vtkFloatArray>(cloud, "ScanAngle", 1, [](int i, int) { return -90.0 + 3.6 * i; });
  AddArray<vtkDoubleArray>(cloud, "GpsTime", 1, [](int i, int) { return 3.5e8 + 0.001 * i; });
  if (colors)
  {
    AddArray<vtkUnsignedShortArray>(cloud, "Red", 1, [](int i, int) { return 1311.0 * i; });
    AddArray<vtkUnsignedShortArray>(cloud, "Green", 1, [](int i, int) { return 65535.0 - i; });
    AddArray<vtkUnsignedShortArray>(cloud, "Blue", 1, [](int i, int) { return 7.0 * i; });
    AddArray<vtkUnsignedShortArray>(cloud, "Infrared", 1, [](int i, int) { return 99.0 * i; });
  }
  AddArray<vtkDoubleArray>(cloud, "Mean_Curvature", 1, [](int i, int) { return std::sin(i) / 3; });
  AddArray<vtkDoubleArray>(
    cloud, "Minimum_Curvature_Direction", 3, [](int i, int c) { return std::cos(i + c) / 7; });
  AddArray<vtkFloatArray>(
    cloud, "Normals", 3, [](int i, int c) { return c == 2 ? 1.0 : 0.01 * i; });
  AddArray<vtkUnsignedCharArray>(
    cloud, "Curvature_Valid", 1, [](int i, int) { return i % 3 ? 1.0 : 0.0; });
  AddArray<vtkIntArray>(cloud, "Neighbor_Count", 1, [](int i, int) { return 16.0 + i; });
  AddArray<vtkSignedCharArray>(cloud, "Signed_Flag", 1, [](int i, int) { return -1.0 * (i % 2); });
  AddArray<vtkLongLongArray>(cloud, "Big_Count", 1, [](int i, int) { return 4.0e12 + i; });
  AddArray<vtkDoubleArray>(
    cloud, "A_Name_Much_Longer_Than_The_32_Characters", 1, [](int i, int) { return 0.5 * i; });
  AddArray<vtkDoubleArray>(
    cloud, "A_Name_Much_Longer_Than_The_32_Characters_Too", 1, [](int i, int) { return -0.5 * i; });
  if (lasField)
  {
    AddTriple(cloud->GetFieldData(), "LAS_Scale", 0.001, 0.001, 0.0001);
    AddTriple(cloud->GetFieldData(), "LAS_Offset", 600000, 800000, 0);
  }
  return cloud;
}

struct Written
{
  std::string Path;
  std::string Errors;
};

Written Write(vtkPolyData* cloud, const std::string& name)
{
  vtkNew<vtkLASPointCloudWriter> writer;
  vtkNew<ErrorCatcher> catcher;
  writer->AddObserver(vtkCommand::ErrorEvent, catcher);
  Written written{ Folder + "/" + name, "" };
  std::remove(written.Path.c_str());
  writer->SetInputData(cloud);
  writer->SetFileName(written.Path.c_str());
  writer->Write();
  written.Errors = catcher->Messages;
  return written;
}

vtkSmartPointer<vtkPolyData> Read(const std::string& path, std::string* errors = nullptr)
{
  vtkNew<vtkLASPointCloudReader> reader;
  vtkNew<ErrorCatcher> catcher;
  reader->AddObserver(vtkCommand::ErrorEvent, catcher);
  reader->SetFileName(path.c_str());
  reader->Update();
  if (errors)
    *errors = catcher->Messages;
  return reader->GetOutput();
}

std::string Bytes(const std::string& path)
{
  std::ifstream file(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

template<typename T>
T At(const std::string& bytes, std::size_t offset)
{
  T value{};
  if (offset + sizeof(T) <= bytes.size())
    std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

std::string StringField(vtkPolyData* cloud, const char* name)
{
  auto* array = vtkStringArray::SafeDownCast(cloud->GetFieldData()->GetAbstractArray(name));
  return array && array->GetNumberOfValues() ? array->GetValue(0) : std::string("(none)");
}

/// Every array of `original` in `read`: equal values (ScanAngle within the
/// file's 0.006 degrees, vectors as 3-component arrays again).
void CheckArraysEqual(Checks& checks, vtkPolyData* original, vtkPolyData* read)
{
  vtkPointData* pd = original->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* in = pd->GetArray(a);
    std::string name = in->GetName();
    // Cut to 32 characters; the second of two equal cuts gets a number.
    if (name.size() > 32)
      name = name.find("_Too") == std::string::npos ? name.substr(0, 32) : UniqueCut;
    vtkDataArray* out = read->GetPointData()->GetArray(name.c_str());
    const std::string what = "array " + name + " read back";
    checks.True(what.c_str(), out && out->GetNumberOfComponents() == in->GetNumberOfComponents());
    if (!out || out->GetNumberOfComponents() != in->GetNumberOfComponents())
      continue;
    const double tolerance = name == "ScanAngle" ? 0.003 + 1e-5 : 0.0;
    double worst = 0;
    for (vtkIdType i = 0; i < in->GetNumberOfTuples(); ++i)
      for (int c = 0; c < in->GetNumberOfComponents(); ++c)
        worst = std::max(worst, std::fabs(in->GetComponent(i, c) - out->GetComponent(i, c)));
    checks.Near((name + " values equal").c_str(), worst, 0, tolerance);
  }
}

void TestRoundTrip(Checks& checks)
{
  for (bool colors : { true, false })
  {
    vtkSmartPointer<vtkPolyData> cloud = MakeCloud(colors, true);
    const Written written = Write(cloud, colors ? "roundtrip8.las" : "roundtrip6.las");
    checks.True("written without error", written.Errors.empty());
    std::string errors;
    vtkSmartPointer<vtkPolyData> read = Read(written.Path, &errors);
    checks.True("read back without error", errors.empty());
    checks.Equal("points read back", read->GetNumberOfPoints(), Count);
    if (read->GetNumberOfPoints() != Count)
      continue;
    double worst[3] = { 0, 0, 0 };
    for (vtkIdType i = 0; i < Count; ++i)
      for (int c = 0; c < 3; ++c)
        worst[c] = std::max(worst[c], std::fabs(cloud->GetPoint(i)[c] - read->GetPoint(i)[c]));
    checks.Near("x within half the kept scale", worst[0], 0, 0.0005 + 1e-9);
    checks.Near("z within half the kept scale", worst[2], 0, 0.00005 + 1e-9);
    CheckArraysEqual(checks, cloud, read);
    checks.True(
      "the second long name made unique", read->GetPointData()->GetArray(UniqueCut) != nullptr);
    checks.True(
      "Red only with colors", (read->GetPointData()->GetArray("Red") != nullptr) == colors);
    checks.True("Normals are the normals again",
      read->GetPointData()->GetNormals() == read->GetPointData()->GetArray("Normals"));
    double scale[3];
    read->GetFieldData()->GetArray("LAS_Scale")->GetTuple(0, scale);
    checks.Near("the input's z scale kept", scale[2], 0.0001, 0);
  }
}

/// A LAS file with colors read (the reader adds the 8-bit RGB) and written
/// again: the same record length, no RGB extra bytes; RGB is derived again
/// from Red, Green and Blue when read back. An RGB without those is kept.
void TestDerivedColors(Checks& checks)
{
  const Written first = Write(MakeCloud(true, true), "colors_first.las");
  vtkSmartPointer<vtkPolyData> read = Read(first.Path);
  checks.True("the reader adds RGB", read->GetPointData()->GetArray("RGB") != nullptr);
  const Written second = Write(read, "colors_second.las");
  checks.True("written again without error", second.Errors.empty());
  const std::string a = Bytes(first.Path), b = Bytes(second.Path);
  checks.Equal("the same point record length (no RGB extra bytes)",
    At<std::uint16_t>(b, 105),
    At<std::uint16_t>(a, 105));
  vtkSmartPointer<vtkPolyData> again = Read(second.Path);
  vtkDataArray* rgb = again->GetPointData()->GetArray("RGB");
  checks.True("RGB derived again, 65535 to 255",
    rgb && again->GetPointData()->GetArray("RGB_X") == nullptr && rgb->GetComponent(0, 1) == 255);

  vtkSmartPointer<vtkPolyData> alone = MakeCloud(false, true);
  AddArray<vtkUnsignedCharArray>(alone, "RGB", 3, [](int i, int c) { return 10.0 * c + i; });
  const Written kept = Write(alone, "colors_alone.las");
  vtkSmartPointer<vtkPolyData> keptRead = Read(kept.Path);
  vtkDataArray* keptRgb = keptRead->GetPointData()->GetArray("RGB");
  checks.True("an RGB without Red, Green and Blue: kept as extra bytes",
    kept.Errors.empty() && keptRgb && keptRgb->GetNumberOfComponents() == 3 &&
      keptRgb->GetComponent(3, 2) == 23);
}

void TestHeaderBytes(Checks& checks)
{
  vtkSmartPointer<vtkPolyData> cloud = MakeCloud(true, true);
  const std::string wkt = "PROJCS[\"NAD83 / Texas North Central (ftUS)\",GEOGCS[\"NAD83\"],"
                          "UNIT[\"US survey foot\",0.304800609601219]]";
  AddString(cloud->GetFieldData(), "Coordinate_System", wkt);
  const std::string b = Bytes(Write(cloud, "header.las").Path);
  checks.True("signature LASF", b.compare(0, 4, "LASF") == 0);
  checks.Equal("version 1.4", b[24] * 10 + b[25], 14);
  checks.Equal("header size 375", At<std::uint16_t>(b, 94), 375);
  checks.Equal("global encoding: the WKT bit (4)", At<std::uint16_t>(b, 6), 0x10);
  checks.Equal("point data format 8 (colors and infrared)", static_cast<unsigned char>(b[104]), 8);
  // Extra bytes: Mean (8), direction (3 x 8), normals (3 x 4), valid (1),
  // neighbors (4), signed (1), big (8), the two long names (2 x 8).
  const int extraBytes = 8 + 24 + 12 + 1 + 4 + 1 + 8 + 16;
  const int dimensions = 1 + 3 + 3 + 1 + 1 + 1 + 1 + 2;
  checks.Equal("record length", At<std::uint16_t>(b, 105), 38 + extraBytes);
  checks.Equal("legacy point count 0 (format > 5)", At<std::uint32_t>(b, 107), 0);
  checks.Equal("legacy points by return 0", At<std::uint32_t>(b, 111), 0);
  checks.Equal("point count", static_cast<long long>(At<std::uint64_t>(b, 247)), Count);
  checks.Equal("points of return 1", static_cast<long long>(At<std::uint64_t>(b, 255)), 4);
  checks.Equal(
    "points of return 15", static_cast<long long>(At<std::uint64_t>(b, 255 + 14 * 8)), 3);
  checks.Near("x scale", At<double>(b, 131), 0.001, 0);
  checks.Near("z scale", At<double>(b, 147), 0.0001, 0);
  checks.Near("y offset", At<double>(b, 163), 800000, 0);
  checks.Near("max x", At<double>(b, 179), 637180.123 + 0.731 * 49, 1e-6);
  checks.Near("min x", At<double>(b, 187), 637180.123, 1e-6);
  checks.Near("max y", At<double>(b, 195), 852000.5, 1e-6);
  checks.Near("min z", At<double>(b, 219), 12.345, 1e-6);
  checks.Equal("two VLRs (WKT, Extra Bytes)", At<std::uint32_t>(b, 100), 2);
  const std::size_t wktVlr = 375;
  checks.True(
    "WKT VLR user id", b.compare(wktVlr + 2, 16, std::string("LASF_Projection\0", 16)) == 0);
  checks.Equal("WKT VLR record id 2112", At<std::uint16_t>(b, wktVlr + 18), 2112);
  const std::size_t wktLength = At<std::uint16_t>(b, wktVlr + 20);
  checks.Equal("WKT VLR length (null-terminated)", wktLength, wkt.size() + 1);
  checks.True(
    "WKT text", b.compare(wktVlr + 54, wkt.size(), wkt) == 0 && b[wktVlr + 54 + wkt.size()] == 0);
  const std::size_t eb = wktVlr + 54 + wktLength;
  checks.Equal("Extra Bytes VLR reserved 0", At<std::uint16_t>(b, eb), 0);
  checks.True("Extra Bytes VLR user id LASF_Spec",
    b.compare(eb + 2, 16, std::string("LASF_Spec\0\0\0\0\0\0\0", 16)) == 0);
  checks.Equal("Extra Bytes record id 4", At<std::uint16_t>(b, eb + 18), 4);
  checks.Equal("192 bytes a descriptor", At<std::uint16_t>(b, eb + 20), 192 * dimensions);
  checks.Equal("offset to point data", At<std::uint32_t>(b, 96), eb + 54 + 192 * dimensions);
  checks.Equal("file size", b.size(), eb + 54 + 192 * dimensions + Count * (38 + extraBytes));
  const struct
  {
    const char* Name;
    int Type;
  } expected[] = { { "Mean_Curvature", 10 },
    { "Minimum_Curvature_Direction_X", 10 },
    { "Minimum_Curvature_Direction_Y", 10 },
    { "Minimum_Curvature_Direction_Z", 10 },
    { "Normals_X", 9 },
    { "Normals_Y", 9 },
    { "Normals_Z", 9 },
    { "Curvature_Valid", 1 },
    { "Neighbor_Count", 6 },
    { "Signed_Flag", 2 },
    { "Big_Count", 8 },
    { "A_Name_Much_Longer_Than_The_32_C", 10 },
    { UniqueCut, 10 } };
  for (int d = 0; d < dimensions; ++d)
  {
    const std::size_t at = eb + 54 + 192 * d;
    const std::string name(b.data() + at + 4, strnlen(b.data() + at + 4, 32));
    checks.True(
      ("descriptor name " + std::string(expected[d].Name)).c_str(), name == expected[d].Name);
    checks.Equal("descriptor data_type", static_cast<unsigned char>(b[at + 2]), expected[d].Type);
    checks.Equal("descriptor options 0 (no scale, offset, no_data)", b[at + 3], 0);
    bool zeros = At<std::uint16_t>(b, at) == 0 && At<std::uint32_t>(b, at + 36) == 0;
    for (std::size_t k = at + 40; k < at + 160; ++k)
      zeros = zeros && b[k] == 0;
    checks.True("descriptor reserved, no_data, min, max, scale, offset zero", zeros);
    checks.True(
      "name padded with zeros", b.find_first_not_of('\0', at + 4 + name.size()) >= at + 36);
  }
  // The first record: x as the int32 of (x - offset) / scale.
  const std::size_t first = At<std::uint32_t>(b, 96);
  checks.Equal("first x", At<std::int32_t>(b, first), 37180123);
  checks.Equal("first return byte", static_cast<unsigned char>(b[first + 14]), 1 | (15 << 4));
  checks.Near("first Mean_Curvature extra", At<double>(b, first + 38), 0, 0);
}

void TestChosenScale(Checks& checks)
{
  vtkSmartPointer<vtkPolyData> cloud = MakeCloud(false, false);
  const Written written = Write(cloud, "chosen_scale.las");
  const std::string b = Bytes(written.Path);
  // x spans 35.8: the finest power of ten within 10^9 units is 1e-7.
  checks.Near("x scale from the extent", At<double>(b, 131), 1e-7, 1e-20);
  checks.Near("x offset at the minimum", At<double>(b, 155), 637180.123, 0);
  checks.Near("z scale (extent 24.01)", At<double>(b, 147), 1e-7, 1e-20);
  checks.Equal("no coordinate system: global encoding 0", At<std::uint16_t>(b, 6), 0);
  vtkSmartPointer<vtkPolyData> read = Read(written.Path);
  double worst = 0;
  for (vtkIdType i = 0; i < read->GetNumberOfPoints(); ++i)
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::fabs(cloud->GetPoint(i)[c] - read->GetPoint(i)[c]));
  checks.Near("coordinates within half the chosen scale", worst, 0, 0.5e-7 + 1e-9);
  checks.True("no unit without a coordinate system", StringField(read, "Length_Unit") == "(none)");

  // Float points (a text cloud's): the same scale, the float values kept.
  vtkNew<vtkPoints> single;
  single->SetDataTypeToFloat();
  single->DeepCopy(cloud->GetPoints());
  single->SetDataTypeToFloat();
  for (vtkIdType i = 0; i < Count; ++i)
    single->SetPoint(i, cloud->GetPoint(i));
  cloud->SetPoints(single);
  vtkSmartPointer<vtkPolyData> readFloat = Read(Write(cloud, "float_points.las").Path);
  worst = readFloat->GetNumberOfPoints() == Count ? 0 : 1;
  for (vtkIdType i = 0; i < readFloat->GetNumberOfPoints(); ++i)
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::fabs(cloud->GetPoint(i)[c] - readFloat->GetPoint(i)[c]));
  checks.Near("float points kept within half the scale", worst, 0, 0.5e-7 + 1e-9);
}

void TestUnits(Checks& checks)
{
  const struct
  {
    const char* Name;
    std::string File;
    const char* Unit;
    const char* System;
  } cases[] = {
    { "geokeys_foot.las",
      LegacyFile({ { 34735, GeoKeys(2276, 9002, 9002) } }),
      "foot",
      "EPSG:2276" },
    { "geokeys_usfoot.las",
      LegacyFile({ { 34735, GeoKeys(2231, 9003, 0) } }),
      "US survey foot",
      "EPSG:2231" },
    { "geokeys_utm.las", LegacyFile({ { 34735, GeoKeys(32633, 0, 0) } }), "metre", "EPSG:32633" },
    { "wkt_compound.las",
      LegacyFile({ { 2112,
        std::string("COMPD_CS[\"x\",PROJCS[\"NAD83 / Ohio North (ftUS)\",GEOGCS[\"NAD83\","
                    "UNIT[\"degree\",0.0174532925199433]],UNIT[\"US survey foot\","
                    "0.3048006096012192,AUTHORITY[\"EPSG\",\"9003\"]]],VERT_CS[\"NAVD88\","
                    "UNIT[\"foot\",0.3048]]]") +
          '\0' } }),
      "US survey foot",
      "COMPD_CS[" },
    { "wkt2_metre.las",
      LegacyFile({ { 2112,
        std::string(
          "PROJCRS[\"ETRS89 / UTM 32N\",BASEGEOGCRS[\"ETRS89\",ANGLEUNIT[\"degree\","
          "0.0174532925199433]],CS[Cartesian,2],AXIS[\"(E)\",east,ORDER[1],"
          "LENGTHUNIT[\"metre\",1]],AXIS[\"(N)\",north,ORDER[2],LENGTHUNIT[\"metre\",1]]]") +
          '\0' } }),
      "metre",
      "PROJCRS[" },
    { "no_crs.las", LegacyFile({}), "(none)", "(none)" },
  };
  for (const auto& c : cases)
  {
    const std::string path = Folder + "/" + c.Name;
    WriteBytes(path, c.File);
    std::string errors;
    vtkSmartPointer<vtkPolyData> read = Read(path, &errors);
    std::printf("%s: Length_Unit %s, Coordinate_System %.40s\n",
      c.Name,
      StringField(read, "Length_Unit").c_str(),
      StringField(read, "Coordinate_System").c_str());
    checks.True(
      (std::string(c.Name) + ": read").c_str(), errors.empty() && read->GetNumberOfPoints() == 3);
    checks.True(
      (std::string(c.Name) + ": Length_Unit").c_str(), StringField(read, "Length_Unit") == c.Unit);
    checks.True((std::string(c.Name) + ": Coordinate_System").c_str(),
      StringField(read, "Coordinate_System").compare(0, std::strlen(c.System), c.System) == 0);
    checks.Equal("ScanAngleRank is a short (printed as a number)",
      read->GetPointData()->GetArray("ScanAngleRank")->GetDataType(),
      VTK_SHORT);
    // Written as LAS 1.4 and read again: the same system and unit, the
    // records copied as they were.
    const Written again = Write(read, std::string("again_") + c.Name);
    vtkSmartPointer<vtkPolyData> reread = Read(again.Path);
    checks.True("unit kept through the writer", StringField(reread, "Length_Unit") == c.Unit);
    checks.True("system kept through the writer",
      StringField(reread, "Coordinate_System") == StringField(read, "Coordinate_System"));
    checks.Near("ScanAngleRank -13 as ScanAngle", ValueOf(reread, "ScanAngle", 0), -13, 0.003);
    checks.Near("ScanAngleRank 45 as ScanAngle", ValueOf(reread, "ScanAngle", 1), 45, 0.003);
    checks.Near("x kept", reread->GetPoint(2)[0], 2000002, 1e-9);
    const std::string b = Bytes(again.Path);
    const bool wkt = std::string(c.Name).compare(0, 3, "wkt") == 0;
    checks.Equal("WKT bit only with a WKT record", At<std::uint16_t>(b, 6), wkt ? 0x10 : 0);
  }
}

void TestExtraBytesRead(Checks& checks)
{
  const std::string descriptors = Descriptor(3, 0x18, "Scaled", 0.01, 5) +
    Descriptor(9, 0, "Value", 0, 0) + Descriptor(0, 1, "", 0, 0) +
    Descriptor(4, 0, "Intensity", 0, 0);
  const std::string path = Folder + "/extra_bytes.las";
  WriteBytes(path, ExtraBytesFile(descriptors, 9));
  std::string errors;
  vtkSmartPointer<vtkPolyData> read = Read(path, &errors);
  checks.True("extra bytes file read", errors.empty() && read->GetNumberOfPoints() == 2);
  checks.Equal("scaled: double", TypeOf(read, "Scaled"), VTK_DOUBLE);
  checks.Near("scaled value 100 * 0.01 + 5", ValueOf(read, "Scaled", 0), 6.0, 1e-12);
  checks.Near("scaled value 101 * 0.01 + 5", ValueOf(read, "Scaled", 1), 6.01, 1e-12);
  checks.Equal("float: float", TypeOf(read, "Value"), VTK_FLOAT);
  checks.Near("float value", ValueOf(read, "Value", 1), 5.0, 0);
  checks.Equal("a second Intensity renamed, a short", TypeOf(read, "Intensity_2"), VTK_SHORT);
  checks.Near("its value after the undocumented byte", ValueOf(read, "Intensity_2", 1), -4, 0);
  checks.Near("the standard Intensity untouched", ValueOf(read, "Intensity", 1), 0, 0);

  // Descriptors for more bytes than the records have: the record is void.
  const std::string mismatch = Folder + "/extra_bytes_mismatch.las";
  WriteBytes(mismatch, ExtraBytesFile(descriptors, 9).replace(105, 2, std::string("\x25\x00", 2)));
  vtkSmartPointer<vtkPolyData> partial = Read(mismatch, &errors);
  checks.True("mismatch: points read", partial->GetNumberOfPoints() == 2);
  checks.True("mismatch: no extra arrays", TypeOf(partial, "Scaled") < 0);
}

/// A LAS 1.4 file whose WKT is in an extended VLR after the points.
void TestWktInEvlr(Checks& checks)
{
  std::string bytes = Bytes(Write(MakeCloud(false, false), "before_evlr.las").Path);
  const std::string wkt = "PROJCS[\"x\",GEOGCS[\"y\"],UNIT[\"foot\",0.3048]]";
  const std::uint64_t start = bytes.size();
  bytes += std::string(2, '\0') + std::string("LASF_Projection\0", 16);
  Append(bytes, static_cast<std::uint16_t>(2112));
  Append(bytes, static_cast<std::uint64_t>(wkt.size() + 1));
  bytes += std::string(32, '\0') + wkt + '\0';
  std::string patch;
  Append(patch, start);
  Append(patch, static_cast<std::uint32_t>(1));
  bytes.replace(235, patch.size(), patch);
  const std::string path = Folder + "/wkt_evlr.las";
  WriteBytes(path, bytes);
  std::string errors;
  vtkSmartPointer<vtkPolyData> read = Read(path, &errors);
  checks.True("EVLR file read", errors.empty() && read->GetNumberOfPoints() == Count);
  checks.True("WKT from the EVLR", StringField(read, "Coordinate_System") == wkt);
  checks.True("its unit", StringField(read, "Length_Unit") == "foot");
  checks.True(
    "the extra bytes still read", read->GetPointData()->GetArray("Mean_Curvature") != nullptr);
}

void TestBadInput(Checks& checks)
{
  vtkSmartPointer<vtkPolyData> far = MakeCloud(false, true);
  far->GetPoints()->SetPoint(7, 1e7, 852000, 0);
  Written w = Write(far, "bad_far.las");
  std::printf("%s", w.Errors.c_str());
  checks.True("a point beyond the kept scale: error",
    w.Errors.find(
      "the x coordinate 10000000 does not fit LAS's 32-bit integers with scale 0.001") !=
      std::string::npos);
  checks.True("no file after an error", Bytes(w.Path).empty());

  vtkSmartPointer<vtkPolyData> intense = MakeCloud(false, true);
  vtkNew<vtkIntArray> wide;
  wide->SetName("Intensity");
  wide->SetNumberOfTuples(Count);
  wide->FillValue(70000);
  intense->GetPointData()->AddArray(wide);
  w = Write(intense, "bad_intensity.las");
  std::printf("%s", w.Errors.c_str());
  checks.True("Intensity 70000: error",
    w.Errors.find("the array Intensity holds 70000 at point 0") != std::string::npos);

  vtkSmartPointer<vtkPolyData> nan = MakeCloud(false, false);
  nan->GetPoints()->SetPoint(3, std::nan(""), 0, 0);
  w = Write(nan, "bad_nan.las");
  checks.True("a NaN coordinate: error",
    w.Errors.find("point 3 has a coordinate that is not a finite number") != std::string::npos);

  vtkNew<vtkPolyData> empty;
  vtkNew<vtkPoints> none;
  empty->SetPoints(none);
  w = Write(empty, "bad_empty.las");
  checks.True("no points: error", w.Errors.find("the input has no points") != std::string::npos);
}

} // namespace

int main(int argc, char* argv[])
{
  Folder = argc > 2 ? argv[2] : ".";
  return RunNamedTests(argc > 1 ? 2 : 1,
    argv,
    {
      { "RoundTrip", TestRoundTrip },
      { "DerivedColors", TestDerivedColors },
      { "HeaderBytes", TestHeaderBytes },
      { "ChosenScale", TestChosenScale },
      { "Units", TestUnits },
      { "ExtraBytesRead", TestExtraBytesRead },
      { "WktInEvlr", TestWktInEvlr },
      { "BadInput", TestBadInput },
    });
}
