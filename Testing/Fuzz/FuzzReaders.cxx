// The LAS and PLY parsers of the core on any bytes, as a file (fmemopen):
// no crash, no undefined behavior, no hang, and
// - LAS: a header that is accepted describes points inside the file, and
//   reading them all then succeeds;
// - PLY: an accepted header has a vertex element with x, y and z, declares
//   no more vertices than the data can hold (so that nothing is allocated
//   for a lying count), and its columns are read without writing outside
//   them (AddressSanitizer) whatever the body holds.
#include "FuzzReaders.h"

#include "FileFormats/LasCrs.h"
#include "FileFormats/LasFile.h"
#include "FileFormats/PlyFile.h"

#include <cstdio>
#include <cstdlib>
#include <vector>

namespace
{

void Require(bool condition, const char* what)
{
  if (!condition)
  {
    std::fprintf(stderr, "invariant broken: %s\n", what);
    std::abort();
  }
}

/// The bytes as a read-only stream; none for no bytes (fmemopen refuses
/// an empty buffer; an empty file is the reader's "cannot read" case).
std::FILE* Stream(const std::uint8_t* data, std::size_t size, std::vector<std::uint8_t>& copy)
{
  copy.assign(data, data + size);
  return size ? fmemopen(copy.data(), size, "rb") : nullptr;
}

} // namespace

void FuzzLasFile(const std::uint8_t* data, std::size_t size)
{
  std::vector<std::uint8_t> copy;
  std::FILE* stream = Stream(data, size, copy);
  if (!stream)
  {
    return;
  }
  pcurv::las::File file;
  if (!file.Open(stream).empty())
  {
    return;
  }
  const pcurv::las::Header& header = file.GetHeader();
  Require(header.OffsetToPointData + header.PointCount * header.RecordLength <= size,
    "las: an accepted header's points lie inside the file");
  const std::size_t count = static_cast<std::size_t>(header.PointCount);
  std::vector<double> points(3 * count), gps(count);
  std::vector<std::uint16_t> words(5 * count);
  std::vector<std::uint8_t> bytes(5 * count);
  std::vector<float> angle(count);
  std::vector<std::int16_t> rank(count);
  std::vector<std::uint8_t> flags(4 * count);
  pcurv::las::PointBuffers out;
  out.Points = points.data();
  out.Intensity = words.data();
  out.PointSourceId = words.data() + count;
  out.Red = words.data() + 2 * count;
  out.Green = words.data() + 3 * count;
  out.Blue = words.data() + 4 * count;
  out.Infrared = out.Red;
  out.ReturnNumber = bytes.data();
  out.NumberOfReturns = bytes.data() + count;
  out.Classification = bytes.data() + 2 * count;
  out.UserData = bytes.data() + 3 * count;
  out.ScanAngle = angle.data();
  out.ScanAngleRank = rank.data();
  out.GpsTime = gps.data();
  out.ClassFlags = flags.data();
  out.ScannerChannel = flags.data() + count;
  out.ScanDirectionFlag = flags.data() + 2 * count;
  out.EdgeOfFlightLine = flags.data() + 3 * count;
  // The records' contents come from the file too: the coordinate system
  // and the extra bytes described within each record.
  const std::vector<pcurv::las::Vlr> records = file.ReadKeptRecords();
  pcurv::las::DescribeCoordinates(records);
  const std::vector<pcurv::las::ExtraField> fields = pcurv::las::ExtraFieldsOf(header, records);
  std::vector<std::vector<double>> extras(fields.size(), std::vector<double>(count));
  for (std::size_t f = 0; f < fields.size(); ++f)
  {
    Require(fields[f].ByteOffset + pcurv::las::SizeOf(fields[f].Type) <= header.RecordLength,
      "las: extra bytes lie within the record");
    out.Extras.push_back({ fields[f].ByteOffset,
      fields[f].Type,
      fields[f].Scaled,
      fields[f].Scale,
      fields[f].Offset,
      extras[f].data(),
      1 });
  }
  Require(file.Read(0, header.PointCount, out).empty(), "las: an accepted file's points read");
}

void FuzzPlyFile(const std::uint8_t* data, std::size_t size)
{
  std::vector<std::uint8_t> copy;
  std::FILE* stream = Stream(data, size, copy);
  if (!stream)
  {
    return;
  }
  pcurv::ply::File file;
  if (!file.Open(stream).empty())
  {
    return;
  }
  pcurv::ply::VertexLayout& layout = file.Layout();
  Require(layout.Points >= 0 && layout.Columns[layout.Points].Components == 3,
    "ply: an accepted file has x y z");
  const std::uint64_t count = file.Vertices().Count;
  Require(count <= size, "ply: no more vertices than bytes");
  std::vector<std::vector<double>> columns; // 8 bytes a value: room for any type
  for (pcurv::ply::Column& column : layout.Columns)
  {
    columns.emplace_back(static_cast<std::size_t>(count) * column.Components);
    column.Data = columns.back().data();
  }
  file.Read(0, count);
  if (count > 1)
  {
    file.Read(count / 2, count); // a piece: rows from 0 again
  }
}
