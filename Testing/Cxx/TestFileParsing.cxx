// The core's file parsers alone (no VTK): text clouds and OFF meshes, each
// bad input with its message, the column layout, the NaN policy, and the
// tests that tell other formats sharing the .xyz extension apart. Fast and
// small, so that the sanitizer builds run it too.
#include "FileFormats/MeshOrientation.h"
#include "FileFormats/OffMesh.h"
#include "TestChecks.h"
#include "FileFormats/TextPointCloud.h"

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace
{
using namespace pcurv;

std::string Parse(const std::string& text, TextCloud& cloud, bool pts = false)
{
  return ParseTextCloud(text.data(), text.size(), pts, false, cloud);
}

/// The message for a bad text cloud, and that it gave no points to use.
std::string ParseError(const std::string& text, bool pts = false)
{
  TextCloud cloud;
  return Parse(text, cloud, pts);
}

bool Contains(const std::string& text, const char* part)
{
  return text.find(part) != std::string::npos;
}

void TestBadTextClouds(Checks& checks)
{
  checks.True("empty file", ParseError("") == "the file is empty: no points");
  checks.True(
    "only a byte order mark", ParseError("\xEF\xBB\xBF") == "the file is empty: no points");
  checks.True("comments and blank lines",
    ParseError("# a\n\n// b\n") == "no points: its 3 line(s) are blank or comments");
  checks.True(
    "two columns", ParseError("1 2\n3 4\n") == "line 1: 2 number(s); a point needs at least x y z");
  checks.True("words after a header",
    ParseError("hello world\nfoo bar baz\n") ==
      "line 2: 'foo' is not a number (line 1, 'hello world', was taken for a header of column "
      "names)");
  checks.True("a header only", Contains(ParseError("x y z\n"), "line 1: 'x y z' is not numbers"));
  checks.True("a point count only",
    ParseError("12\n") == "line 1: only a point count, and no line of numbers follows: no points");
  checks.True("a later line with too few numbers",
    ParseError("1 2 3\n4 5 6\n7 8\n") == "line 3: 2 columns, but line 1 has 3");
  checks.True("a later line with too many numbers",
    ParseError("1 2 3\n\n4 5 6 7\n") == "line 3: 4 columns, but line 1 has 3");
  checks.True(
    "a word among numbers", ParseError("1 2 3\n4 5 x6\n") == "line 2: 'x6' is not a number");
  const std::string binary("1 2 3\n4 5\0 6\n", 13);
  checks.True("a NUL byte", ParseError(binary) == "line 2: a NUL byte (byte 9): not a text file");
  checks.True("unprintable bytes are escaped in messages",
    Contains(ParseError("1 2 3\n4 5 \x01\x7f\n"), "'\\x01\\x7f' is not a number"));
  checks.True("header and data disagree",
    ParseError("x y z nx\n1 2 3\n") == "line 2: 3 columns, but the header (line 1) names 4");
}

void TestNonFiniteNumbers(Checks& checks)
{
  TextCloud cloud;
  checks.True(
    "NaN and infinity are numbers", Parse("1 2 3\nnan 5 6\n7 8 9\n10 -inf 12\n", cloud).empty());
  checks.Equal("NaN rows are kept", static_cast<long long>(cloud.Rows()), 4);
  const std::vector<std::size_t> lines =
    NonFinitePositionLines(cloud, ChooseColumnLayout(cloud, false));
  checks.True("the lines of the rows with a NaN or infinite coordinate",
    lines == std::vector<std::size_t>({ 2, 4 }));
  cloud = TextCloud();
  Parse("1 2 3 0 0 1\n4 5 6 nan 0 1\n", cloud);
  checks.True("a NaN normal is no NaN coordinate",
    NonFinitePositionLines(cloud, ChooseColumnLayout(cloud, false)).empty());
}

void TestLayouts(Checks& checks)
{
  TextCloud cloud;
  Parse("1 2 3 0 0 1\n4 5 6 0 1 0\n", cloud);
  ColumnLayout layout = ChooseColumnLayout(cloud, false);
  checks.True("6 columns: normals", layout.Normal == std::vector<std::size_t>({ 3, 4, 5 }));
  cloud = TextCloud();
  Parse("1 2 3 255 0 10\n4 5 6 0 128 255\n", cloud);
  layout = ChooseColumnLayout(cloud, false);
  checks.True("x y z r g b: colors, no normals", layout.Normal.empty() && layout.Color.size() == 3);
  cloud = TextCloud();
  Parse("2\n1 2 3 -5 10 20 30\n4 5 6 7 40 50 60\n", cloud, true);
  layout = ChooseColumnLayout(cloud, true);
  checks.True(".pts: intensity and colors",
    layout.Normal.empty() && layout.Color.size() == 3 && layout.Scalars.size() == 1 &&
      layout.Scalars[0].second == "Intensity");
}

std::string Bytes(const std::vector<std::int32_t>& words)
{
  std::string bytes(4 * words.size(), '\0');
  std::memcpy(&bytes[0], words.data(), bytes.size());
  return bytes;
}

void TestOtherFormats(Checks& checks)
{
  const std::string water = "3\nwater\nO 0 0 0\nH 0.76 0.59 0\nH -0.76 0.59 0\n";
  checks.True("an XYZ molecule", LooksLikeMolecule(water.data(), water.size()));
  const std::string cloud = "3\n1 2 3\n4 5 6\n7 8 9\n";
  checks.True(
    "a cloud with a count line is no molecule", !LooksLikeMolecule(cloud.data(), cloud.size()));
  const std::string record = Bytes({ 12, 4, 5, 6, 12, 0, 0, 0 });
  checks.True("a PLOT3D grid as Fortran records", LooksLikePlot3d(record.data(), record.size()));
  const std::string plain = Bytes({ 1, 10, 20, 30, 0, 0 });
  checks.True("a PLOT3D grid without records", LooksLikePlot3d(plain.data(), plain.size()));
  std::string noise(1024, '\0');
  std::uint32_t state = 12345;
  for (char& byte : noise)
  {
    state = state * 1664525u + 1013904223u;
    byte = static_cast<char>(state >> 24);
  }
  noise[7] = '\0';
  checks.True("random bytes are no PLOT3D grid", !LooksLikePlot3d(noise.data(), noise.size()));
  checks.True("text is no PLOT3D grid", !LooksLikePlot3d(cloud.data(), cloud.size()));
}

std::string OffError(const std::string& text)
{
  OffMesh mesh;
  return ParseOffMesh(text.data(), text.size(), mesh);
}

void TestOffMeshes(Checks& checks)
{
  OffMesh mesh;
  const std::string tetrahedron = "OFF # a tetrahedron\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 "
                                  "1\n3 0 1 3\n3 0 3 2\n3 1 2 3 255 0 0\n";
  checks.True("a tetrahedron", ParseOffMesh(tetrahedron.data(), tetrahedron.size(), mesh).empty());
  checks.Equal("its faces", static_cast<long long>(mesh.Faces()), 4);
  checks.Equal("its vertex indices", static_cast<long long>(mesh.Connectivity.size()), 12);
  mesh = OffMesh();
  const std::string counts = "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  checks.True(
    "counts on the header line", ParseOffMesh(counts.data(), counts.size(), mesh).empty());
  checks.True("empty", OffError("") == "the file is empty (no OFF header)");
  checks.True(
    "not OFF", OffError("ply\n") == "line 1: 'ply' where the OFF header belongs: not an OFF file");
  checks.True("binary", Contains(OffError("OFF BINARY\n"), "binary OFF"));
  checks.True(
    "no counts", Contains(OffError("OFF\n"), "the counts 'vertices faces edges' are missing"));
  checks.True("bad counts", Contains(OffError("OFF\nfour 4 6\n"), "line 2: the counts"));
  checks.True("a short vertex",
    OffError("OFF\n2 0 0\n0 0 0\n1 0\n") == "line 4: vertex 1: 2 number(s); a vertex needs x y z");
  // Found by fuzzing: a huge count in a tiny file reserved memory for it.
  checks.True("a vertex count beyond the file's size",
    OffError("OFF\n777777777888885 0\n") ==
      "the file ends after 0 of its 777777777888885 vertices");
  checks.True("missing vertices",
    OffError("OFF\n3 0 0\n0 0 0\n") == "the file ends after 1 of its 3 vertices");
  checks.True("an index out of range",
    OffError("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n") ==
      "line 6: face 0: '3' is not a vertex index (0 to 2)");
  checks.True("a face of two vertices",
    Contains(
      OffError("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n"), "line 6: face 0: '2' then 2 word(s)"));
  const double points[] = { 1, 0, 0, -1, 0, 0, 0, 1, 0 };
  const double outward[] = { 1, 0, 0, -1, 0, 0, 0, 1, 0 };
  const double inward[] = { -1, 0, 0, 1, 0, 0, 0, -1, 0 };
  checks.True("outward normals", !NormalsMostlyInward(points, outward, 3));
  checks.True("inward normals", NormalsMostlyInward(points, inward, 3));
}

} // namespace

int main()
{
  Checks checks;
  TestBadTextClouds(checks);
  TestNonFiniteNumbers(checks);
  TestLayouts(checks);
  TestOtherFormats(checks);
  TestOffMeshes(checks);
  return checks.Summary();
}
