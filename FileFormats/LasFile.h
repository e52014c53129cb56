/**
 * LAS 1.0-1.4 point files (ASPRS LAS specification), uncompressed, point
 * data formats 0-10: the header checked against the file, then the point
 * records decoded in chunks straight into the caller's arrays. No VTK here;
 * vtkLASPointCloudReader is the VTK glue.
 *
 * The names of the fields are PDAL's (Intensity, ReturnNumber, ...), so that
 * scripts written for PDAL's output find the same arrays.
 */
#ifndef pcurv_LasFile_h
#define pcurv_LasFile_h

#include "FileFormats/FileInput.h"
#include "FileFormats/LasVlr.h"

#include <cstdint>
#include <string>
#include <vector>

namespace pcurv
{
namespace las
{

/// The parts of the public header block this reader uses.
struct Header
{
  int VersionMajor = 0;
  int VersionMinor = 0;
  std::uint32_t HeaderSize = 0;
  std::uint32_t OffsetToPointData = 0;
  std::uint16_t GlobalEncoding = 0; // bit 0: GPS time type; bit 4: the CRS is WKT
  std::uint32_t VlrCount = 0;
  std::uint64_t EvlrStart = 0; // 1.4: the first extended VLR
  std::uint32_t EvlrCount = 0;
  std::uint64_t FileSize = 0;
  int PointFormat = 0;
  std::uint32_t RecordLength = 0;
  std::uint64_t PointCount = 0;
  double Scale[3] = { 1, 1, 1 };
  double Offset[3] = { 0, 0, 0 };
};

/// Where a point data format keeps its optional fields (-1: absent).
struct RecordLayout
{
  std::uint32_t MinimumLength = 0;
  bool Extended = false; // formats 6-10: 4-bit return numbers, a full classification byte
  int GpsTime = -1;
  int Color = -1;    // Red, Green, Blue: three uint16
  int Infrared = -1; // formats 8 and 10
};

/// The layout of point data format 0-10; MinimumLength 0 for any other.
RecordLayout LayoutOf(int pointFormat);

/**
 * The caller's arrays, one value (three for Points) per point; a null
 * pointer skips that field. Fields the format lacks are left untouched.
 */
struct PointBuffers
{
  double* Points = nullptr; // x y z: the int32 record value times scale plus offset
  std::uint16_t* Intensity = nullptr;
  std::uint8_t* ReturnNumber = nullptr;
  std::uint8_t* NumberOfReturns = nullptr;
  std::uint8_t* Classification = nullptr;
  // Formats 0-5: synthetic, key-point, withheld (bits 0-2); formats 6-10
  // also overlap (bit 3), as LAS 1.4 stores them.
  std::uint8_t* ClassFlags = nullptr;
  std::uint8_t* ScannerChannel = nullptr; // formats 6-10
  std::uint8_t* ScanDirectionFlag = nullptr;
  std::uint8_t* EdgeOfFlightLine = nullptr;
  std::int16_t* ScanAngleRank = nullptr; // formats 0-5: whole degrees
  float* ScanAngle = nullptr;            // formats 6-10: degrees (0.006 per unit)
  std::uint8_t* UserData = nullptr;
  std::uint16_t* PointSourceId = nullptr;
  double* GpsTime = nullptr;
  std::uint16_t* Red = nullptr;
  std::uint16_t* Green = nullptr;
  std::uint16_t* Blue = nullptr;
  std::uint16_t* Infrared = nullptr;
  /// Extra-bytes dimensions: the value at ByteOffset of each record, as
  /// Type into Out (a buffer of that type), or as double times Scale plus
  /// Offset when Scaled.
  struct Extra
  {
    std::uint32_t ByteOffset = 0;
    ValueType Type = ValueType::Float64;
    bool Scaled = false;
    double Scale = 1;
    double Offset = 0;
    void* Out = nullptr;
    std::size_t Stride = 1; // values between two points' in Out
  };
  std::vector<Extra> Extras;
};

/// A dimension of the extra bytes that the reader returns: a scalar of
/// type 1-10 (the deprecated arrays and undocumented bytes are skipped)
/// lying within the record.
struct ExtraField
{
  std::string Name;
  ValueType Type = ValueType::Float64;
  std::uint32_t ByteOffset = 0;
  bool Scaled = false;
  double Scale = 1;
  double Offset = 0;
};

/// The extra fields that the Extra Bytes record (among records) describes
/// for the header's records; none when the record describes more bytes than
/// the records have (an "extra bytes mismatch" voids it).
std::vector<ExtraField> ExtraFieldsOf(const Header& header, const std::vector<Vlr>& records);

/// Decodes count records of the header's format from records (little
/// endian, header.RecordLength bytes apart) into out, from out's index first.
void DecodeRecords(const Header& header,
  const unsigned char* records,
  std::size_t count,
  std::size_t first,
  const PointBuffers& out);

/**
 * Checks the header in data (the file's first size bytes; the whole header
 * is needed) against the file's size. Returns an empty string when it
 * holds, else what is wrong, in words that name the field and its value.
 */
std::string ParseHeader(const unsigned char* data,
  std::size_t size,
  std::uint64_t fileSize,
  Header& header);

/// An open LAS file: Open (InputFile's) reads and checks the header, Read
/// the points.
class File final : public InputFile
{
public:
  const Header& GetHeader() const { return this->TheHeader; }
  /// Reads points [begin, end) into out (index 0 is point begin), in chunks
  /// of a fixed size; an empty string, or what went wrong.
  std::string Read(std::uint64_t begin, std::uint64_t end, const PointBuffers& out);
  /// The coordinate-system and Extra Bytes records of the file (VLRs and
  /// EVLRs), in file order.
  std::vector<Vlr> ReadKeptRecords();

private:
  std::string ReadHeader(std::uint64_t fileSize) override;

  Header TheHeader;
};

} // namespace las
} // namespace pcurv

#endif
