#include "FileFormats/PlyBody.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <utility>

namespace pcurv
{
namespace ply
{
namespace
{

bool IsSpace(char c)
{
  return c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\v' || c == '\f';
}

template<typename T>
double Decode(const char* p, bool swap)
{
  char bytes[sizeof(T)];
  std::memcpy(bytes, p, sizeof(T));
  if (swap)
  {
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i)
    {
      std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
    }
  }
  T value;
  std::memcpy(&value, bytes, sizeof(T));
  return static_cast<double>(value);
}

/// The range of an integer type, to check ascii values against.
bool InRange(Type type, double value)
{
  static const double limits[][2] = { { -128, 127 },
    { 0, 255 },
    { -32768, 32767 },
    { 0, 65535 },
    { -2147483648.0, 2147483647.0 },
    { 0, 4294967295.0 } };
  const double* range = limits[static_cast<int>(type)];
  return value >= range[0] && value <= range[1] && value == std::floor(value);
}

/// The value of type at p, in the file's byte order.
double DecodeBinary(const char* p, Type type, bool swap)
{
  switch (type)
  {
    case Type::Int8:
      return static_cast<std::int8_t>(*p);
    case Type::UInt8:
      return static_cast<std::uint8_t>(*p);
    case Type::Int16:
      return Decode<std::int16_t>(p, swap);
    case Type::UInt16:
      return Decode<std::uint16_t>(p, swap);
    case Type::Int32:
      return Decode<std::int32_t>(p, swap);
    case Type::UInt32:
      return Decode<std::uint32_t>(p, swap);
    case Type::Float32:
      return Decode<float>(p, swap);
    case Type::Float64:
      break;
  }
  return Decode<double>(p, swap);
}

/// The ascii word as a value of type; false if it is not one.
bool ParseWord(const char* word, std::size_t length, Type type, double& value)
{
  std::from_chars_result result;
  if (type == Type::Float32)
  {
    float single = 0; // parsed as float: the nearest float, as the writer meant
    result = std::from_chars(word, word + length, single);
    value = single;
  }
  else
  {
    result = std::from_chars(word, word + length, value);
  }
  const bool integer = type != Type::Float32 && type != Type::Float64;
  return result.ptr == word + length && result.ec == std::errc() &&
    (!integer || InRange(type, value));
}

template<typename T>
void Put(void* data, std::size_t at, double value)
{
  static_cast<T*>(data)[at] = static_cast<T>(value);
}

} // namespace

//------------------------------------------------------------------------------
void Store(const Column& column, std::size_t row, int component, double value)
{
  const std::size_t at = row * column.Components + component;
  switch (column.ValueType)
  {
    case Type::Int8:
      return Put<std::int8_t>(column.Data, at, value);
    case Type::UInt8:
      return Put<std::uint8_t>(column.Data, at, value);
    case Type::Int16:
      return Put<std::int16_t>(column.Data, at, value);
    case Type::UInt16:
      return Put<std::uint16_t>(column.Data, at, value);
    case Type::Int32:
      return Put<std::int32_t>(column.Data, at, value);
    case Type::UInt32:
      return Put<std::uint32_t>(column.Data, at, value);
    case Type::Float32:
      return Put<float>(column.Data, at, value);
    case Type::Float64:
      return Put<double>(column.Data, at, value);
  }
}

//------------------------------------------------------------------------------
Body::Body(std::FILE* file, Format format)
  : Handle(file)
  , BodyFormat(format)
  , Buffer(1 << 16)
{
}

//------------------------------------------------------------------------------
bool Body::Ensure(std::size_t n)
{
  if (this->End - this->Position >= n)
  {
    return true;
  }
  std::memmove(
    this->Buffer.data(), this->Buffer.data() + this->Position, this->End - this->Position);
  this->End -= this->Position;
  this->Position = 0;
  if (this->Buffer.size() < n)
  {
    this->Buffer.resize(n);
  }
  this->End +=
    std::fread(this->Buffer.data() + this->End, 1, this->Buffer.size() - this->End, this->Handle);
  return this->End >= n;
}

//------------------------------------------------------------------------------
bool Body::NextBinary(Type type, double& value)
{
  const std::size_t size = SizeOf(type);
  if (!this->Ensure(size))
  {
    return false;
  }
  value = DecodeBinary(
    this->Buffer.data() + this->Position, type, this->BodyFormat == Format::BinaryBigEndian);
  this->Position += size;
  return true;
}

//------------------------------------------------------------------------------
bool Body::NextText(Type type, double& value)
{
  // Skip white space, then take the word (refilling as it may run past the
  // buffer's end).
  for (;;)
  {
    while (this->Position < this->End && IsSpace(this->Buffer[this->Position]))
    {
      ++this->Position;
    }
    if (this->Position < this->End || !this->Ensure(1))
    {
      break;
    }
  }
  std::size_t length = 0;
  while (this->Ensure(length + 1) && !IsSpace(this->Buffer[this->Position + length]))
  {
    if (++length > 4096)
    {
      this->Problem = "a word of more than 4096 characters";
      return false;
    }
  }
  if (length == 0)
  {
    return false;
  }
  const char* word = this->Buffer.data() + this->Position;
  this->Position += length;
  if (!ParseWord(word, length, type, value))
  {
    this->Problem = "'" + std::string(word, std::min<std::size_t>(length, 40)) + "' is not a" +
      (type == Type::Int32 ? "n " : " ") + NameOf(type) + " value";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool Body::NextValue(Type type, double& value)
{
  return this->BodyFormat == Format::Ascii ? this->NextText(type, value)
                                           : this->NextBinary(type, value);
}

//------------------------------------------------------------------------------
bool Body::Record(const Element& element, double* row)
{
  double value;
  for (std::size_t p = 0; p < element.Properties.size(); ++p)
  {
    const Property& property = element.Properties[p];
    if (!this->NextValue(property.IsList ? property.CountType : property.ValueType, value))
    {
      return false;
    }
    if (row)
    {
      row[p] = value;
    }
    if (property.IsList && value < 0)
    {
      this->Problem = "a list of negative length (" + std::to_string(value) + ")";
      return false;
    }
    if (property.IsList)
    {
      for (double n = value; n > 0; --n)
      {
        double item;
        if (!this->NextValue(property.ValueType, item))
        {
          return false;
        }
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
std::string Body::Failure(const Element& element, std::uint64_t record) const
{
  if (!this->Problem.empty())
  {
    return "element " + element.Name + " " + std::to_string(record) + ": " + this->Problem;
  }
  return "the file ends in element " + element.Name + " " + std::to_string(record) + " of " +
    std::to_string(element.Count) + " (truncated)";
}

//------------------------------------------------------------------------------
std::string Body::SkipElement(const Element& element)
{
  for (std::uint64_t record = 0; record < element.Count; ++record)
  {
    if (!this->Record(element, nullptr))
    {
      return this->Failure(element, record);
    }
  }
  return std::string();
}

//------------------------------------------------------------------------------
std::string Body::ReadVertices(const Element& vertex,
  const VertexLayout& layout,
  std::uint64_t begin,
  std::uint64_t end)
{
  std::vector<double> row(vertex.Properties.size());
  for (std::uint64_t record = 0; record < end; ++record)
  {
    if (!this->Record(vertex, row.data()))
    {
      return this->Failure(vertex, record);
    }
    if (record < begin)
    {
      continue;
    }
    for (std::size_t p = 0; p < row.size(); ++p)
    {
      const int column = layout.ColumnOf[p];
      if (column >= 0)
      {
        Store(layout.Columns[column], record - begin, layout.ComponentOf[p], row[p]);
      }
    }
  }
  return std::string();
}

//------------------------------------------------------------------------------
std::string Body::ReadRows(const Element& element, std::vector<double>& rows)
{
  const std::size_t width = element.Properties.size();
  rows.assign(static_cast<std::size_t>(element.Count) * width, 0.0);
  for (std::uint64_t record = 0; record < element.Count; ++record)
  {
    if (!this->Record(element, rows.data() + record * width))
    {
      return this->Failure(element, record);
    }
  }
  return std::string();
}

} // namespace ply
} // namespace pcurv
