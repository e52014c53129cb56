#include "FileFormats/LasWriter.h"

#include "FileFormats/LasBytes.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <limits>
#include <set>
#include <sstream>

namespace pcurv
{
namespace las
{
namespace
{

constexpr std::uint32_t HeaderSize = 375;
constexpr double AngleUnit = 0.006; // degrees per unit of the 1.4 scan angle

template<typename T>
const T& ValueAt(const Column& column, std::uint64_t i)
{
  return static_cast<const T*>(column.Data)[i * column.Stride];
}

/// Writes point i's value of column at p, in the column's own type.
void PutValue(unsigned char* p, const Column& column, std::uint64_t i)
{
  switch (column.Type)
  {
    case ValueType::UInt8:
      return Put(p, ValueAt<std::uint8_t>(column, i));
    case ValueType::Int8:
      return Put(p, ValueAt<std::int8_t>(column, i));
    case ValueType::UInt16:
      return Put(p, ValueAt<std::uint16_t>(column, i));
    case ValueType::Int16:
      return Put(p, ValueAt<std::int16_t>(column, i));
    case ValueType::UInt32:
      return Put(p, ValueAt<std::uint32_t>(column, i));
    case ValueType::Int32:
      return Put(p, ValueAt<std::int32_t>(column, i));
    case ValueType::UInt64:
      return Put(p, ValueAt<std::uint64_t>(column, i));
    case ValueType::Int64:
      return Put(p, ValueAt<std::int64_t>(column, i));
    case ValueType::Float32:
      return Put(p, ValueAt<float>(column, i));
    case ValueType::Float64:
      return Put(p, ValueAt<double>(column, i));
    default:
      return;
  }
}

std::string Number(double value)
{
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}

/// The point's integer coordinates and the rest of the transform.
struct Transform
{
  double Scale[3];
  double Offset[3];
  double Minimum[3]; // of the stored (rounded) coordinates
  double Maximum[3];

  double Units(int axis, double value) const
  {
    return std::round((value - this->Offset[axis]) / this->Scale[axis]);
  }
};

std::string ChooseTransform(const PointSet& points, const FileSettings& settings, Transform& t)
{
  const Column* axes[3] = { &points.X, &points.Y, &points.Z };
  for (int a = 0; a < 3; ++a)
  {
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (std::uint64_t i = 0; i < points.Count; ++i)
    {
      const double v = axes[a]->At(i);
      if (!std::isfinite(v))
        return "point " + std::to_string(i) + " has a coordinate that is not a finite number (" +
          Number(v) + ")";
      low = std::min(low, v);
      high = std::max(high, v);
    }
    if (points.Count == 0)
      low = high = 0;
    if (settings.KeepScale)
    {
      t.Scale[a] = settings.Scale[a];
      t.Offset[a] = settings.Offset[a];
    }
    else
    {
      ChooseScale(low, high, t.Scale[a], t.Offset[a]);
    }
    const double lowUnits = t.Units(a, low), highUnits = t.Units(a, high);
    const double limit = 2147483647.0;
    if (!(t.Scale[a] > 0) || !std::isfinite(lowUnits) || !std::isfinite(highUnits) ||
      lowUnits < -limit - 1 || highUnits > limit)
    {
      const double bad = lowUnits < -limit - 1 || !std::isfinite(lowUnits) ? low : high;
      return std::string("the ") + "xyz"[a] + " coordinate " + Number(bad) +
        " does not fit LAS's 32-bit integers with scale " + Number(t.Scale[a]) + " and offset " +
        Number(t.Offset[a]) +
        (settings.KeepScale ? " (the input LAS file's: remove the LAS_Scale and LAS_Offset field "
                              "data to have them chosen from the points)"
                            : "");
    }
    t.Minimum[a] = lowUnits * t.Scale[a] + t.Offset[a];
    t.Maximum[a] = highUnits * t.Scale[a] + t.Offset[a];
  }
  return std::string();
}

/// An error naming the first value of column that is not an integer in
/// [low, high], or an empty string.
std::string CheckRange(const Column& column,
  std::uint64_t count,
  const char* name,
  double low,
  double high)
{
  if (!column.Present())
  {
    return std::string();
  }
  for (std::uint64_t i = 0; i < count; ++i)
  {
    const double v = column.At(i);
    if (!(v >= low && v <= high && v == std::floor(v)))
    {
      return std::string("the array ") + name + " holds " + Number(v) + " at point " +
        std::to_string(i) + ", which LAS's " + name + " field cannot hold (integers " +
        Number(low) + " to " + Number(high) + ")";
    }
  }
  return std::string();
}

std::string CheckStandardFields(const PointSet& p)
{
  const struct
  {
    const Column& Values;
    const char* Name;
    double Low, High;
  } fields[] = {
    { p.Intensity, "Intensity", 0, 65535 },
    { p.ReturnNumber, "ReturnNumber", 0, 15 },
    { p.NumberOfReturns, "NumberOfReturns", 0, 15 },
    { p.ClassFlags, "ClassFlags", 0, 15 },
    { p.ScannerChannel, "ScannerChannel", 0, 3 },
    { p.ScanDirectionFlag, "ScanDirectionFlag", 0, 1 },
    { p.EdgeOfFlightLine, "EdgeOfFlightLine", 0, 1 },
    { p.Classification, "Classification", 0, 255 },
    { p.UserData, "UserData", 0, 255 },
    { p.PointSourceId, "PointSourceId", 0, 65535 },
    { p.ScanAngleRank, "ScanAngleRank", -180, 180 },
    { p.Red, "Red", 0, 65535 },
    { p.Green, "Green", 0, 65535 },
    { p.Blue, "Blue", 0, 65535 },
    { p.Infrared, "Infrared", 0, 65535 },
  };
  for (const auto& field : fields)
  {
    std::string error = CheckRange(field.Values, p.Count, field.Name, field.Low, field.High);
    if (!error.empty())
      return error;
  }
  for (std::uint64_t i = 0; p.ScanAngle.Present() && i < p.Count; ++i)
  {
    const double v = p.ScanAngle.At(i);
    if (!(std::fabs(v) <= 180.0))
      return "the array ScanAngle holds " + Number(v) + " at point " + std::to_string(i) +
        ", outside LAS's -180 to 180 degrees";
  }
  return std::string();
}

std::string CheckExtras(const PointSet& points, std::uint32_t& extraBytes)
{
  std::set<std::string> names;
  extraBytes = 0;
  for (const ExtraDimension& extra : points.Extras)
  {
    if (extra.Name.empty() || extra.Name.size() > 32 || !names.insert(extra.Name).second)
      return "the extra dimension name '" + extra.Name +
        "' is empty, longer than 32 characters "
        "or used twice";
    if (SizeOf(extra.Values.Type) == 0 || !extra.Values.Present())
      return "the extra dimension '" + extra.Name + "' has no values of a LAS type";
    extraBytes += static_cast<std::uint32_t>(SizeOf(extra.Values.Type));
  }
  if (points.Extras.size() * ExtraBytesDescriptorSize > 65535 || extraBytes > 65535 - 38)
    return "too many extra dimensions (" + std::to_string(points.Extras.size()) + ", " +
      std::to_string(extraBytes) + " bytes a point): LAS records hold at most 65535 bytes";
  return std::string();
}

/// The records between the header and the points.
std::vector<Vlr> RecordsOf(const PointSet& points, const FileSettings& settings, bool& wkt)
{
  std::vector<Vlr> records = settings.CoordinateRecords;
  wkt =
    std::any_of(records.begin(), records.end(), [](const Vlr& r) { return r.RecordId == 2112; });
  if (!wkt && !settings.Wkt.empty())
  {
    Vlr record{ "LASF_Projection", 2112, "OGC coordinate system WKT", {} };
    record.Data.assign(settings.Wkt.begin(), settings.Wkt.end());
    record.Data.push_back(0); // a null-terminated string
    records.push_back(record);
    wkt = true;
  }
  if (!points.Extras.empty())
  {
    std::vector<ExtraBytesDescriptor> descriptors;
    for (const ExtraDimension& extra : points.Extras)
    {
      ExtraBytesDescriptor d;
      d.DataType = static_cast<int>(extra.Values.Type);
      d.Name = extra.Name;
      d.Description = extra.Description;
      descriptors.push_back(d);
    }
    records.push_back({ "LASF_Spec", 4, "Extra Bytes", ExtraBytesPayload(descriptors) });
  }
  if (!settings.Fields.empty())
  {
    records.push_back(FieldDataRecord(settings.Fields));
  }
  return records;
}

struct Layout
{
  int Format = 6;
  std::uint32_t RecordLength = 30;
  std::uint32_t ExtraStart = 30;
};

std::uint8_t Byte(const Column& column, std::uint64_t i, std::uint8_t absent)
{
  return column.Present() ? static_cast<std::uint8_t>(column.At(i)) : absent;
}

std::uint16_t Short(const Column& column, std::uint64_t i)
{
  return column.Present() ? static_cast<std::uint16_t>(column.At(i)) : 0;
}

void EncodeRecord(unsigned char* r,
  const PointSet& p,
  std::uint64_t i,
  const Transform& t,
  const Layout& layout)
{
  std::memset(r, 0, layout.RecordLength);
  const Column* axes[3] = { &p.X, &p.Y, &p.Z };
  for (int a = 0; a < 3; ++a)
  {
    Put(r + 4 * a, static_cast<std::int32_t>(t.Units(a, axes[a]->At(i))));
  }
  Put(r + 12, Short(p.Intensity, i));
  r[14] =
    static_cast<unsigned char>(Byte(p.ReturnNumber, i, 1) | (Byte(p.NumberOfReturns, i, 1) << 4));
  r[15] =
    static_cast<unsigned char>(Byte(p.ClassFlags, i, 0) | (Byte(p.ScannerChannel, i, 0) << 4) |
      (Byte(p.ScanDirectionFlag, i, 0) << 6) | (Byte(p.EdgeOfFlightLine, i, 0) << 7));
  r[16] = Byte(p.Classification, i, 0);
  r[17] = Byte(p.UserData, i, 0);
  const Column& angle = p.ScanAngle.Present() ? p.ScanAngle : p.ScanAngleRank;
  const double degrees = angle.Present() ? angle.At(i) : 0.0;
  Put(r + 18, static_cast<std::int16_t>(std::round(degrees / AngleUnit)));
  Put(r + 20, Short(p.PointSourceId, i));
  Put(r + 22, p.GpsTime.Present() ? p.GpsTime.At(i) : 0.0);
  if (layout.Format >= 7)
  {
    Put(r + 30, Short(p.Red, i));
    Put(r + 32, Short(p.Green, i));
    Put(r + 34, Short(p.Blue, i));
  }
  if (layout.Format == 8)
    Put(r + 36, Short(p.Infrared, i));
  unsigned char* extra = r + layout.ExtraStart;
  for (const ExtraDimension& dimension : p.Extras)
  {
    PutValue(extra, dimension.Values, i);
    extra += SizeOf(dimension.Values.Type);
  }
}

std::vector<unsigned char> HeaderBytes(const PointSet& points,
  const FileSettings& settings,
  const Layout& layout,
  const Transform& t,
  std::uint32_t vlrCount,
  std::uint32_t vlrBytes,
  bool wkt)
{
  std::vector<unsigned char> h(HeaderSize, 0);
  std::memcpy(h.data(), "LASF", 4);
  Put(h.data() + 6, static_cast<std::uint16_t>((settings.GlobalEncoding & 1) | (wkt ? 0x10 : 0)));
  h[24] = 1;
  h[25] = 4;
  PutText(h.data() + 26, "PROCESSING", 32);
  PutText(h.data() + 58, settings.Software, 32);
  const std::time_t now = std::time(nullptr);
  const std::tm* date = std::gmtime(&now);
  Put(h.data() + 90, static_cast<std::uint16_t>(date ? date->tm_yday + 1 : 0));
  Put(h.data() + 92, static_cast<std::uint16_t>(date ? date->tm_year + 1900 : 0));
  Put(h.data() + 94, static_cast<std::uint16_t>(HeaderSize));
  Put(h.data() + 96, HeaderSize + vlrBytes);
  Put(h.data() + 100, vlrCount);
  h[104] = static_cast<unsigned char>(layout.Format);
  Put(h.data() + 105, static_cast<std::uint16_t>(layout.RecordLength));
  Put(h.data() + 107, LegacyPointCount(points.Count, layout.Format));
  for (int a = 0; a < 3; ++a)
  {
    Put(h.data() + 131 + 8 * a, t.Scale[a]);
    Put(h.data() + 155 + 8 * a, t.Offset[a]);
    Put(h.data() + 179 + 16 * a, t.Maximum[a]);
    Put(h.data() + 187 + 16 * a, t.Minimum[a]);
  }
  Put(h.data() + 247, points.Count);
  std::uint64_t byReturn[15] = {};
  for (std::uint64_t i = 0; i < points.Count; ++i)
  {
    const int r = points.ReturnNumber.Present() ? static_cast<int>(points.ReturnNumber.At(i)) : 1;
    if (r >= 1 && r <= 15)
      ++byReturn[r - 1];
  }
  for (int r = 0; r < 15; ++r)
    Put(h.data() + 255 + 8 * r, byReturn[r]);
  return h;
}

std::string WritePoints(std::FILE* file,
  const PointSet& points,
  const Transform& t,
  const Layout& layout)
{
  const std::uint64_t chunk = std::max<std::uint64_t>(1, (1u << 22) / layout.RecordLength);
  std::vector<unsigned char> buffer(static_cast<std::size_t>(chunk * layout.RecordLength));
  for (std::uint64_t first = 0; first < points.Count; first += chunk)
  {
    const std::uint64_t n = std::min(chunk, points.Count - first);
    for (std::uint64_t i = 0; i < n; ++i)
      EncodeRecord(buffer.data() + i * layout.RecordLength, points, first + i, t, layout);
    if (std::fwrite(buffer.data(), layout.RecordLength, n, file) != n)
      return std::string("cannot write the points: ") + std::strerror(errno);
  }
  return std::string();
}

} // namespace

//------------------------------------------------------------------------------
double Column::At(std::uint64_t i) const
{
  switch (this->Type)
  {
    case ValueType::UInt8:
      return ValueAt<std::uint8_t>(*this, i);
    case ValueType::Int8:
      return ValueAt<std::int8_t>(*this, i);
    case ValueType::UInt16:
      return ValueAt<std::uint16_t>(*this, i);
    case ValueType::Int16:
      return ValueAt<std::int16_t>(*this, i);
    case ValueType::UInt32:
      return ValueAt<std::uint32_t>(*this, i);
    case ValueType::Int32:
      return ValueAt<std::int32_t>(*this, i);
    case ValueType::UInt64:
      return static_cast<double>(ValueAt<std::uint64_t>(*this, i));
    case ValueType::Int64:
      return static_cast<double>(ValueAt<std::int64_t>(*this, i));
    case ValueType::Float32:
      return ValueAt<float>(*this, i);
    case ValueType::Float64:
      return ValueAt<double>(*this, i);
    default:
      return 0;
  }
}

//------------------------------------------------------------------------------
void ChooseScale(double minimum, double maximum, double& scale, double& offset)
{
  offset = minimum;
  const double extent = maximum - minimum;
  // The finest power of ten that keeps the extent within 10^9 units; a
  // flat extent gets that of an extent of 1.
  const double span = extent > 0 && std::isfinite(extent) ? extent : 1.0;
  scale = std::pow(10.0, std::ceil(std::log10(span / 1e9)));
  if (span / scale > 1e9) // log10's rounding
    scale *= 10;
}

//------------------------------------------------------------------------------
int PointFormatOf(const PointSet& points)
{
  if (!(points.Red.Present() && points.Green.Present() && points.Blue.Present()))
    return 6;
  return points.Infrared.Present() ? 8 : 7;
}

//------------------------------------------------------------------------------
std::uint32_t LegacyPointCount(std::uint64_t count, int pointFormat)
{
  return pointFormat <= 5 && count <= 0xFFFFFFFFull ? static_cast<std::uint32_t>(count) : 0;
}

//------------------------------------------------------------------------------
std::string WriteFile(const char* fileName, const PointSet& points, const FileSettings& settings)
{
  Layout layout;
  layout.Format = PointFormatOf(points);
  layout.ExtraStart = layout.Format == 6 ? 30 : (layout.Format == 7 ? 36 : 38);
  std::uint32_t extraBytes = 0;
  Transform t;
  for (const std::string& error : { CheckExtras(points, extraBytes),
         CheckStandardFields(points),
         ChooseTransform(points, settings, t) })
  {
    if (!error.empty())
      return error;
  }
  layout.RecordLength = layout.ExtraStart + extraBytes;
  bool wkt = false;
  const std::vector<Vlr> records = RecordsOf(points, settings, wkt);
  std::vector<unsigned char> recordBytes;
  for (const Vlr& record : records)
  {
    if (record.Data.size() > 65535)
      return "the record " + record.UserId + " " + std::to_string(record.RecordId) +
        " is longer than a LAS variable length record (65535 bytes)";
    AppendVlr(recordBytes, record);
  }
  const std::vector<unsigned char> header = HeaderBytes(points,
    settings,
    layout,
    t,
    static_cast<std::uint32_t>(records.size()),
    static_cast<std::uint32_t>(recordBytes.size()),
    wkt);

  std::FILE* file = std::fopen(fileName, "wb");
  if (!file)
    return std::string("cannot open the file for writing: ") + std::strerror(errno);
  std::string error;
  // The header and records in one write (a file without records has none).
  std::vector<unsigned char> head = header;
  head.insert(head.end(), recordBytes.begin(), recordBytes.end());
  if (std::fwrite(head.data(), 1, head.size(), file) != head.size())
    error = std::string("cannot write the header: ") + std::strerror(errno);
  if (error.empty())
    error = WritePoints(file, points, t, layout);
  if (std::fclose(file) != 0 && error.empty())
    error = std::string("cannot write the file: ") + std::strerror(errno);
  if (!error.empty())
    std::remove(fileName);
  return error;
}

} // namespace las
} // namespace pcurv
