// vtkPLYPointCloudReader on small PLY files written here: ascii, binary
// little and big endian, with an element before the vertices and faces
// after them, double x y z kept exactly, float ones as float, normals under
// two naming schemes, uchar colors as RGB, every other vertex property as
// its own array of its type, a vertex list property skipped; an edge
// element (vertex1 vertex2, as the command-line tool writes curvature
// lines) as line cells with its other properties as cell data; then bad
// files, each with the error it must give (and no points, no crash).
#include "ReaderTestHelpers.h"
#include "TestChecks.h"
#include "vtkPLYPointCloudReader.h"

#include "vtkCellData.h"
#include "vtkErrorCode.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPoints.h"

#include <cstdint>
#include <string>
#include <vector>

namespace
{

struct Vertex
{
  double X, Y, Z;
  float Normal[3];
  std::uint8_t Color[3];
  std::int32_t Label;
  float Quality;
};

const std::vector<Vertex> Vertices = {
  { 596700.123, 243650.5, 80.0, { 0, 0, 1 }, { 255, 0, 10 }, 7, 0.5f },
  { 596702.000000001, 243648.1, 82.000000002, { 0.6f, 0, -0.8f }, { 1, 2, 3 }, -3, 1e-7f },
  { -0.1, 1e-30, -1e30, { 0, -1, 0 }, { 0, 128, 255 }, 2147483647, -2.5f },
};

/// A PLY file of Vertices: a camera element before them, faces after,
/// x y z double (or float), normals, colors, label, quality and a list.
std::string PlyFile(const std::string& format, bool floatPoints, const char* normal = "normal_")
{
  const std::string point = floatPoints ? "float" : "double";
  std::string text = "ply\nformat " + format + " 1.0\ncomment written by TestPLYReader\n" +
    "element camera 1\nproperty float view_px\nproperty list uchar int tags\n" +
    "element vertex 3\nproperty " + point + " x\nproperty " + point + " y\nproperty " + point +
    " z\n";
  for (const char* axis : { "x", "y", "z" })
  {
    text += std::string("property float ") + normal + axis + "\n";
  }
  text += "property uchar red\nproperty uchar green\nproperty uchar blue\nproperty int label\n"
          "property list uchar int indices\nproperty float quality\n"
          "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const bool big = format == "binary_big_endian";
  const auto put = [&](auto value)
  {
    if (big)
      AppendBigEndian(text, value);
    else
      Append(text, value);
  };
  if (format == "ascii")
  {
    char line[400];
    text += "1.5 2 7 9\n";
    for (const Vertex& v : Vertices)
    {
      std::snprintf(line,
        sizeof line,
        "%.17g %.17g %.17g %.9g %.9g %.9g %d %d %d %d 2 4 5 %.9g\n",
        floatPoints ? static_cast<float>(v.X) : v.X,
        floatPoints ? static_cast<float>(v.Y) : v.Y,
        floatPoints ? static_cast<float>(v.Z) : v.Z,
        v.Normal[0],
        v.Normal[1],
        v.Normal[2],
        v.Color[0],
        v.Color[1],
        v.Color[2],
        v.Label,
        v.Quality);
      text += line;
    }
    return text + "3 0 1 2\n";
  }
  put(1.5f);
  put(std::uint8_t(2));
  put(std::int32_t(7));
  put(std::int32_t(9));
  for (const Vertex& v : Vertices)
  {
    for (double c : { v.X, v.Y, v.Z })
    {
      if (floatPoints)
        put(static_cast<float>(c));
      else
        put(c);
    }
    for (float c : v.Normal)
      put(c);
    for (std::uint8_t c : v.Color)
      put(c);
    put(v.Label);
    put(std::uint8_t(2));
    put(std::int32_t(4));
    put(std::int32_t(5));
    put(v.Quality);
  }
  put(std::uint8_t(3));
  for (std::int32_t i : { 0, 1, 2 })
    put(i);
  return text;
}

struct Read
{
  vtkSmartPointer<vtkPolyData> Cloud;
  std::string Errors;
  unsigned long Code = 0;
};

Read ReadPly(const std::string& path)
{
  vtkNew<vtkPLYPointCloudReader> reader;
  vtkNew<ErrorCatcher> catcher;
  reader->AddObserver(vtkCommand::ErrorEvent, catcher);
  reader->SetFileName(path.c_str());
  reader->Update();
  return { reader->GetOutput(), catcher->Messages, reader->GetErrorCode() };
}

void CheckGoodFile(Checks& checks,
  const std::string& folder,
  const std::string& format,
  bool floatPoints,
  const char* normal)
{
  const std::string path =
    folder + "/good_" + format + (floatPoints ? "_float" : "_double") + normal + ".ply";
  WriteBytes(path, PlyFile(format, floatPoints, normal));
  const Read read = ReadPly(path);
  std::printf("%s, %s points, normals %sx: %s\n",
    format.c_str(),
    floatPoints ? "float" : "double",
    normal,
    read.Errors.empty() ? "read" : read.Errors.c_str());
  vtkPolyData* cloud = read.Cloud;
  checks.True("no error", read.Errors.empty() && read.Code == vtkErrorCode::NoError);
  checks.Equal("points", cloud->GetNumberOfPoints(), 3);
  checks.Equal("vertex cells", cloud->GetNumberOfVerts(), 3);
  if (cloud->GetNumberOfPoints() != 3)
  {
    return;
  }
  checks.Equal(
    "point type", cloud->GetPoints()->GetDataType(), floatPoints ? VTK_FLOAT : VTK_DOUBLE);
  vtkPointData* pd = cloud->GetPointData();
  checks.True(
    "Normals attribute", pd->GetNormals() && pd->GetNormals()->GetName() == std::string("Normals"));
  checks.True("RGB scalars, uchar",
    pd->GetScalars() && pd->GetScalars()->GetName() == std::string("RGB") &&
      pd->GetScalars()->GetDataType() == VTK_UNSIGNED_CHAR &&
      pd->GetScalars()->GetNumberOfComponents() == 3);
  checks.Equal("label is int", TypeOf(cloud, "label"), VTK_INT);
  checks.Equal("quality is float", TypeOf(cloud, "quality"), VTK_FLOAT);
  checks.Equal("arrays: Normals RGB label quality (no list)", pd->GetNumberOfArrays(), 4);
  for (int i = 0; i < 3; ++i)
  {
    const Vertex& v = Vertices[i];
    double x[3];
    cloud->GetPoint(i, x);
    const double* expected = &v.X;
    for (int c = 0; c < 3; ++c)
    {
      const double want = floatPoints ? static_cast<float>(expected[c]) : expected[c];
      checks.Near("coordinate, exactly", x[c], want, 0);
      checks.Near("normal", pd->GetNormals()->GetComponent(i, c), v.Normal[c], 0);
      checks.Near("color", pd->GetScalars()->GetComponent(i, c), v.Color[c], 0);
    }
    checks.Near("label", ValueOf(cloud, "label", i), v.Label, 0);
    checks.Near("quality", ValueOf(cloud, "quality", i), v.Quality, 0);
  }
}

/// Edges: two segments of a polyline over three of four vertices, each
/// with its kind and length, as line cells and cell data.
void CheckEdges(Checks& checks, const std::string& folder)
{
  const std::string path = folder + "/edges.ply";
  WriteBytes(path,
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
    "property double z\nelement edge 2\nproperty int vertex1\nproperty int vertex2\n"
    "property uchar Line_Kind\nproperty double Line_Length\nend_header\n"
    "0 0 0\n1 0 0\n2 0 0\n9 9 9\n0 1 1 2.5\n1 2 1 2.5\n");
  const Read read = ReadPly(path);
  vtkPolyData* lines = read.Cloud;
  checks.True("edges: no error", read.Errors.empty());
  checks.Equal("edges: points", lines->GetNumberOfPoints(), 4);
  checks.Equal("edges: line cells", lines->GetNumberOfLines(), 2);
  checks.Equal("edges: no vertex cells", lines->GetNumberOfVerts(), 0);
  vtkDataArray* kind = lines->GetCellData()->GetArray("Line_Kind");
  vtkDataArray* length = lines->GetCellData()->GetArray("Line_Length");
  checks.True("edges: Line_Kind uchar, Line_Length double",
    kind && length && kind->GetDataType() == VTK_UNSIGNED_CHAR &&
      length->GetDataType() == VTK_DOUBLE && lines->GetCellData()->GetNumberOfArrays() == 2);
  if (lines->GetNumberOfLines() == 2 && kind && length)
  {
    vtkNew<vtkIdList> ends;
    lines->GetCellPoints(1, ends);
    checks.True("edges: the second from vertex 1 to 2", ends->GetId(0) == 1 && ends->GetId(1) == 2);
    checks.Near("edges: kind", kind->GetComponent(1, 0), 1, 0);
    checks.Near("edges: length", length->GetComponent(1, 0), 2.5, 0);
  }
}

struct BadCase
{
  const char* Name;
  std::string Bytes;
  const char* Expected;
};

void CheckBadFiles(Checks& checks, const std::string& folder)
{
  const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
  const std::string good = PlyFile("binary_little_endian", false);
  const std::string ascii = PlyFile("ascii", false);
  const std::vector<BadCase> cases = {
    { "no_vertex.ply",
      "ply\nformat ascii 1.0\nelement face 0\nproperty list uchar int v\nend_header\n",
      "no vertex element (elements: face), so no points" },
    { "colors_only.ply",
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty uchar red\nproperty uchar green\n"
      "property uchar blue\nend_header\n1 2 3\n",
      "the vertex element has no x, y, z properties (it has: red green blue), so no points" },
    { "only_xy.ply",
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n1 "
      "2\n",
      "the vertex element has no z property (it has: x y), so no points" },
    { "truncated.ply",
      good.substr(0, good.size() - 40),
      "the file ends in element vertex 2 of 3 (truncated)" },
    { "truncated_ascii.ply",
      ascii.substr(0, ascii.find("\n-0.1")),
      "the file ends in element vertex 2 of 3 (truncated)" },
    { "count_lies.ply",
      "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000\n" + xyz + "end_header\n" +
        std::string(24, '\0'),
      "the header declares 1000000000 vertices (12 bytes each at least), but the data after the "
      "header has only 24 bytes" },
    { "not_ply.ply",
      "PLX\nformat ascii 1.0\n",
      "not a PLY file (it does not start with a line 'ply')" },
    { "empty.ply", "", "not a PLY file" },
    { "no_end.ply",
      "ply\nformat ascii 1.0\nelement vertex 1\n" + xyz,
      "the header has no end_header line" },
    { "data_in_header.ply",
      "ply\nformat ascii 1.0\nelement vertex 1\n" + xyz + "1 2 3\n",
      "header line 7: unknown header line '1' (is end_header missing?)" },
    { "no_format.ply",
      "ply\nelement vertex 1\n" + xyz + "end_header\n",
      "header line 2: the format line must follow 'ply'" },
    { "unknown_format.ply",
      "ply\nformat binary_middle_endian 1.0\nend_header\n",
      "header line 2: unknown format 'binary_middle_endian'" },
    { "unknown_type.ply",
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty int128 x\nend_header\n",
      "header line 4: unknown property type 'int128' of property 'x'" },
    { "bad_element.ply",
      "ply\nformat ascii 1.0\nelement vertex lots\nend_header\n",
      "header line 3: an element line needs 'element <name> <count>'" },
    { "property_first.ply",
      "ply\nformat ascii 1.0\nproperty float x\nend_header\n",
      "header line 3: a property before any element" },
    { "bad_value.ply",
      "ply\nformat ascii 1.0\nelement vertex 2\n" + xyz + "end_header\n1 2 3\n4 abc 6\n",
      "element vertex 1: 'abc' is not a float value" },
    { "edge_out_of_range.ply",
      "ply\nformat ascii 1.0\nelement vertex 2\n" + xyz +
        "element edge 2\nproperty int vertex1\nproperty int vertex2\nend_header\n"
        "0 0 0\n1 1 1\n0 1\n1 7\n",
      "edge 1: vertex 7 is not one of the 2 vertices" },
    { "out_of_range.ply",
      "ply\nformat ascii 1.0\nelement vertex 1\n" + xyz +
        "property uchar red\nend_header\n1 2 3 300\n",
      "element vertex 0: '300' is not a uchar value" },
  };
  for (const BadCase& bad : cases)
  {
    const std::string path = folder + "/" + bad.Name;
    WriteBytes(path, bad.Bytes);
    const Read read = ReadPly(path);
    std::printf("%s: %s", bad.Name, read.Errors.c_str());
    const bool named = read.Errors.find(path + ": ") != std::string::npos;
    const bool said = read.Errors.find(bad.Expected) != std::string::npos;
    checks.True(bad.Name, named && said && read.Code != vtkErrorCode::NoError);
    checks.Equal(bad.Name, read.Cloud->GetNumberOfPoints(), 0);
  }
  const std::string none = folder + "/no_vertices.ply";
  WriteBytes(none, "ply\nformat ascii 1.0\nelement vertex 0\n" + xyz + "end_header\n");
  const Read empty = ReadPly(none);
  checks.True("0 vertices: no error, no points",
    empty.Errors.empty() && empty.Cloud->GetNumberOfPoints() == 0);
}

} // namespace

int main(int argc, char* argv[])
{
  const std::string folder = argc > 1 ? argv[1] : ".";
  Checks checks;
  for (const char* format : { "ascii", "binary_little_endian", "binary_big_endian" })
  {
    CheckGoodFile(checks, folder, format, false, "normal_");
    CheckGoodFile(checks, folder, format, true, "n");
  }
  CheckEdges(checks, folder);
  CheckBadFiles(checks, folder);
  return checks.Summary();
}
