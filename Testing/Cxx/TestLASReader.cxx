// vtkLASPointCloudReader on small LAS files written here (versions 1.2,
// 1.3, 1.4; every point format 0-10, with extra bytes and a variable
// length record before the points): every array's values, the exact double
// coordinates, the 4-bit return numbers and full classification byte of
// formats 6-10, their flags, the 8-bit RGB of 16-bit and 8-bit colors,
// 64-bit point counts, pieces; then bad files, each with the
// error it must give (and no points, no crash).
#include "ReaderTestHelpers.h"
#include "TestChecks.h"
#include "vtkLASPointCloudReader.h"

#include "vtkErrorCode.h"
#include "vtkNew.h"
#include "vtkPoints.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace
{

struct LasPoint
{
  std::int32_t X, Y, Z;
  std::uint16_t Intensity;
  int ReturnNumber, NumberOfReturns, Classification;
  int ScanAngle; // whole degrees (formats 0-5) or 0.006-degree units (6-10)
  std::uint8_t UserData;
  std::uint16_t PointSourceId;
  double GpsTime;
  std::uint16_t Red, Green, Blue, Infrared;
};

struct LasSpec
{
  int Minor = 2;
  int Format = 0;
  int ExtraBytes = 0; // per record, after the format's fields
  int VlrBytes = 0;   // a variable length record between header and points
  double Scale[3] = { 0.001, 0.001, 0.01 };
  double Offset[3] = { 596000, 243000, 0 };
  bool LegacyCountZero = false; // 1.4: only the 64-bit count
};

int HeaderSizeOf(int minor)
{
  return minor <= 2 ? 227 : (minor == 3 ? 235 : 375);
}

int RecordLengthOf(int format)
{
  static const int lengths[] = { 20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67 };
  return lengths[format];
}

bool HasGps(int format)
{
  return format != 0 && format != 2;
}

bool HasColor(int format)
{
  return format == 2 || format == 3 || format == 5 || format == 7 || format == 8 || format == 10;
}

bool HasInfrared(int format)
{
  return format == 8 || format == 10;
}

/// One point record of the spec's format.
std::string Record(const LasSpec& spec, const LasPoint& p)
{
  std::string r;
  Append(r, p.X);
  Append(r, p.Y);
  Append(r, p.Z);
  Append(r, p.Intensity);
  const bool extended = spec.Format >= 6;
  if (extended)
  {
    Append(r, static_cast<std::uint8_t>(p.ReturnNumber | (p.NumberOfReturns << 4)));
    Append(r, static_cast<std::uint8_t>(0xF3)); // flags, channel, scan direction, edge
    Append(r, static_cast<std::uint8_t>(p.Classification));
    Append(r, p.UserData);
    Append(r, static_cast<std::int16_t>(p.ScanAngle));
    Append(r, p.PointSourceId);
    Append(r, p.GpsTime);
  }
  else
  {
    // Scan direction and edge bits set, and the class's three flag bits:
    // none of them may leak into the values.
    Append(r, static_cast<std::uint8_t>(p.ReturnNumber | (p.NumberOfReturns << 3) | 0xC0));
    Append(r, static_cast<std::uint8_t>(p.Classification | 0xE0));
    Append(r, static_cast<std::int8_t>(p.ScanAngle));
    Append(r, p.UserData);
    Append(r, p.PointSourceId);
    if (HasGps(spec.Format))
    {
      Append(r, p.GpsTime);
    }
  }
  if (HasColor(spec.Format))
  {
    Append(r, p.Red);
    Append(r, p.Green);
    Append(r, p.Blue);
  }
  if (HasInfrared(spec.Format))
  {
    Append(r, p.Infrared);
  }
  if (spec.Format == 4 || spec.Format == 5 || spec.Format >= 9)
  {
    r.append(29, '\x33'); // a wave packet, which the reader skips
  }
  r.append(spec.ExtraBytes, '\x5A');
  return r;
}

/// A whole LAS file of the spec holding points.
std::string LasFile(const LasSpec& spec, const std::vector<LasPoint>& points)
{
  const int headerSize = HeaderSizeOf(spec.Minor);
  const int recordLength = RecordLengthOf(spec.Format) + spec.ExtraBytes;
  std::string h("LASF");
  h.append(20, '\0'); // file source id, global encoding, GUID
  Append(h, static_cast<std::uint8_t>(1));
  Append(h, static_cast<std::uint8_t>(spec.Minor));
  h.append(64, ' '); // system identifier, generating software
  Append(h, static_cast<std::uint16_t>(336));
  Append(h, static_cast<std::uint16_t>(2026));
  Append(h, static_cast<std::uint16_t>(headerSize));
  Append(h, static_cast<std::uint32_t>(headerSize + spec.VlrBytes));
  Append(h, static_cast<std::uint32_t>(spec.VlrBytes ? 1 : 0));
  Append(h, static_cast<std::uint8_t>(spec.Format));
  Append(h, static_cast<std::uint16_t>(recordLength));
  Append(h, static_cast<std::uint32_t>(spec.LegacyCountZero ? 0 : points.size()));
  h.append(20, '\0'); // points by return
  for (double v : spec.Scale)
    Append(h, v);
  for (double v : spec.Offset)
    Append(h, v);
  h.append(48, '\0'); // bounds (not used by the reader)
  if (spec.Minor >= 3)
    Append(h, static_cast<std::uint64_t>(0)); // waveform data
  if (spec.Minor >= 4)
  {
    Append(h, static_cast<std::uint64_t>(0)); // first extended VLR
    Append(h, static_cast<std::uint32_t>(0));
    Append(h, static_cast<std::uint64_t>(points.size()));
    h.append(120, '\0');
  }
  h.append(spec.VlrBytes, '\x11');
  for (const LasPoint& p : points)
  {
    h += Record(spec, p);
  }
  return h;
}

std::vector<LasPoint> KnownPoints(bool extended)
{
  // x = 596700.123 (scale 0.001, offset 596000), y = 243650.5, z = 80.25.
  LasPoint a{ 700123, 650500, 8025, 1234, 5, 7, 18, -30, 9, 4321, 3.5e8, 65535, 256, 7, 999 };
  LasPoint b{ -1, 0, -8025, 0, 1, 1, 2, 45, 0, 0, -1.25, 0, 65280, 255, 0 };
  if (extended)
  {
    a.ReturnNumber = 9; // 4 bits
    a.NumberOfReturns = 12;
    a.Classification = 200; // a whole byte
    a.ScanAngle = -15000;   // -90 degrees
    b.ScanAngle = 30000;    // +180
  }
  return { a, b };
}

struct Read
{
  vtkSmartPointer<vtkPolyData> Cloud;
  std::string Errors;
  unsigned long Code = 0;
};

Read ReadLas(const std::string& path, int piece = 0, int pieces = 1)
{
  vtkNew<vtkLASPointCloudReader> reader;
  vtkNew<ErrorCatcher> catcher;
  reader->AddObserver(vtkCommand::ErrorEvent, catcher);
  reader->SetFileName(path.c_str());
  reader->UpdatePiece(piece, pieces, 0);
  Read read;
  read.Cloud = reader->GetOutput();
  read.Errors = catcher->Messages;
  read.Code = reader->GetErrorCode();
  return read;
}

void CheckGoodFile(Checks& checks, const LasSpec& spec, const std::string& folder)
{
  const bool extended = spec.Format >= 6;
  const std::vector<LasPoint> points = KnownPoints(extended);
  const std::string path = folder + "/good_1" + std::to_string(spec.Minor) + "_format" +
    std::to_string(spec.Format) + ".las";
  checks.True("writes the LAS file", WriteBytes(path, LasFile(spec, points)));
  const Read read = ReadLas(path);
  std::printf("LAS 1.%d format %d (extra bytes %d, VLR %d): %s\n",
    spec.Minor,
    spec.Format,
    spec.ExtraBytes,
    spec.VlrBytes,
    read.Errors.empty() ? "read" : read.Errors.c_str());
  vtkPolyData* cloud = read.Cloud;
  checks.True("no error", read.Errors.empty() && read.Code == vtkErrorCode::NoError);
  checks.Equal("points", cloud->GetNumberOfPoints(), 2);
  checks.Equal("vertex cells", cloud->GetNumberOfVerts(), 2);
  if (cloud->GetNumberOfPoints() != 2)
  {
    return;
  }
  checks.Equal("double points", cloud->GetPoints()->GetDataType(), VTK_DOUBLE);
  double x[3];
  cloud->GetPoint(0, x);
  checks.Near("x = 596700.123", x[0], 596700.123, 1e-9);
  checks.Near("y = 243650.5", x[1], 243650.5, 1e-9);
  checks.Near("z = 80.25", x[2], 80.25, 1e-9);
  cloud->GetPoint(1, x);
  checks.Near("x = 595999.999", x[0], 595999.999, 1e-9);
  checks.Near("z = -80.25", x[2], -80.25, 1e-9);
  for (int i = 0; i < 2; ++i)
  {
    const LasPoint& p = points[i];
    checks.Near("Intensity", ValueOf(cloud, "Intensity", i), p.Intensity, 0);
    checks.Near("ReturnNumber", ValueOf(cloud, "ReturnNumber", i), p.ReturnNumber, 0);
    checks.Near("NumberOfReturns", ValueOf(cloud, "NumberOfReturns", i), p.NumberOfReturns, 0);
    checks.Near("Classification", ValueOf(cloud, "Classification", i), p.Classification, 0);
    checks.Near("UserData", ValueOf(cloud, "UserData", i), p.UserData, 0);
    checks.Near("PointSourceId", ValueOf(cloud, "PointSourceId", i), p.PointSourceId, 0);
    if (extended)
    {
      checks.Near("ScanAngle (degrees)", ValueOf(cloud, "ScanAngle", i), p.ScanAngle * 0.006, 1e-4);
    }
    else
    {
      checks.Near("ScanAngleRank", ValueOf(cloud, "ScanAngleRank", i), p.ScanAngle, 0);
    }
    const bool gps = HasGps(spec.Format);
    const bool rgb = HasColor(spec.Format);
    checks.True(
      "GpsTime present as the format says", (TypeOf(cloud, "GpsTime") == VTK_DOUBLE) == gps);
    if (gps)
      checks.Near("GpsTime", ValueOf(cloud, "GpsTime", i), p.GpsTime, 0);
    checks.True(
      "Red present as the format says", (TypeOf(cloud, "Red") == VTK_UNSIGNED_SHORT) == rgb);
    if (rgb)
    {
      checks.Near("Red", ValueOf(cloud, "Red", i), p.Red, 0);
      checks.Near("Green", ValueOf(cloud, "Green", i), p.Green, 0);
      checks.Near("Blue", ValueOf(cloud, "Blue", i), p.Blue, 0);
    }
    if (rgb)
    {
      // 16-bit colors (values above 255): scaled, 65535 to 255, rounded.
      const double eightBit[2][3] = { { 255, 1, 0 }, { 0, 254, 1 } };
      for (int c = 0; c < 3; ++c)
        checks.Near("RGB, 16-bit scaled", ValueOf(cloud, "RGB", i, c), eightBit[i][c], 0);
    }
    checks.True("Infrared only in formats 8 and 10",
      (TypeOf(cloud, "Infrared") >= 0) == HasInfrared(spec.Format));
    if (HasInfrared(spec.Format))
      checks.Near("Infrared", ValueOf(cloud, "Infrared", i), p.Infrared, 0);
  }
  vtkDataArray* colors = cloud->GetPointData()->GetArray("RGB");
  checks.True("RGB (3 unsigned chars, the active scalars) exactly when there are colors",
    HasColor(spec.Format) ? colors && TypeOf(cloud, "RGB") == VTK_UNSIGNED_CHAR &&
        colors->GetNumberOfComponents() == 3 && cloud->GetPointData()->GetScalars() == colors
                          : !colors);
  checks.True(
    "ScanAngleRank only in formats 0-5", (TypeOf(cloud, "ScanAngleRank") >= 0) != extended);
  if (!extended)
  {
    // A short: ParaView's CSV writer prints a signed char as a character.
    checks.Equal("ScanAngleRank is a short", TypeOf(cloud, "ScanAngleRank"), VTK_SHORT);
  }
  // The records' flag bits (see Record): formats 0-5 synthetic, key-point
  // and withheld set, scan direction and edge set; formats 6-10 0xF3:
  // class flags 3, scanner channel 3, scan direction and edge set.
  for (int i = 0; i < 2; ++i)
  {
    checks.Near("ClassFlags", ValueOf(cloud, "ClassFlags", i), extended ? 3 : 7, 0);
    checks.Near("ScanDirectionFlag", ValueOf(cloud, "ScanDirectionFlag", i), 1, 0);
    checks.Near("EdgeOfFlightLine", ValueOf(cloud, "EdgeOfFlightLine", i), 1, 0);
    checks.True("ScannerChannel only in formats 6-10",
      extended ? ValueOf(cloud, "ScannerChannel", i) == 3 : TypeOf(cloud, "ScannerChannel") < 0);
  }
}

/// 8-bit colors in the 16-bit fields (no value above 255), as many
/// writers store them: RGB keeps the values, not a near-black 0 or 1.
void CheckEightBitColors(Checks& checks, const std::string& folder)
{
  LasSpec spec;
  spec.Format = 2;
  std::vector<LasPoint> points = KnownPoints(false);
  points[0].Red = 255, points[0].Green = 128, points[0].Blue = 7;
  points[1].Red = 0, points[1].Green = 40, points[1].Blue = 200;
  const std::string path = folder + "/eight_bit_colors.las";
  WriteBytes(path, LasFile(spec, points));
  const Read read = ReadLas(path);
  const bool two = read.Cloud->GetNumberOfPoints() == 2 && TypeOf(read.Cloud, "RGB") >= 0;
  checks.True("8-bit colors: read", two);
  for (int i = 0; two && i < 2; ++i)
  {
    const double expected[3] = {
      double(points[i].Red), double(points[i].Green), double(points[i].Blue)
    };
    for (int c = 0; c < 3; ++c)
      checks.Near("8-bit colors kept in RGB", ValueOf(read.Cloud, "RGB", i, c), expected[c], 0);
    checks.Near("Red as stored", ValueOf(read.Cloud, "Red", i), points[i].Red, 0);
  }
}

void CheckPieces(Checks& checks, const std::string& folder)
{
  LasSpec spec;
  std::vector<LasPoint> points;
  for (int i = 0; i < 5; ++i)
  {
    points.push_back(KnownPoints(false)[0]);
    points.back().X = i;
  }
  const std::string path = folder + "/pieces.las";
  WriteBytes(path, LasFile(spec, points));
  const Read second = ReadLas(path, 1, 2);
  checks.Equal("piece 1 of 2: points 2-4", second.Cloud->GetNumberOfPoints(), 3);
  if (second.Cloud->GetNumberOfPoints() == 3)
    checks.Near("piece 1 of 2 starts at point 2", second.Cloud->GetPoint(0)[0], 596000.002, 1e-9);
}

struct BadCase
{
  const char* Name;
  std::string Bytes;
  const char* Expected;
};

std::string Patched(std::string bytes, std::size_t at, const std::string& with)
{
  bytes.replace(at, with.size(), with);
  return bytes;
}

template<typename T>
std::string Value(T value)
{
  std::string bytes;
  Append(bytes, value);
  return bytes;
}

void CheckBadFiles(Checks& checks, const std::string& folder)
{
  LasSpec spec;
  spec.Format = 1;
  const std::string good = LasFile(spec, KnownPoints(false)); // 227 + 2 x 28 bytes
  LasSpec spec14;
  spec14.Minor = 4;
  spec14.Format = 6;
  const std::string good14 = LasFile(spec14, KnownPoints(true));
  const std::vector<BadCase> cases = {
    { "signature.las", Patched(good, 0, "LASX"), "not a LAS file: it starts with 'LASX'" },
    { "empty.las", "", "not a LAS file: it starts with ''" },
    { "short_header.las",
      good.substr(0, 100),
      "truncated: the file has 100 bytes, less than a LAS header (227)" },
    { "short_header14.las",
      good14.substr(0, 300),
      "truncated: the file has 300 bytes, less than its LAS 1.4 header (375)" },
    { "truncated.las",
      good.substr(0, good.size() - 10),
      "the header declares 2 points of 28 bytes from byte 227, but the file (273 bytes) holds only "
      "1" },
    { "count_lies.las",
      Patched(good, 107, Value<std::uint32_t>(1000000)),
      "the header declares 1000000 points of 28 bytes from byte 227" },
    { "count_too_small.las",
      Patched(good, 107, Value<std::uint32_t>(0)),
      "the header declares 0 points, but the file holds 2 records of 28 bytes" },
    { "count64_lies.las",
      Patched(Patched(good14, 107, Value<std::uint32_t>(0)), 247, Value<std::uint64_t>(~0ull)),
      "the header declares 18446744073709551615 points of 30 bytes" },
    { "counts_disagree.las",
      Patched(good14, 247, Value<std::uint64_t>(3)),
      "the legacy point count (2) disagrees with the 64-bit point count (3)" },
    { "offset_beyond.las",
      Patched(good, 96, Value<std::uint32_t>(5000)),
      "the offset to point data (5000) is beyond the end of the file (283 bytes)" },
    { "offset_in_header.las",
      Patched(good, 96, Value<std::uint32_t>(100)),
      "the offset to point data (100) is inside the header (227 bytes)" },
    { "record_short.las",
      Patched(good, 105, Value<std::uint16_t>(20)),
      "the point data record length is 20 bytes, smaller than point data format 1 needs (28)" },
    { "version.las",
      Patched(good, 24, std::string("\x02\x00", 2)),
      "unknown LAS version 2.0 (this reader knows 1.0 to 1.4)" },
    { "minor.las", Patched(good, 25, std::string("\x07", 1)), "unknown LAS version 1.7" },
    { "header_size.las",
      Patched(good, 94, Value<std::uint16_t>(200)),
      "the header size is 200 bytes, LAS 1.2 needs 227" },
    { "format.las",
      Patched(good, 104, std::string("\x0B", 1)),
      "unknown point data format 11 (this reader knows 0 to 10)" },
    { "compressed.las",
      Patched(good, 104, std::string("\x81", 1)),
      "the file is LAZ-compressed (point data format 1 with the compression bit set)" },
    { "compressed.laz",
      Patched(good14, 104, std::string("\x46", 1)),
      "decompress it first, e.g. 'laszip -i in.laz -o out.las' or 'pdal translate in.laz "
      "out.las'" },
    { "scale.las",
      Patched(good, 131, Value<double>(0)),
      "the x scale (0) or offset (596000) is not a finite number, or the scale is 0" },
  };
  for (const BadCase& bad : cases)
  {
    const std::string path = folder + "/" + bad.Name;
    WriteBytes(path, bad.Bytes);
    const Read read = ReadLas(path);
    std::printf("%s: %s", bad.Name, read.Errors.c_str());
    const bool named = read.Errors.find(path + ": ") != std::string::npos;
    const bool said = read.Errors.find(bad.Expected) != std::string::npos;
    checks.True(bad.Name, named && said && read.Code != vtkErrorCode::NoError);
    checks.Equal(bad.Name, read.Cloud->GetNumberOfPoints(), 0);
  }
  const Read missing = ReadLas(folder + "/no_such_file.las");
  checks.True("a missing file: cannot open",
    missing.Errors.find("cannot open the file") != std::string::npos);
}

} // namespace

int TestLASReader(int argc, char* argv[])
{
  const std::string folder = argc > 1 ? argv[1] : ".";
  Checks checks;
  for (int format : { 0, 1, 2, 3, 4, 5 })
  {
    LasSpec spec;
    spec.Format = format;
    CheckGoodFile(checks, spec, folder);
  }
  LasSpec v13;
  v13.Minor = 3;
  v13.Format = 1;
  v13.ExtraBytes = 4;
  v13.VlrBytes = 60;
  CheckGoodFile(checks, v13, folder);
  for (int format : { 6, 7, 8, 9, 10 })
  {
    LasSpec spec;
    spec.Minor = 4;
    spec.Format = format;
    spec.ExtraBytes = format == 7 ? 3 : 0;
    spec.VlrBytes = format == 8 ? 54 : 0;
    CheckGoodFile(checks, spec, folder);
  }
  LasSpec only64;
  only64.Minor = 4;
  only64.Format = 3;
  only64.LegacyCountZero = true;
  CheckGoodFile(checks, only64, folder);
  CheckEightBitColors(checks, folder);
  CheckPieces(checks, folder);
  CheckBadFiles(checks, folder);
  return checks.Summary();
}

int main(int argc, char* argv[])
{
  return TestLASReader(argc, argv);
}
