#include "FileFormats/LasFile.h"

#include "FileFormats/LasBytes.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <sstream>
#include <vector>

namespace pcurv
{
namespace las
{
namespace
{

/// The smallest header of each minor version (1.0-1.2, 1.3, 1.4).
std::uint32_t RequiredHeaderSize(int minor)
{
  return minor <= 2 ? 227 : (minor == 3 ? 235 : 375);
}

std::string Printable(const unsigned char* p, std::size_t n)
{
  std::string text;
  for (std::size_t i = 0; i < n; ++i)
  {
    text += (p[i] >= 32 && p[i] < 127) ? static_cast<char>(p[i]) : '?';
  }
  return text;
}

std::string CheckSignature(const unsigned char* data,
  std::size_t size,
  std::uint64_t fileSize,
  Header&)
{
  if (size < 4 || std::memcmp(data, "LASF", 4) != 0)
  {
    return "not a LAS file: it starts with '" + Printable(data, size < 4 ? size : 4) +
      "', not the signature 'LASF'";
  }
  if (size < 227)
  {
    return "truncated: the file has " + std::to_string(fileSize) +
      " bytes, less than a LAS header (227)";
  }
  return std::string();
}

/// The version, and a header as large as the version's.
std::string CheckVersion(const unsigned char* data,
  std::size_t size,
  std::uint64_t fileSize,
  Header& header)
{
  header.VersionMajor = data[24];
  header.VersionMinor = data[25];
  if (header.VersionMajor != 1 || header.VersionMinor > 4)
  {
    return "unknown LAS version " + std::to_string(header.VersionMajor) + "." +
      std::to_string(header.VersionMinor) + " (this reader knows 1.0 to 1.4)";
  }
  const std::string version = "LAS 1." + std::to_string(header.VersionMinor);
  header.HeaderSize = U16(data + 94);
  const std::uint32_t required = RequiredHeaderSize(header.VersionMinor);
  if (header.HeaderSize < required)
  {
    return "the header size is " + std::to_string(header.HeaderSize) + " bytes, " + version +
      " needs " + std::to_string(required);
  }
  if (size < header.HeaderSize)
  {
    return "truncated: the file has " + std::to_string(fileSize) + " bytes, less than its " +
      version + " header (" + std::to_string(header.HeaderSize) + ")";
  }
  return std::string();
}

/// The point format (LAZ's compression bits first) and the record length.
std::string CheckRecords(const unsigned char* data, std::size_t, std::uint64_t, Header& header)
{
  const int format = data[104];
  header.RecordLength = U16(data + 105);
  if (format & 0xC0)
  {
    return "the file is LAZ-compressed (point data format " + std::to_string(format & 0x3F) +
      " with the compression bit set), which this reader does not read; decompress it first, "
      "e.g. 'laszip -i in.laz -o out.las' or 'pdal translate in.laz out.las'";
  }
  header.PointFormat = format;
  const RecordLayout layout = LayoutOf(format);
  if (layout.MinimumLength == 0)
  {
    return "unknown point data format " + std::to_string(format) + " (this reader knows 0 to 10)";
  }
  if (header.RecordLength < layout.MinimumLength)
  {
    return "the point data record length is " + std::to_string(header.RecordLength) +
      " bytes, smaller than point data format " + std::to_string(format) + " needs (" +
      std::to_string(layout.MinimumLength) + ")";
  }
  return std::string();
}

std::string CheckOffsets(const unsigned char* data,
  std::size_t,
  std::uint64_t fileSize,
  Header& header)
{
  header.OffsetToPointData = U32(data + 96);
  header.VlrCount = U32(data + 100);
  header.GlobalEncoding = U16(data + 6);
  header.FileSize = fileSize;
  if (header.OffsetToPointData < header.HeaderSize)
  {
    return "the offset to point data (" + std::to_string(header.OffsetToPointData) +
      ") is inside the header (" + std::to_string(header.HeaderSize) + " bytes)";
  }
  if (header.OffsetToPointData > fileSize)
  {
    return "the offset to point data (" + std::to_string(header.OffsetToPointData) +
      ") is beyond the end of the file (" + std::to_string(fileSize) + " bytes)";
  }
  return std::string();
}

std::string CheckScales(const unsigned char* data, std::size_t, std::uint64_t, Header& header)
{
  for (int c = 0; c < 3; ++c)
  {
    header.Scale[c] = F64(data + 131 + 8 * c);
    header.Offset[c] = F64(data + 155 + 8 * c);
    if (!std::isfinite(header.Scale[c]) || header.Scale[c] == 0 || !std::isfinite(header.Offset[c]))
    {
      std::ostringstream text;
      text.precision(17);
      text << "the "
           << "xyz"[c] << " scale (" << header.Scale[c] << ") or offset (" << header.Offset[c]
           << ") is not a finite number, or the scale is 0";
      return text.str();
    }
  }
  return std::string();
}

/// The point count: the legacy 32-bit one, or LAS 1.4's 64-bit one when the
/// legacy one is 0 (as 1.4 writers do for more than 2^32 - 1 points).
std::string PointCountOf(const unsigned char* data, Header& header)
{
  const std::uint32_t legacy = U32(data + 107);
  header.PointCount = legacy;
  if (header.VersionMinor >= 4)
  {
    header.EvlrStart = U64(data + 235);
    header.EvlrCount = U32(data + 243);
    const std::uint64_t full = U64(data + 247);
    if (legacy == 0)
    {
      header.PointCount = full;
    }
    else if (full != 0 && full != legacy)
    {
      return "the legacy point count (" + std::to_string(legacy) +
        ") disagrees with the 64-bit point count (" + std::to_string(full) + ")";
    }
  }
  return std::string();
}

/// Checks the point records' extent against the file's size.
std::string CheckExtent(const unsigned char* data, std::uint64_t fileSize, const Header& header)
{
  const std::uint64_t available = fileSize - header.OffsetToPointData;
  const std::uint64_t fits = available / header.RecordLength;
  if (header.PointCount > fits)
  {
    return "the header declares " + std::to_string(header.PointCount) + " points of " +
      std::to_string(header.RecordLength) + " bytes from byte " +
      std::to_string(header.OffsetToPointData) + ", but the file (" + std::to_string(fileSize) +
      " bytes) holds only " + std::to_string(fits) + " (truncated, or a wrong point count)";
  }
  // Bytes after the points are only allowed where the header says what they
  // are (1.3 waveform data, 1.4 extended variable length records), or when
  // they are less than a record (padding).
  const std::uint64_t end = header.OffsetToPointData + header.PointCount * header.RecordLength;
  std::uint64_t declaredTail = 0;
  if (header.VersionMinor == 3)
  {
    declaredTail = U64(data + 227);
  }
  else if (header.VersionMinor >= 4)
  {
    declaredTail = U32(data + 243) > 0 ? U64(data + 235) : U64(data + 227);
  }

  if (fileSize - end >= header.RecordLength && !(declaredTail >= end && declaredTail < fileSize))
  {
    return "the header declares " + std::to_string(header.PointCount) +
      " points, but the file holds " + std::to_string(fits) + " records of " +
      std::to_string(header.RecordLength) + " bytes after byte " +
      std::to_string(header.OffsetToPointData) + " (a wrong point count)";
  }
  return std::string();
}

/// Formats 0-5: return number in bits 0-2 of byte 14, number of returns in
/// 3-5, scan direction 6, edge of flight line 7; the class in the low 5 bits
/// of byte 15, its synthetic, key-point and withheld flags in bits 5-7.
void DecodeLegacyFields(const unsigned char* r, std::size_t at, const PointBuffers& out)
{
  const unsigned char returns = r[14];
  if (out.ReturnNumber)
    out.ReturnNumber[at] = returns & 0x07;
  if (out.NumberOfReturns)
    out.NumberOfReturns[at] = (returns >> 3) & 0x07;
  if (out.ScanDirectionFlag)
    out.ScanDirectionFlag[at] = (returns >> 6) & 1;
  if (out.EdgeOfFlightLine)
    out.EdgeOfFlightLine[at] = returns >> 7;
  if (out.Classification)
    out.Classification[at] = r[15] & 0x1F;
  if (out.ClassFlags)
    out.ClassFlags[at] = r[15] >> 5;
  if (out.ScanAngleRank)
    out.ScanAngleRank[at] = static_cast<std::int8_t>(r[16]);
  if (out.PointSourceId)
    out.PointSourceId[at] = U16(r + 18);
}

/// Formats 6-10: 4-bit return number and number of returns (byte 14); the
/// class flags in bits 0-3 of byte 15, the scanner channel in 4-5, scan
/// direction 6, edge 7; the class a byte of its own (16).
void DecodeExtendedFields(const unsigned char* r, std::size_t at, const PointBuffers& out)
{
  const unsigned char returns = r[14];
  const unsigned char flags = r[15];
  if (out.ReturnNumber)
    out.ReturnNumber[at] = returns & 0x0F;
  if (out.NumberOfReturns)
    out.NumberOfReturns[at] = returns >> 4;
  if (out.ClassFlags)
    out.ClassFlags[at] = flags & 0x0F;
  if (out.ScannerChannel)
    out.ScannerChannel[at] = (flags >> 4) & 0x03;
  if (out.ScanDirectionFlag)
    out.ScanDirectionFlag[at] = (flags >> 6) & 1;
  if (out.EdgeOfFlightLine)
    out.EdgeOfFlightLine[at] = flags >> 7;
  if (out.Classification)
    out.Classification[at] = r[16];
  if (out.ScanAngle)
    out.ScanAngle[at] = static_cast<float>(static_cast<std::int16_t>(U16(r + 18)) * 0.006);
  if (out.PointSourceId)
    out.PointSourceId[at] = U16(r + 20);
}

template<typename T, typename Bits>
void StoreExtra(Bits bits, std::size_t at, const PointBuffers::Extra& extra)
{
  const T value = FromBits<T>(bits);
  if (extra.Scaled)
    static_cast<double*>(extra.Out)[at * extra.Stride] =
      static_cast<double>(value) * extra.Scale + extra.Offset;
  else
    static_cast<T*>(extra.Out)[at * extra.Stride] = value;
}

/// One extra-bytes value at p into the extra's buffer.
void DecodeExtra(const unsigned char* p, std::size_t at, const PointBuffers::Extra& extra)
{
  switch (extra.Type)
  {
    case ValueType::UInt8:
      return StoreExtra<std::uint8_t>(p[0], at, extra);
    case ValueType::Int8:
      return StoreExtra<std::int8_t>(p[0], at, extra);
    case ValueType::UInt16:
      return StoreExtra<std::uint16_t>(U16(p), at, extra);
    case ValueType::Int16:
      return StoreExtra<std::int16_t>(U16(p), at, extra);
    case ValueType::UInt32:
      return StoreExtra<std::uint32_t>(U32(p), at, extra);
    case ValueType::Int32:
      return StoreExtra<std::int32_t>(U32(p), at, extra);
    case ValueType::UInt64:
      return StoreExtra<std::uint64_t>(U64(p), at, extra);
    case ValueType::Int64:
      return StoreExtra<std::int64_t>(U64(p), at, extra);
    case ValueType::Float32:
      return StoreExtra<float>(U32(p), at, extra);
    case ValueType::Float64:
      return StoreExtra<double>(U64(p), at, extra);
    default:
      return;
  }
}

} // namespace

//------------------------------------------------------------------------------
RecordLayout LayoutOf(int pointFormat)
{
  RecordLayout layout;
  switch (pointFormat)
  {
    case 0:
      layout.MinimumLength = 20;
      break;
    case 1:
      layout = { 28, false, 20, -1, -1 };
      break;
    case 2:
      layout = { 26, false, -1, 20, -1 };
      break;
    case 3:
      layout = { 34, false, 20, 28, -1 };
      break;
    case 4: // format 1 and a wave packet
      layout = { 57, false, 20, -1, -1 };
      break;
    case 5: // format 3 and a wave packet
      layout = { 63, false, 20, 28, -1 };
      break;
    case 6:
      layout = { 30, true, 22, -1, -1 };
      break;
    case 7:
      layout = { 36, true, 22, 30, -1 };
      break;
    case 8:
      layout = { 38, true, 22, 30, 36 };
      break;
    case 9: // format 6 and a wave packet
      layout = { 59, true, 22, -1, -1 };
      break;
    case 10: // format 8 and a wave packet
      layout = { 67, true, 22, 30, 36 };
      break;
    default:
      break;
  }
  return layout;
}

//------------------------------------------------------------------------------
void DecodeRecords(const Header& header,
  const unsigned char* records,
  std::size_t count,
  std::size_t first,
  const PointBuffers& out)
{
  const RecordLayout layout = LayoutOf(header.PointFormat);
  for (std::size_t i = 0; i < count; ++i)
  {
    const unsigned char* r = records + i * header.RecordLength;
    const std::size_t at = first + i;
    if (out.Points)
    {
      for (int c = 0; c < 3; ++c)
      {
        out.Points[3 * at + c] = I32(r + 4 * c) * header.Scale[c] + header.Offset[c];
      }
    }
    if (out.Intensity)
      out.Intensity[at] = U16(r + 12);
    if (layout.Extended)
      DecodeExtendedFields(r, at, out);
    else
      DecodeLegacyFields(r, at, out);
    if (out.UserData)
      out.UserData[at] = r[17];
    if (layout.GpsTime >= 0 && out.GpsTime)
      out.GpsTime[at] = F64(r + layout.GpsTime);
    if (layout.Color >= 0)
    {
      if (out.Red)
        out.Red[at] = U16(r + layout.Color);
      if (out.Green)
        out.Green[at] = U16(r + layout.Color + 2);
      if (out.Blue)
        out.Blue[at] = U16(r + layout.Color + 4);
    }
    if (layout.Infrared >= 0 && out.Infrared)
      out.Infrared[at] = U16(r + layout.Infrared);
    for (const PointBuffers::Extra& extra : out.Extras)
    {
      DecodeExtra(r + extra.ByteOffset, at, extra);
    }
  }
}

//------------------------------------------------------------------------------
std::vector<ExtraField> ExtraFieldsOf(const Header& header, const std::vector<Vlr>& records)
{
  std::vector<ExtraField> fields;
  for (const Vlr& record : records)
  {
    if (record.UserId != "LASF_Spec" || record.RecordId != 4)
      continue;
    std::uint32_t at = LayoutOf(header.PointFormat).MinimumLength;
    fields.clear();
    for (const ExtraBytesDescriptor& d : ParseExtraBytes(record.Data))
    {
      const int size = d.Size();
      if (size < 0 || at + static_cast<std::uint32_t>(size) > header.RecordLength)
        return std::vector<ExtraField>();
      if (d.DataType >= 1 && d.DataType <= 10)
        fields.push_back(
          { d.Name, static_cast<ValueType>(d.DataType), at, d.Scaled(), d.Scale, d.Offset });
      at += static_cast<std::uint32_t>(size);
    }
  }
  return fields;
}

//------------------------------------------------------------------------------
std::string ParseHeader(const unsigned char* data,
  std::size_t size,
  std::uint64_t fileSize,
  Header& header)
{
  // Each check reads only fields the earlier ones have shown to be there.
  for (auto check : { CheckSignature, CheckVersion, CheckRecords, CheckOffsets, CheckScales })
  {
    const std::string error = check(data, size, fileSize, header);
    if (!error.empty())
    {
      return error;
    }
  }
  std::string error = PointCountOf(data, header);
  return error.empty() ? CheckExtent(data, fileSize, header) : error;
}

//------------------------------------------------------------------------------
std::string File::ReadHeader(std::uint64_t fileSize)
{
  unsigned char data[375] = {};
  const std::size_t got = std::fread(data, 1, sizeof data, this->Stream());
  return ParseHeader(data, got, fileSize, this->TheHeader);
}

//------------------------------------------------------------------------------
std::vector<Vlr> File::ReadKeptRecords()
{
  const Header& h = this->TheHeader;
  return las::ReadKeptRecords(this->Stream(),
    h.HeaderSize,
    h.VlrCount,
    h.OffsetToPointData,
    h.EvlrStart,
    h.EvlrCount,
    h.FileSize);
}

//------------------------------------------------------------------------------
std::string File::Read(std::uint64_t begin, std::uint64_t end, const PointBuffers& out)
{
  const Header& header = this->TheHeader;
  // About 4 MB of records at a time whatever the file's size, and no more
  // than are asked for: a record may be up to 64 kB long.
  constexpr std::uint64_t chunkBytes = 1 << 22;
  const std::uint64_t chunk = std::max<std::uint64_t>(
    1, std::min<std::uint64_t>(end > begin ? end - begin : 1, chunkBytes / header.RecordLength));
  std::vector<unsigned char> buffer(chunk * header.RecordLength);
  const std::uint64_t start = header.OffsetToPointData + begin * header.RecordLength;
  if (std::fseek(this->Stream(), static_cast<long>(start), SEEK_SET) != 0)
  {
    return std::string("cannot seek to the points: ") + std::strerror(errno);
  }
  for (std::uint64_t first = begin; first < end; first += chunk)
  {
    const std::size_t count = static_cast<std::size_t>(std::min(chunk, end - first));
    const std::size_t got = std::fread(buffer.data(), header.RecordLength, count, this->Stream());
    if (got != count)
    {
      return "the file ends in point " + std::to_string(first + got) + " of " +
        std::to_string(header.PointCount) + " (truncated)";
    }
    DecodeRecords(header, buffer.data(), count, static_cast<std::size_t>(first - begin), out);
  }
  return std::string();
}

} // namespace las
} // namespace pcurv
