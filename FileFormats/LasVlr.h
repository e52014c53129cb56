/**
 * LAS variable length records (VLRs and 1.4's extended ones) and the Extra
 * Bytes record (user id LASF_Spec, record id 4) that names and types the
 * bytes a point record has beyond its format's fields (ASPRS LAS 1.4 R15,
 * "Extra Bytes"). No VTK here.
 */
#ifndef pcurv_LasVlr_h
#define pcurv_LasVlr_h

#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace pcurv
{
namespace las
{

/// The value types of extra bytes; the numbers are the specification's
/// data_type codes.
enum class ValueType : int
{
  Undocumented = 0,
  UInt8 = 1,
  Int8 = 2,
  UInt16 = 3,
  Int16 = 4,
  UInt32 = 5,
  Int32 = 6,
  UInt64 = 7,
  Int64 = 8,
  Float32 = 9,
  Float64 = 10
};

/// Bytes of one value of the type (0 for Undocumented).
int SizeOf(ValueType type);

/// One record: a VLR's or an EVLR's identification and its payload.
struct Vlr
{
  std::string UserId;
  std::uint16_t RecordId = 0;
  std::string Description;
  std::vector<unsigned char> Data;
};

constexpr std::uint32_t VlrHeaderSize = 54;
constexpr std::uint32_t ExtraBytesDescriptorSize = 192;
constexpr std::size_t MaximumVlrPayload = 65535;

/// One descriptor of the Extra Bytes record.
struct ExtraBytesDescriptor
{
  int DataType = 0; // ValueType's codes; 11-30: the deprecated 2- and 3-value arrays
  int Options = 0;  // bit 0 no_data, 1 min, 2 max, 3 scale, 4 offset
  std::string Name;
  std::string Description;
  double Scale = 1;
  double Offset = 0;

  /// Bytes the dimension takes in each record.
  int Size() const;
  /// Whether the values are to be multiplied by Scale or moved by Offset.
  bool Scaled() const { return (this->Options & 0x18) != 0; }
};

/// The descriptors of an Extra Bytes record's payload (192 bytes each).
std::vector<ExtraBytesDescriptor> ParseExtraBytes(const std::vector<unsigned char>& payload);

/// The payload of an Extra Bytes record describing the dimensions.
std::vector<unsigned char> ExtraBytesPayload(const std::vector<ExtraBytesDescriptor>& dimensions);

/// Appends a VLR (its 54-byte header, then its payload) to out.
void AppendVlr(std::vector<unsigned char>& out, const Vlr& vlr);

/// Whether a record is one this project keeps: the coordinate system
/// (LASF_Projection), the Extra Bytes description and the field data.
bool IsKept(const std::string& userId, std::uint16_t recordId);

/// The data set's field data as (name, value text) pairs (CloudTable.h),
/// the values of a several-valued one as pairs of the same name.
using FieldTexts = std::vector<std::pair<std::string, std::string>>;

/// The record of the plugin's own that carries the field data (the unit,
/// class names, counts) which the LAS header and its standard records have
/// no place for: user id FieldDataUserId, record FieldDataRecordId, a
/// line "field <name> <value>" per pair (PlyComments.h's form); a line
/// that would take the payload past a VLR's 65535 bytes is left out, and
/// its field's name added to `left` when given.
constexpr const char* FieldDataUserId = "PCurv_FieldData";
constexpr std::uint16_t FieldDataRecordId = 1;
Vlr FieldDataRecord(const FieldTexts& fields, std::vector<std::string>* left = nullptr);

/// The pairs of the field-data records among `records`, in order.
FieldTexts FieldDataOf(const std::vector<Vlr>& records);

/**
 * The kept records of an open file (stream): the count VLRs from byte
 * first up to pointData, then the evlrCount EVLRs from byte evlrStart.
 * A record that runs past its area ends the scan: files with records that
 * do not follow the specification still give their points.
 */
std::vector<Vlr> ReadKeptRecords(std::FILE* stream,
  std::uint64_t first,
  std::uint32_t count,
  std::uint64_t pointData,
  std::uint64_t evlrStart,
  std::uint32_t evlrCount,
  std::uint64_t fileSize);

} // namespace las
} // namespace pcurv

#endif
