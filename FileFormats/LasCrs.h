/**
 * The coordinate system and length unit a LAS file declares: GeoTIFF keys
 * (LASF_Projection record 34735, the GeoKeyDirectory, with its ASCII
 * parameters in 34737) or OGC WKT (record 2112). No VTK here.
 */
#ifndef pcurv_LasCrs_h
#define pcurv_LasCrs_h

#include "FileFormats/LasVlr.h"

#include <string>
#include <vector>

namespace pcurv
{
namespace las
{

/// What a file says of its coordinates; empty strings where it says nothing.
struct CoordinateSystem
{
  /// The WKT as written, or "EPSG:<code>" (with "+<vertical code>" when
  /// the keys name a vertical system), or the keys' citation.
  std::string Description;
  /// The horizontal length unit: "metre", "foot", "US survey foot", or the
  /// name the file gives; "degree" for geographic coordinates.
  std::string LengthUnit;
  /// The vertical unit, when the file names one.
  std::string VerticalUnit;
};

/// From a GeoKeyDirectory payload (record 34735) and the ASCII parameters
/// (record 34737, may be empty).
CoordinateSystem FromGeoKeys(const std::vector<unsigned char>& directory,
  const std::vector<unsigned char>& asciiParameters);

/// From OGC WKT (WKT 1, or WKT 2's PROJCRS / LENGTHUNIT forms).
CoordinateSystem FromWkt(const std::string& wkt);

/// The file's coordinate system from its records: the WKT record when
/// there is one (as LAS 1.4 asks for point formats 6-10), else the GeoTIFF
/// keys.
CoordinateSystem DescribeCoordinates(const std::vector<Vlr>& records);

/// The name of an EPSG unit of length code (9001 "metre", 9002 "foot",
/// 9003 "US survey foot", ...), or "EPSG unit <code>".
std::string UnitName(int epsgUnitCode);

} // namespace las
} // namespace pcurv

#endif
