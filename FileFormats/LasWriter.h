/**
 * Writes LAS 1.4 point files (ASPRS LAS 1.4 R15): a 375-byte header, the
 * coordinate-system records, an Extra Bytes record describing every
 * further dimension, then point data format 6 (7 with colors, 8 with near
 * infrared too). No VTK here; vtkLASPointCloudWriter is the VTK glue.
 */
#ifndef pcurv_LasWriter_h
#define pcurv_LasWriter_h

#include "FileFormats/LasVlr.h"

#include <cstdint>
#include <string>
#include <vector>

namespace pcurv
{
namespace las
{

/// One value per point: Data points at point 0's value, of Type, and the
/// next point's is Stride values further on (3 for one component of a
/// 3-component array). A null Data: the dimension is absent.
struct Column
{
  const void* Data = nullptr;
  ValueType Type = ValueType::Float64;
  std::size_t Stride = 1;

  bool Present() const { return this->Data != nullptr; }
  /// Point i's value as a double (exact but for 64-bit integers beyond 2^53).
  double At(std::uint64_t i) const;
};

/// A dimension written as extra bytes, in its own type.
struct ExtraDimension
{
  std::string Name; // at most 32 characters, unique among the dimensions
  std::string Description;
  Column Values;
};

/// What to write. The standard dimensions take integer values in their
/// field's range (an error names the first that does not); absent ones are
/// written as 0, ReturnNumber and NumberOfReturns as 1.
struct PointSet
{
  std::uint64_t Count = 0;
  Column X, Y, Z;
  Column Intensity, ReturnNumber, NumberOfReturns, ClassFlags, ScannerChannel, ScanDirectionFlag,
    EdgeOfFlightLine, Classification, UserData, PointSourceId;
  Column ScanAngle;     // degrees; stored in 0.006-degree units
  Column ScanAngleRank; // whole degrees (formats 0-5), used without ScanAngle
  Column GpsTime;
  Column Red, Green, Blue, Infrared;
  std::vector<ExtraDimension> Extras;
};

/// The header's choices and the records that go with the points.
struct FileSettings
{
  /// Scale and offset to keep (an input LAS file's); otherwise chosen from
  /// the coordinates' extent (ChooseScale).
  bool KeepScale = false;
  double Scale[3] = { 1, 1, 1 };
  double Offset[3] = { 0, 0, 0 };
  /// Bit 0 (the GPS time type) is kept; the WKT bit is set when a WKT
  /// record is written.
  std::uint16_t GlobalEncoding = 0;
  /// LASF_Projection records to copy (GeoTIFF keys 34735-34737, WKT 2112).
  std::vector<Vlr> CoordinateRecords;
  /// WKT to write as record 2112 when CoordinateRecords has none.
  std::string Wkt;
  /// Field data to keep in the plugin's own record (LasVlr.h's
  /// FieldDataRecord); none when empty.
  FieldTexts Fields;
  std::string Software = "PrincipalCurvatures";
};

/**
 * The scale and offset for coordinates from minimum to maximum: the offset
 * is the minimum; the scale the smallest power of ten with which the extent
 * spans at most 10^9 units (within int32, with a margin of two).
 */
void ChooseScale(double minimum, double maximum, double& scale, double& offset);

/// The point data format for the dimensions: 6, 7 (Red, Green and Blue),
/// 8 (and Infrared).
int PointFormatOf(const PointSet& points);

/// The legacy point count of a 1.4 header: the count when the format is
/// 0-5 and the count fits 32 bits, else 0 (as the specification asks).
std::uint32_t LegacyPointCount(std::uint64_t count, int pointFormat);

/// Writes the file; an empty string, or what went wrong (nothing usable is
/// left behind then).
std::string WriteFile(const char* fileName, const PointSet& points, const FileSettings& settings);

} // namespace las
} // namespace pcurv

#endif
