/**
 * PLY files (ascii, binary_little_endian, binary_big_endian) read as point
 * clouds: the header checked, then the vertex element's properties read
 * into the caller's arrays, in their own types (x y z stay double when the
 * file has double); an edge element (vertex1 vertex2: segments between two
 * vertices, as MeshLab writes them) read as rows of values. Other elements
 * are skipped. No VTK here;
 * vtkPLYPointCloudReader is the VTK glue.
 */
#ifndef pcurv_PlyFile_h
#define pcurv_PlyFile_h

#include "FileFormats/FileInput.h"
#include "FileFormats/PlyComments.h"

#include <cstdint>
#include <string>
#include <vector>

namespace pcurv
{
namespace ply
{

enum class Type
{
  Int8,
  UInt8,
  Int16,
  UInt16,
  Int32,
  UInt32,
  Float32,
  Float64
};

/// The type's name in PLY headers (char, uchar, ...).
const char* NameOf(Type type);

/// Bytes of one value of the type.
int SizeOf(Type type);

struct Property
{
  std::string Name;
  Type ValueType = Type::Float32;
  bool IsList = false;
  Type CountType = Type::UInt8; // of a list
};

struct Element
{
  std::string Name;
  std::uint64_t Count = 0;
  std::vector<Property> Properties;
};

enum class Format
{
  Ascii,
  BinaryLittleEndian,
  BinaryBigEndian
};

struct Header
{
  Format BodyFormat = Format::Ascii;
  std::vector<Element> Elements;
  std::vector<std::string> Comments; // each comment line's text after "comment "
  std::size_t BodyOffset = 0;        // the first byte after end_header's line
};

/**
 * Parses the header at the start of data (the file's first size bytes).
 * Returns an empty string, or what is wrong with the line number.
 */
std::string ParseHeader(const char* data, std::size_t size, Header& header);

/// Index of the vertex element, or an error if there is none or it lacks
/// scalar x, y and z properties (naming the missing ones).
std::string FindVertexElement(const Header& header, std::size_t& vertex);

/// Index of an edge element whose scalar integer properties vertex1 and
/// vertex2 (their indices in it: first, second) name a segment's two
/// vertices; false if the header has none.
bool FindEdgeElement(const Header& header, std::size_t& edge, int& first, int& second);

/// An output array: its values are written through Data (Count x Components).
struct Column
{
  std::string Name;
  Type ValueType = Type::Float64;
  int Components = 1;
  void* Data = nullptr; // set by the caller before reading
};

/**
 * What each vertex property becomes: x y z the column Points (float when
 * all three are float, else double); nx ny nz (or normal_x ..., normalx
 * ..., n_x ...) Normals, the same way; red green blue, when all uchar, RGB
 * (3 x uchar); the properties an array comment names (consecutive, scalar,
 * of one type) an array of its name, and Normals or RGB renamed by one;
 * any other scalar property a column of its own name and type. List
 * properties are skipped.
 */
struct VertexLayout
{
  std::vector<Column> Columns;
  /// Per vertex property: its column (-1: skipped) and component.
  std::vector<int> ColumnOf;
  std::vector<int> ComponentOf;
  int Points = -1;
  int Normals = -1;
  int Colors = -1;
};
VertexLayout PlanVertexColumns(const Element& vertex,
  const std::vector<std::string>& comments = std::vector<std::string>());

class Body;

/// An open PLY file: Open (InputFile's) reads and checks the header and
/// the vertex element, Read the vertices.
class File final : public InputFile
{
public:
  const Header& GetHeader() const { return this->TheHeader; }
  const Element& Vertices() const { return this->TheHeader.Elements[this->Vertex]; }
  VertexLayout& Layout() { return this->TheLayout; }
  /// Reads vertices [begin, end) into the layout's columns (set their Data
  /// first; row 0 is vertex begin); an empty string, or what went wrong.
  std::string Read(std::uint64_t begin, std::uint64_t end);

  /// The edge element (FindEdgeElement), or null without one.
  const Element* Edges() const;
  /// Reads the edge element: each edge's property values in their order
  /// (a list's length for a list) into rows, one row after the other; an
  /// empty string, or what went wrong (a vertex index out of range too).
  std::string ReadEdges(std::vector<double>& rows);

private:
  std::string ReadHeader(std::uint64_t fileSize) override;
  std::string SkipTo(std::size_t element, Body& body);

  Header TheHeader;
  std::size_t Vertex = 0;
  std::size_t Edge = 0;
  int EdgeFirst = -1;
  int EdgeSecond = -1;
  VertexLayout TheLayout;
};

} // namespace ply
} // namespace pcurv

#endif
