// LAS files made byte by byte for the LAS writer's tests (TestLASWriter):
// legacy files with coordinate-system records, GeoTIFF key directories,
// LAS 1.4 files with an Extra Bytes record.
#ifndef LasTestFiles_h
#define LasTestFiles_h

#include "ReaderTestHelpers.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

/// A LAS 1.2 file, format 1, with the given LASF_Projection records.
inline std::string LegacyFile(const std::vector<std::pair<int, std::string>>& records)
{
  std::string vlrs;
  for (const auto& record : records)
  {
    vlrs += std::string(2, '\0') + std::string("LASF_Projection\0", 16);
    Append(vlrs, static_cast<std::uint16_t>(record.first));
    Append(vlrs, static_cast<std::uint16_t>(record.second.size()));
    vlrs += std::string(32, '\0') + record.second;
  }
  std::string h("LASF");
  h.append(20, '\0');
  h += "\x01\x02";
  h.append(64, ' ');
  Append(h, static_cast<std::uint32_t>(0)); // day, year
  Append(h, static_cast<std::uint16_t>(227));
  Append(h, static_cast<std::uint32_t>(227 + vlrs.size()));
  Append(h, static_cast<std::uint32_t>(records.size()));
  Append(h, static_cast<std::uint8_t>(1));
  Append(h, static_cast<std::uint16_t>(28));
  Append(h, static_cast<std::uint32_t>(3));
  h.append(20, '\0');
  for (double v : { 0.01, 0.01, 0.01, 2000000.0, 7000000.0, 0.0 })
    Append(h, v);
  h.append(48, '\0');
  h += vlrs;
  for (int i = 0; i < 3; ++i)
  {
    for (std::int32_t v : { 100 * i, 200 * i, 300 * i })
      Append(h, v);
    Append(h, static_cast<std::uint16_t>(7));
    Append(h, static_cast<std::uint8_t>(1 | (1 << 3)));
    Append(h, static_cast<std::uint8_t>(2));
    Append(h, static_cast<std::int8_t>(i == 0 ? -13 : 45)); // scan angle rank
    Append(h, static_cast<std::uint8_t>(0));
    Append(h, static_cast<std::uint16_t>(1));
    Append(h, 1000.0 + i);
  }
  return h;
}

/// A GeoKeyDirectory: projected system `code`, linear unit `unit`, and
/// (vertical != 0) a vertical unit.
inline std::string GeoKeys(int code, int unit, int vertical)
{
  std::vector<std::uint16_t> keys = { 1024, 0, 1, 1, 3072, 0, 1, static_cast<std::uint16_t>(code) };
  if (unit)
    keys.insert(keys.end(), { 3076, 0, 1, static_cast<std::uint16_t>(unit) });
  if (vertical)
    keys.insert(keys.end(), { 4099, 0, 1, static_cast<std::uint16_t>(vertical) });
  std::string bytes;
  for (std::uint16_t v : { 1, 1, 0, static_cast<int>(keys.size() / 4) })
    Append(bytes, v);
  for (std::uint16_t v : keys)
    Append(bytes, v);
  return bytes;
}

inline std::string Descriptor(int type,
  int options,
  const std::string& name,
  double scale,
  double offset)
{
  std::string d(192, '\0');
  d[2] = static_cast<char>(type);
  d[3] = static_cast<char>(options);
  d.replace(4, name.size(), name);
  std::string number;
  Append(number, scale);
  d.replace(112, 8, number);
  number.clear();
  Append(number, offset);
  d.replace(136, 8, number);
  return d;
}

/// LAS 1.4 format 6, two points, recordExtra bytes after each record's 30,
/// with an Extra Bytes record of the descriptors.
inline std::string ExtraBytesFile(const std::string& descriptors, int recordExtra)
{
  std::string vlr(2, '\0');
  vlr += std::string("LASF_Spec\0\0\0\0\0\0\0", 16);
  Append(vlr, static_cast<std::uint16_t>(4));
  Append(vlr, static_cast<std::uint16_t>(descriptors.size()));
  vlr += std::string(32, '\0') + descriptors;
  std::string h("LASF");
  h.append(20, '\0');
  h += "\x01\x04";
  h.append(68, ' ');
  Append(h, static_cast<std::uint16_t>(375));
  Append(h, static_cast<std::uint32_t>(375 + vlr.size()));
  Append(h, static_cast<std::uint32_t>(1));
  Append(h, static_cast<std::uint8_t>(6));
  Append(h, static_cast<std::uint16_t>(30 + recordExtra));
  h.append(24, '\0'); // legacy counts
  for (double v : { 0.01, 0.01, 0.01, 0.0, 0.0, 0.0 })
    Append(h, v);
  h.append(48 + 20, '\0');
  Append(h, static_cast<std::uint64_t>(2));
  h.append(120, '\0');
  h += vlr;
  for (int i = 0; i < 2; ++i)
  {
    std::string r(30, '\0');
    r[14] = 0x11;
    h += r;
    Append(h, static_cast<std::uint16_t>(100 + i)); // Scaled: 100 * 0.01 + 5
    Append(h, 2.5f * (i + 1));                      // Value
    h += '\x7F';                                    // undocumented
    Append(h, static_cast<std::int16_t>(-3 - i));   // Intensity (a second one)
  }
  return h;
}

#endif
