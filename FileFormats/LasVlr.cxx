#include "FileFormats/LasVlr.h"

#include "FileFormats/LasBytes.h"
#include "FileFormats/PlyComments.h"

#include <sstream>

namespace pcurv
{
namespace las
{
namespace
{

bool ReadAt(std::FILE* stream, std::uint64_t at, unsigned char* out, std::size_t size)
{
  return std::fseek(stream, static_cast<long>(at), SEEK_SET) == 0 &&
    std::fread(out, 1, size, stream) == size;
}

/// Reads one record's header at `at` (extended: the 60-byte EVLR header with
/// a 64-bit length) and, if it is kept, its payload. Returns the byte after
/// the record, or 0 when the record does not fit before `end`.
std::uint64_t ReadRecord(std::FILE* stream,
  std::uint64_t at,
  std::uint64_t end,
  bool extended,
  std::vector<Vlr>& kept)
{
  const std::uint64_t headerSize = extended ? 60 : VlrHeaderSize;
  unsigned char header[60];
  if (at + headerSize > end || !ReadAt(stream, at, header, headerSize))
  {
    return 0;
  }
  Vlr vlr;
  vlr.UserId = TextField(header + 2, 16);
  vlr.RecordId = U16(header + 18);
  const std::uint64_t length = extended ? U64(header + 20) : U16(header + 20);
  vlr.Description = TextField(header + (extended ? 28 : 22), 32);
  const std::uint64_t next = at + headerSize + length;
  if (length > end - at - headerSize)
  {
    return 0;
  }
  if (IsKept(vlr.UserId, vlr.RecordId) && length <= (1u << 24))
  {
    vlr.Data.resize(static_cast<std::size_t>(length));
    if (length > 0 && !ReadAt(stream, at + headerSize, vlr.Data.data(), vlr.Data.size()))
    {
      return 0;
    }
    kept.push_back(std::move(vlr));
  }
  return next;
}

} // namespace

//------------------------------------------------------------------------------
int SizeOf(ValueType type)
{
  static const int sizes[] = { 0, 1, 1, 2, 2, 4, 4, 8, 8, 4, 8 };
  const int code = static_cast<int>(type);
  return code >= 0 && code <= 10 ? sizes[code] : 0;
}

//------------------------------------------------------------------------------
int ExtraBytesDescriptor::Size() const
{
  if (this->DataType == 0)
  {
    return this->Options; // undocumented bytes: options holds their count
  }
  if (this->DataType <= 10)
  {
    return SizeOf(static_cast<ValueType>(this->DataType));
  }
  if (this->DataType <= 30) // deprecated arrays: 11-20 of two values, 21-30 of three
  {
    const int base = (this->DataType - 1) % 10 + 1;
    return SizeOf(static_cast<ValueType>(base)) * (this->DataType <= 20 ? 2 : 3);
  }
  return -1;
}

//------------------------------------------------------------------------------
std::vector<ExtraBytesDescriptor> ParseExtraBytes(const std::vector<unsigned char>& payload)
{
  std::vector<ExtraBytesDescriptor> dimensions;
  for (std::size_t at = 0; at + ExtraBytesDescriptorSize <= payload.size();
       at += ExtraBytesDescriptorSize)
  {
    const unsigned char* d = payload.data() + at;
    ExtraBytesDescriptor dimension;
    dimension.DataType = d[2];
    dimension.Options = d[3];
    dimension.Name = TextField(d + 4, 32);
    dimension.Scale = (dimension.Options & 0x08) ? F64(d + 112) : 1.0;
    dimension.Offset = (dimension.Options & 0x10) ? F64(d + 136) : 0.0;
    dimension.Description = TextField(d + 160, 32);
    dimensions.push_back(dimension);
  }
  return dimensions;
}

//------------------------------------------------------------------------------
std::vector<unsigned char> ExtraBytesPayload(const std::vector<ExtraBytesDescriptor>& dimensions)
{
  // Every field not set below (reserved, unused, no_data, min, max, the
  // deprecated ones) must be zero.
  std::vector<unsigned char> payload(dimensions.size() * ExtraBytesDescriptorSize, 0);
  for (std::size_t i = 0; i < dimensions.size(); ++i)
  {
    const ExtraBytesDescriptor& dimension = dimensions[i];
    unsigned char* d = payload.data() + i * ExtraBytesDescriptorSize;
    d[2] = static_cast<unsigned char>(dimension.DataType);
    d[3] = static_cast<unsigned char>(dimension.Options);
    PutText(d + 4, dimension.Name, 32);
    if (dimension.Options & 0x08)
      Put(d + 112, dimension.Scale);
    if (dimension.Options & 0x10)
      Put(d + 136, dimension.Offset);
    PutText(d + 160, dimension.Description, 32);
  }
  return payload;
}

//------------------------------------------------------------------------------
void AppendVlr(std::vector<unsigned char>& out, const Vlr& vlr)
{
  unsigned char header[VlrHeaderSize] = {};
  PutText(header + 2, vlr.UserId, 16);
  Put(header + 18, vlr.RecordId);
  Put(header + 20, static_cast<std::uint16_t>(vlr.Data.size()));
  PutText(header + 22, vlr.Description, 32);
  out.insert(out.end(), header, header + VlrHeaderSize);
  out.insert(out.end(), vlr.Data.begin(), vlr.Data.end());
}

//------------------------------------------------------------------------------
bool IsKept(const std::string& userId, std::uint16_t recordId)
{
  return userId == "LASF_Projection" || (userId == "LASF_Spec" && recordId == 4) ||
    (userId == FieldDataUserId && recordId == FieldDataRecordId);
}

//------------------------------------------------------------------------------
Vlr FieldDataRecord(const FieldTexts& fields, std::vector<std::string>* left)
{
  Vlr record{ FieldDataUserId, FieldDataRecordId, "Field data (PrincipalCurvatures)", {} };
  for (const auto& field : fields)
  {
    const std::string line = ply::FormatFieldComment(field.first, field.second) + "\n";
    if (record.Data.size() + line.size() <= MaximumVlrPayload)
    {
      record.Data.insert(record.Data.end(), line.begin(), line.end());
    }
    else if (left)
    {
      left->push_back(field.first);
    }
  }
  return record;
}

//------------------------------------------------------------------------------
FieldTexts FieldDataOf(const std::vector<Vlr>& records)
{
  FieldTexts fields;
  for (const Vlr& record : records)
  {
    if (record.UserId != FieldDataUserId || record.RecordId != FieldDataRecordId)
    {
      continue;
    }
    std::istringstream lines(std::string(record.Data.begin(), record.Data.end()));
    std::string line, name, value;
    while (std::getline(lines, line))
    {
      if (ply::ParseFieldComment(line, name, value))
      {
        fields.emplace_back(name, value);
      }
    }
  }
  return fields;
}

//------------------------------------------------------------------------------
std::vector<Vlr> ReadKeptRecords(std::FILE* stream,
  std::uint64_t first,
  std::uint32_t count,
  std::uint64_t pointData,
  std::uint64_t evlrStart,
  std::uint32_t evlrCount,
  std::uint64_t fileSize)
{
  std::vector<Vlr> kept;
  std::uint64_t at = first;
  for (std::uint32_t i = 0; i < count && at != 0; ++i)
  {
    at = ReadRecord(stream, at, pointData, false, kept);
  }
  at = evlrStart >= pointData ? evlrStart : 0;
  for (std::uint32_t i = 0; i < evlrCount && at != 0; ++i)
  {
    at = ReadRecord(stream, at, fileSize, true, kept);
  }
  return kept;
}

} // namespace las
} // namespace pcurv
