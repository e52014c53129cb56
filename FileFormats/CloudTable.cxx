#include "FileFormats/CloudTable.h"

#include <charconv>
#include <cstring>
#include <set>

namespace pcurv
{
namespace table
{
namespace
{

/// Printable ASCII without white space, commas or quotes, which would
/// split a PLY header word or a CSV cell.
std::string CleanName(const std::string& name, std::size_t index)
{
  std::string clean = name;
  for (char& c : clean)
  {
    const unsigned char u = static_cast<unsigned char>(c);
    if (u <= ' ' || u > '~' || c == ',' || c == '"' || c == '\'')
    {
      c = '_';
    }
  }
  return clean.empty() ? "Array_" + std::to_string(index) : clean;
}

std::string Unique(const std::string& name, std::set<std::string>& used)
{
  std::string unique = name;
  for (int suffix = 2; used.count(unique); ++suffix)
  {
    unique = name + "_" + std::to_string(suffix);
  }
  used.insert(unique);
  return unique;
}

/// The columns' names before they are made clean and unique.
std::vector<std::string> RawColumnNames(const Array& array)
{
  static const char* const points[] = { "x", "y", "z" };
  static const char* const normals[] = { "nx", "ny", "nz" };
  static const char* const colors[] = { "red", "green", "blue", "alpha" };
  std::vector<std::string> names;
  for (int c = 0; c < array.Components; ++c)
  {
    if (array.Kind == Role::Points && array.Components == 3)
      names.emplace_back(points[c]);
    else if (array.Kind == Role::Normals && array.Components == 3)
      names.emplace_back(normals[c]);
    else if (array.Kind == Role::Colors && array.Components <= 4)
      names.emplace_back(colors[c]);
    else if (array.Components == 1)
      names.push_back(array.Name);
    else if (array.Components == 3)
      names.push_back(array.Name + "_" + points[c]);
    else
      names.push_back(array.Name + "_" + std::to_string(c));
  }
  return names;
}

template<typename T>
void AppendNumber(T value, std::string& text)
{
  char buffer[64];
  const std::to_chars_result result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  text.append(buffer, result.ptr);
}

template<typename T>
T At(const void* data, std::uint64_t index)
{
  T value;
  std::memcpy(&value, static_cast<const char*>(data) + index * sizeof(T), sizeof(T));
  return value;
}

} // namespace

//------------------------------------------------------------------------------
void NameColumns(Cloud& cloud)
{
  std::set<std::string> used;
  for (std::size_t a = 0; a < cloud.Arrays.size(); ++a)
  {
    Array& array = cloud.Arrays[a];
    array.ColumnNames.clear();
    for (const std::string& raw : RawColumnNames(array))
    {
      array.ColumnNames.push_back(Unique(CleanName(raw, a), used));
    }
  }
}

//------------------------------------------------------------------------------
bool NeedsArrayComment(const Array& array)
{
  return array.Kind != Role::Points &&
    (array.Components > 1 || array.ColumnNames.empty() || array.ColumnNames[0] != array.Name);
}

//------------------------------------------------------------------------------
void AppendValue(const Array& array, std::uint64_t index, std::string& text)
{
  switch (array.ValueType)
  {
    case Type::Int8:
      return AppendNumber(static_cast<int>(At<std::int8_t>(array.Data, index)), text);
    case Type::UInt8:
      return AppendNumber(static_cast<int>(At<std::uint8_t>(array.Data, index)), text);
    case Type::Int16:
      return AppendNumber(At<std::int16_t>(array.Data, index), text);
    case Type::UInt16:
      return AppendNumber(At<std::uint16_t>(array.Data, index), text);
    case Type::Int32:
      return AppendNumber(At<std::int32_t>(array.Data, index), text);
    case Type::UInt32:
      return AppendNumber(At<std::uint32_t>(array.Data, index), text);
    case Type::Float32:
      return AppendNumber(At<float>(array.Data, index), text);
    case Type::Float64:
      break;
  }
  AppendNumber(At<double>(array.Data, index), text);
}

//------------------------------------------------------------------------------
std::string OneLine(std::string text)
{
  for (char& c : text)
  {
    if (c == '\n' || c == '\r')
    {
      c = ' ';
    }
  }
  return text;
}

} // namespace table
} // namespace pcurv
