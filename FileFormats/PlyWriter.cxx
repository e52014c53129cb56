#include "FileFormats/PlyWriter.h"

#include "FileFormats/FileOutput.h"

#include <algorithm>
#include <cstring>

namespace pcurv
{
namespace ply
{
namespace
{

bool HostIsLittleEndian()
{
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

/// The bytes of value `index` of the array, little endian.
void AppendBinary(const table::Array& array, std::uint64_t index, std::string& out)
{
  const int size = SizeOf(array.ValueType);
  const std::size_t at = out.size();
  out.append(static_cast<const char*>(array.Data) + index * size, size);
  if (!HostIsLittleEndian())
  {
    std::reverse(out.begin() + at, out.end());
  }
}

/// An integer (a list count or a vertex id) as a PLY value of the type.
void AppendInteger(Type type, std::uint64_t value, Format format, std::string& out)
{
  if (format == Format::Ascii)
  {
    out += std::to_string(value);
    return;
  }
  const std::uint8_t small = static_cast<std::uint8_t>(value);
  const std::uint32_t wide = static_cast<std::uint32_t>(value);
  table::Array one;
  one.ValueType = type;
  one.Data = type == Type::UInt8 ? static_cast<const void*>(&small) : &wide;
  AppendBinary(one, 0, out);
}

/// The face element's list count type (uchar when every polygon has at
/// most 255 vertices, as most tools expect) and vertex id type.
void FaceTypes(const table::Cloud& cloud, Type& count, Type& id)
{
  std::uint64_t largest = 0;
  for (std::size_t f = 0; f + 1 < cloud.FaceOffsets.size(); ++f)
  {
    largest = std::max(largest, cloud.FaceOffsets[f + 1] - cloud.FaceOffsets[f]);
  }
  count = largest <= 255 ? Type::UInt8 : Type::UInt32;
  id = cloud.Count <= 2147483647u ? Type::Int32 : Type::UInt32;
}

std::uint64_t FaceCount(const table::Cloud& cloud)
{
  return cloud.FaceOffsets.empty() ? 0 : cloud.FaceOffsets.size() - 1;
}

void AppendRecord(const table::Cloud& cloud, std::uint64_t point, Format format, std::string& out)
{
  bool first = true;
  for (const table::Array& array : cloud.Arrays)
  {
    for (int c = 0; c < array.Components; ++c)
    {
      const std::uint64_t index = point * array.Components + c;
      if (format == Format::Ascii)
      {
        out += first ? "" : " ";
        table::AppendValue(array, index, out);
      }
      else
      {
        AppendBinary(array, index, out);
      }
      first = false;
    }
  }
  out += format == Format::Ascii ? "\n" : "";
}

void AppendFace(const table::Cloud& cloud,
  std::uint64_t face,
  Type countType,
  Type idType,
  Format format,
  std::string& out)
{
  const std::uint64_t begin = cloud.FaceOffsets[face], end = cloud.FaceOffsets[face + 1];
  AppendInteger(countType, end - begin, format, out);
  for (std::uint64_t i = begin; i < end; ++i)
  {
    out += format == Format::Ascii ? " " : "";
    AppendInteger(idType, cloud.FaceIds[i], format, out);
  }
  out += format == Format::Ascii ? "\n" : "";
}

} // namespace

//------------------------------------------------------------------------------
std::string WriterHeader(const table::Cloud& cloud, Format format)
{
  std::string header = "ply\nformat ";
  header += format == Format::Ascii ? "ascii" : "binary_little_endian";
  header += " 1.0\ncomment written by the PrincipalCurvatures plugin (vtkPLYPointCloudWriter)\n";
  for (const auto& field : cloud.Fields)
  {
    header += "comment " + table::OneLine(FormatFieldComment(field.first, field.second)) + "\n";
  }
  for (const table::Array& array : cloud.Arrays)
  {
    if (table::NeedsArrayComment(array))
    {
      const ArrayComment comment{ array.ColumnNames[0], array.Components, array.Name };
      header += "comment " + table::OneLine(FormatArrayComment(comment)) + "\n";
    }
  }
  header += "element vertex " + std::to_string(cloud.Count) + "\n";
  for (const table::Array& array : cloud.Arrays)
  {
    for (const std::string& name : array.ColumnNames)
    {
      header += std::string("property ") + NameOf(array.ValueType) + " " + name + "\n";
    }
  }
  if (FaceCount(cloud) > 0)
  {
    Type countType, idType;
    FaceTypes(cloud, countType, idType);
    header += "element face " + std::to_string(FaceCount(cloud)) + "\nproperty list " +
      NameOf(countType) + " " + NameOf(idType) + " vertex_indices\n";
  }
  return header + "end_header\n";
}

//------------------------------------------------------------------------------
std::string WriteFile(const char* fileName, const table::Cloud& cloud, Format format)
{
  if (format == Format::BinaryBigEndian)
  {
    return "the writer writes binary_little_endian or ascii PLY files";
  }
  OutputFile file;
  std::string error = file.Open(fileName);
  std::string& out = file.Buffer();
  out = WriterHeader(cloud, format);
  for (std::uint64_t point = 0; point < cloud.Count && error.empty(); ++point)
  {
    AppendRecord(cloud, point, format, out);
    error = file.FlushIfFull();
  }
  Type countType, idType;
  FaceTypes(cloud, countType, idType);
  for (std::uint64_t face = 0; face < FaceCount(cloud) && error.empty(); ++face)
  {
    AppendFace(cloud, face, countType, idType, format, out);
    error = file.FlushIfFull();
  }
  return error.empty() ? file.Close() : error;
}

} // namespace ply
} // namespace pcurv
