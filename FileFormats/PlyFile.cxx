#include "FileFormats/PlyFile.h"

#include "FileFormats/PlyBody.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <sstream>

namespace pcurv
{
namespace ply
{
namespace
{

bool TypeOf(const std::string& name, Type& type)
{
  static const std::pair<const char*, Type> names[] = { { "char", Type::Int8 },
    { "int8", Type::Int8 },
    { "uchar", Type::UInt8 },
    { "uint8", Type::UInt8 },
    { "short", Type::Int16 },
    { "int16", Type::Int16 },
    { "ushort", Type::UInt16 },
    { "uint16", Type::UInt16 },
    { "int", Type::Int32 },
    { "int32", Type::Int32 },
    { "uint", Type::UInt32 },
    { "uint32", Type::UInt32 },
    { "float", Type::Float32 },
    { "float32", Type::Float32 },
    { "double", Type::Float64 },
    { "float64", Type::Float64 } };
  for (const auto& entry : names)
  {
    if (name == entry.first)
    {
      type = entry.second;
      return true;
    }
  }
  return false;
}

/// "property <type> <name>" or "property list <count type> <type> <name>".
std::string ParseProperty(const std::vector<std::string>& words, Property& property)
{
  const bool list = words.size() >= 2 && words[1] == "list";
  if (words.size() != (list ? 5u : 3u))
  {
    return "a property line needs 'property <type> <name>' or 'property list <count type> "
           "<type> <name>'";
  }
  property.IsList = list;
  property.Name = words.back();
  const std::string& valueType = words[list ? 3 : 1];
  if (!TypeOf(valueType, property.ValueType))
  {
    return "unknown property type '" + valueType + "' of property '" + property.Name + "'";
  }
  if (list &&
    (!TypeOf(words[2], property.CountType) || property.CountType == Type::Float32 ||
      property.CountType == Type::Float64))
  {
    return "unknown list count type '" + words[2] + "' of property '" + property.Name + "'";
  }
  return std::string();
}

/// One header line (its words); sets done at end_header.
std::string ParseLine(const std::vector<std::string>& words, Header& header, bool& done)
{
  const std::string& keyword = words[0];
  if (keyword == "comment" || keyword == "obj_info")
  {
    return std::string();
  }
  if (keyword == "end_header")
  {
    done = true;
    return std::string();
  }
  if (keyword == "format")
  {
    const std::string name = words.size() > 1 ? words[1] : std::string();
    if (name == "ascii")
      header.BodyFormat = Format::Ascii;
    else if (name == "binary_little_endian")
      header.BodyFormat = Format::BinaryLittleEndian;
    else if (name == "binary_big_endian")
      header.BodyFormat = Format::BinaryBigEndian;
    else
      return "unknown format '" + name + "' (ascii, binary_little_endian or binary_big_endian)";
    return std::string();
  }
  if (keyword == "element")
  {
    Element element;
    const char* count = words.size() == 3 ? words[2].c_str() : "";
    const char* end = count + std::strlen(count);
    if (words.size() != 3 || std::from_chars(count, end, element.Count).ptr != end || !*count)
    {
      return "an element line needs 'element <name> <count>'";
    }
    element.Name = words[1];
    header.Elements.push_back(element);
    return std::string();
  }
  if (keyword == "property")
  {
    if (header.Elements.empty())
    {
      return "a property before any element";
    }
    Property property;
    std::string error = ParseProperty(words, property);
    header.Elements.back().Properties.push_back(property);
    return error;
  }
  return "unknown header line '" + keyword + "' (is end_header missing?)";
}

/// A comment line's text after the keyword and its space, without the
/// line end.
std::string CommentText(const std::string& line)
{
  std::size_t begin = line.find("comment") + 7;
  begin += begin < line.size() && (line[begin] == ' ' || line[begin] == '\t') ? 1 : 0;
  std::size_t end = line.size();
  while (end > begin && (line[end - 1] == '\r' || line[end - 1] == '\n'))
  {
    --end;
  }
  return line.substr(begin, end - begin);
}

int FindProperty(const Element& element, const char* name)
{
  for (std::size_t i = 0; i < element.Properties.size(); ++i)
  {
    const Property& p = element.Properties[i];
    if (!p.IsList && LowerCase(p.Name) == name)
    {
      return static_cast<int>(i);
    }
  }
  return -1;
}

/// A property that can hold a vertex index: an integer type.
bool IsIntegerIndex(const Property& property)
{
  return property.ValueType != Type::Float32 && property.ValueType != Type::Float64;
}

/// Makes properties `names` the components of a new column, when all are
/// there (and of the type `only` if given). Returns the column or -1.
int Group(const Element& vertex,
  std::initializer_list<const char*> names,
  const char* columnName,
  const Type* only,
  VertexLayout& layout)
{
  std::vector<int> found;
  bool allFloat = true;
  for (const char* name : names)
  {
    const int at = FindProperty(vertex, name);
    if (at < 0 || layout.ColumnOf[at] >= 0 || (only && vertex.Properties[at].ValueType != *only))
    {
      return -1;
    }
    allFloat = allFloat && vertex.Properties[at].ValueType == Type::Float32;
    found.push_back(at);
  }
  Column column;
  column.Name = columnName;
  column.Components = static_cast<int>(found.size());
  column.ValueType = only ? *only : (allFloat ? Type::Float32 : Type::Float64);
  const int index = static_cast<int>(layout.Columns.size());
  layout.Columns.push_back(column);
  for (std::size_t c = 0; c < found.size(); ++c)
  {
    layout.ColumnOf[found[c]] = index;
    layout.ComponentOf[found[c]] = static_cast<int>(c);
  }
  return index;
}

/// A name no column of the layout has yet: name, else name_<index>.
std::string UniqueColumnName(const VertexLayout& layout, const std::string& name, std::size_t index)
{
  for (const Column& other : layout.Columns)
  {
    if (other.Name == name)
    {
      return name + "_" + std::to_string(index); // a property named Normals, RGB, ...
    }
  }
  return name;
}

/// Whether properties [first, first + count) are scalars of one type that
/// no column holds yet.
bool FreeRun(const Element& vertex, const VertexLayout& layout, std::size_t first, int count)
{
  if (count < 1 || first + count > vertex.Properties.size())
  {
    return false;
  }
  for (std::size_t p = first; p < first + count; ++p)
  {
    const Property& property = vertex.Properties[p];
    if (property.IsList || layout.ColumnOf[p] >= 0 ||
      property.ValueType != vertex.Properties[first].ValueType)
    {
      return false;
    }
  }
  return true;
}

/// What one array comment makes of the vertex properties: a new column of
/// the properties it names, or Normals or RGB under the array's own name.
/// A comment that does not fit the properties (edited by another tool) is
/// left out.
void ApplyArrayComment(const Element& vertex, const ArrayComment& comment, VertexLayout& layout)
{
  std::size_t first = 0;
  while (first < vertex.Properties.size() && vertex.Properties[first].Name != comment.FirstProperty)
  {
    ++first;
  }
  if (first == vertex.Properties.size())
  {
    return;
  }
  const int existing = layout.ColumnOf[first];
  if (existing >= 0)
  {
    Column& column = layout.Columns[existing];
    if (existing != layout.Points && layout.ComponentOf[first] == 0 &&
      column.Components == comment.Components)
    {
      column.Name = comment.Name;
    }
    return;
  }
  if (!FreeRun(vertex, layout, first, comment.Components))
  {
    return;
  }
  Column column;
  column.Name = UniqueColumnName(layout, comment.Name, first);
  column.Components = comment.Components;
  column.ValueType = vertex.Properties[first].ValueType;
  const int index = static_cast<int>(layout.Columns.size());
  layout.Columns.push_back(column);
  for (int c = 0; c < comment.Components; ++c)
  {
    layout.ColumnOf[first + c] = index;
    layout.ComponentOf[first + c] = c;
  }
}

/// The fewest bytes a record of element can take: its binary size without
/// list items, or in ascii one character and a separator per value.
double SmallestRecord(const Element& element, Format format)
{
  double bytes = 0;
  for (const Property& property : element.Properties)
  {
    bytes += format == Format::Ascii
      ? 2
      : SizeOf(property.IsList ? property.CountType : property.ValueType);
  }
  return bytes;
}

/// A header that declares more records than the body can hold (checked
/// before anything is allocated for them).
std::string CheckBodySize(const Header& header, std::size_t vertex, std::uint64_t fileSize)
{
  double needed = 0;
  for (std::size_t e = 0; e <= vertex; ++e)
  {
    needed += static_cast<double>(header.Elements[e].Count) *
      SmallestRecord(header.Elements[e], header.BodyFormat);
  }
  // The last ascii value needs no separator.
  const double body =
    static_cast<double>(fileSize - std::min<std::uint64_t>(fileSize, header.BodyOffset));
  if (needed - (header.BodyFormat == Format::Ascii ? 1 : 0) > body)
  {
    const Element& element = header.Elements[vertex];
    return "the header declares " + std::to_string(element.Count) + " vertices (" +
      std::to_string(static_cast<unsigned long long>(SmallestRecord(element, header.BodyFormat))) +
      " bytes each at least), but the data after the header has only " +
      std::to_string(fileSize - std::min<std::uint64_t>(fileSize, header.BodyOffset)) +
      " bytes (truncated, or a wrong count)";
  }
  return std::string();
}

} // namespace

//------------------------------------------------------------------------------
const char* NameOf(Type type)
{
  static const char* names[] = {
    "char", "uchar", "short", "ushort", "int", "uint", "float", "double"
  };
  return names[static_cast<int>(type)];
}

//------------------------------------------------------------------------------
int SizeOf(Type type)
{
  static const int sizes[] = { 1, 1, 2, 2, 4, 4, 4, 8 };
  return sizes[static_cast<int>(type)];
}

//------------------------------------------------------------------------------
std::string ParseHeader(const char* data, std::size_t size, Header& header)
{
  std::size_t position = 0, lineNumber = 0;
  bool done = false;
  while (!done)
  {
    const char* start = data + position;
    // (memchr wants a buffer even for no bytes: an empty file has none.)
    const void* newline = position < size ? std::memchr(start, '\n', size - position) : nullptr;
    if (!newline)
    {
      return lineNumber == 0 ? "not a PLY file (it does not start with a line 'ply')"
                             : "the header has no end_header line";
    }
    const std::size_t length = static_cast<const char*>(newline) - start;
    const std::string text(start, length);
    std::istringstream line(text);
    position += length + 1;
    ++lineNumber;
    std::vector<std::string> words;
    for (std::string word; line >> word;)
    {
      words.push_back(word);
    }
    if (lineNumber == 1)
    {
      if (words.size() != 1 || words[0] != "ply")
      {
        return "not a PLY file (it does not start with a line 'ply')";
      }
      continue;
    }
    if (lineNumber == 2 && (words.empty() || words[0] != "format"))
    {
      return "header line 2: the format line must follow 'ply'";
    }
    if (!words.empty() && words[0] == "comment")
    {
      header.Comments.push_back(CommentText(text));
    }
    const std::string error = words.empty() ? std::string() : ParseLine(words, header, done);
    if (!error.empty())
    {
      return "header line " + std::to_string(lineNumber) + ": " + error;
    }
  }
  header.BodyOffset = position;
  return std::string();
}

//------------------------------------------------------------------------------
std::string FindVertexElement(const Header& header, std::size_t& vertex)
{
  std::string names;
  for (vertex = 0; vertex < header.Elements.size(); ++vertex)
  {
    if (header.Elements[vertex].Name == "vertex")
    {
      break;
    }
    names += (names.empty() ? "" : " ") + header.Elements[vertex].Name;
  }
  if (vertex == header.Elements.size())
  {
    return "no vertex element (elements: " + (names.empty() ? std::string("none") : names) +
      "), so no points";
  }
  const Element& element = header.Elements[vertex];
  std::string missing, have;
  for (const char* axis : { "x", "y", "z" })
  {
    if (FindProperty(element, axis) < 0)
    {
      missing += missing.empty() ? axis : std::string(", ") + axis;
    }
  }
  if (missing.empty())
  {
    return std::string();
  }
  for (const Property& property : element.Properties)
  {
    have += (have.empty() ? "" : " ") + property.Name;
  }
  return "the vertex element has no " + missing + " propert" + (missing.size() > 1 ? "ies" : "y") +
    " (it has: " + (have.empty() ? "none" : have) + "), so no points";
}

//------------------------------------------------------------------------------
VertexLayout PlanVertexColumns(const Element& vertex, const std::vector<std::string>& comments)
{
  VertexLayout layout;
  layout.ColumnOf.assign(vertex.Properties.size(), -1);
  layout.ComponentOf.assign(vertex.Properties.size(), 0);
  layout.Points = Group(vertex, { "x", "y", "z" }, "Points", nullptr, layout);
  for (auto names : { std::initializer_list<const char*>{ "nx", "ny", "nz" },
         std::initializer_list<const char*>{ "normal_x", "normal_y", "normal_z" },
         std::initializer_list<const char*>{ "normalx", "normaly", "normalz" },
         std::initializer_list<const char*>{ "n_x", "n_y", "n_z" } })
  {
    if (layout.Normals < 0)
    {
      layout.Normals = Group(vertex, names, "Normals", nullptr, layout);
    }
  }
  const Type byte = Type::UInt8;
  layout.Colors = Group(vertex, { "red", "green", "blue" }, "RGB", &byte, layout);
  for (const std::string& text : comments)
  {
    ArrayComment comment;
    if (ParseArrayComment(text, comment))
    {
      ApplyArrayComment(vertex, comment, layout);
    }
  }
  for (std::size_t i = 0; i < vertex.Properties.size(); ++i)
  {
    const Property& property = vertex.Properties[i];
    if (property.IsList || layout.ColumnOf[i] >= 0)
    {
      continue;
    }
    Column column;
    column.Name = UniqueColumnName(layout, property.Name, i);
    column.ValueType = property.ValueType;
    layout.ColumnOf[i] = static_cast<int>(layout.Columns.size());
    layout.Columns.push_back(column);
  }
  return layout;
}

//------------------------------------------------------------------------------
std::string File::ReadHeader(std::uint64_t fileSize)
{
  // The header is text before the body; a megabyte holds any real one.
  std::vector<char> start(std::min<std::size_t>(static_cast<std::size_t>(fileSize), 1 << 20));
  start.resize(std::fread(start.data(), 1, start.size(), this->Stream()));
  std::string error = ParseHeader(start.data(), start.size(), this->TheHeader);
  if (error.empty())
  {
    error = FindVertexElement(this->TheHeader, this->Vertex);
  }
  if (error.empty())
  {
    error = CheckBodySize(this->TheHeader, this->Vertex, fileSize);
  }
  if (error.empty())
  {
    this->TheLayout = PlanVertexColumns(this->Vertices(), this->TheHeader.Comments);
    if (!FindEdgeElement(this->TheHeader, this->Edge, this->EdgeFirst, this->EdgeSecond))
    {
      this->EdgeFirst = this->EdgeSecond = -1;
    }
  }
  return error;
}

//------------------------------------------------------------------------------
bool FindEdgeElement(const Header& header, std::size_t& edge, int& first, int& second)
{
  for (edge = 0; edge < header.Elements.size(); ++edge)
  {
    const Element& element = header.Elements[edge];
    first = FindProperty(element, "vertex1");
    second = FindProperty(element, "vertex2");
    if (element.Name == "edge" && first >= 0 && second >= 0 &&
      IsIntegerIndex(element.Properties[first]) && IsIntegerIndex(element.Properties[second]))
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
std::string File::SkipTo(std::size_t element, Body& body)
{
  if (std::fseek(this->Stream(), static_cast<long>(this->TheHeader.BodyOffset), SEEK_SET) != 0)
  {
    return std::string("cannot seek to the data: ") + std::strerror(errno);
  }
  for (std::size_t e = 0; e < element; ++e)
  {
    std::string error = body.SkipElement(this->TheHeader.Elements[e]);
    if (!error.empty())
    {
      return error;
    }
  }
  return std::string();
}

//------------------------------------------------------------------------------
std::string File::Read(std::uint64_t begin, std::uint64_t end)
{
  Body body(this->Stream(), this->TheHeader.BodyFormat);
  const std::string error = this->SkipTo(this->Vertex, body);
  return error.empty() ? body.ReadVertices(this->Vertices(), this->TheLayout, begin, end) : error;
}

//------------------------------------------------------------------------------
const Element* File::Edges() const
{
  return this->EdgeFirst >= 0 ? &this->TheHeader.Elements[this->Edge] : nullptr;
}

//------------------------------------------------------------------------------
std::string File::ReadEdges(std::vector<double>& rows)
{
  const Element* edges = this->Edges();
  if (!edges)
  {
    rows.clear();
    return std::string();
  }
  Body body(this->Stream(), this->TheHeader.BodyFormat);
  std::string error = this->SkipTo(this->Edge, body);
  if (error.empty())
  {
    error = body.ReadRows(*edges, rows);
  }
  const std::size_t width = edges->Properties.size();
  const auto vertices = static_cast<double>(this->Vertices().Count);
  for (std::size_t row = 0; error.empty() && row < rows.size() / width; ++row)
  {
    for (int end : { this->EdgeFirst, this->EdgeSecond })
    {
      const double index = rows[row * width + end];
      if (error.empty() && !(index >= 0 && index < vertices))
      {
        error = "edge " + std::to_string(row) + ": vertex " +
          std::to_string(static_cast<long long>(index)) + " is not one of the " +
          std::to_string(this->Vertices().Count) + " vertices";
      }
    }
  }
  return error;
}

} // namespace ply
} // namespace pcurv
