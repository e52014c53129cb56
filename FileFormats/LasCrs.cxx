#include "FileFormats/LasCrs.h"

#include "FileFormats/LasBytes.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>

namespace pcurv
{
namespace las
{
namespace
{

// GeoTIFF keys (GeoTIFF 1.0, section 6.2) used here.
constexpr int ModelTypeKey = 1024;
constexpr int CitationKey = 1026;
constexpr int GeographicTypeKey = 2048;
constexpr int ProjectedTypeKey = 3072;
constexpr int ProjectedCitationKey = 3073;
constexpr int ProjectedUnitsKey = 3076;
constexpr int VerticalTypeKey = 4096;
constexpr int VerticalUnitsKey = 4099;
constexpr int UserDefined = 32767;

struct GeoKeys
{
  std::map<int, int> Values;       // keys stored in the directory itself
  std::map<int, std::string> Text; // keys stored in the ASCII parameters

  int Get(int key) const
  {
    const auto found = this->Values.find(key);
    return found == this->Values.end() ? 0 : found->second;
  }
};

GeoKeys ParseKeys(const std::vector<unsigned char>& directory,
  const std::vector<unsigned char>& ascii)
{
  GeoKeys keys;
  if (directory.size() < 8)
  {
    return keys;
  }
  const std::size_t count = U16(directory.data() + 6);
  for (std::size_t i = 1; i <= count && 8 * i + 8 <= directory.size(); ++i)
  {
    const unsigned char* entry = directory.data() + 8 * i;
    const int key = U16(entry);
    const int location = U16(entry + 2);
    const std::size_t n = U16(entry + 4);
    const std::size_t value = U16(entry + 6);
    if (location == 0)
    {
      keys.Values[key] = static_cast<int>(value);
    }
    else if (location == 34737 && value < ascii.size())
    {
      std::string text(ascii.begin() + value, ascii.begin() + std::min(ascii.size(), value + n));
      while (!text.empty() && (text.back() == '|' || text.back() == '\0'))
      {
        text.pop_back();
      }
      keys.Text[key] = text;
    }
  }
  return keys;
}

/// EPSG projected systems whose unit is the metre (UTM zones on WGS 84,
/// NAD83 and ETRS89), for files that name the system but not the unit.
bool IsMetricProjection(int code)
{
  return (code >= 32601 && code <= 32660) || (code >= 32701 && code <= 32760) ||
    (code >= 26901 && code <= 26923) || (code >= 25828 && code <= 25838);
}

/// A WKT node: KEYWORD[value, value, CHILD[...], ...].
struct WktNode
{
  std::string Keyword;
  std::vector<std::string> Values;
  std::vector<WktNode> Children;

  const WktNode* Child(std::initializer_list<const char*> keywords) const
  {
    for (const WktNode& child : this->Children)
    {
      for (const char* keyword : keywords)
      {
        if (child.Keyword == keyword)
          return &child;
      }
    }
    return nullptr;
  }
};

class WktParser
{
public:
  explicit WktParser(const std::string& text)
    : Text(text)
  {
  }

  /// Parses a node at the current position; false on a syntax error.
  bool Node(WktNode& node, int depth = 0)
  {
    this->SkipSpace();
    while (this->At < this->Text.size() &&
      (std::isalnum(static_cast<unsigned char>(this->Text[this->At])) ||
        this->Text[this->At] == '_'))
    {
      node.Keyword +=
        static_cast<char>(std::toupper(static_cast<unsigned char>(this->Text[this->At++])));
    }
    this->SkipSpace();
    if (node.Keyword.empty() || depth > 32 || !this->Take("[("))
    {
      return false;
    }
    do
    {
      if (!this->Item(node, depth))
        return false;
    } while (this->Take(","));
    return this->Take("])");
  }

private:
  bool Item(WktNode& node, int depth)
  {
    this->SkipSpace();
    if (this->At < this->Text.size() && this->Text[this->At] == '"')
    {
      node.Values.push_back(this->Quoted());
      return true;
    }
    const std::size_t start = this->At;
    while (this->At < this->Text.size() && !std::strchr(",[]()", this->Text[this->At]))
    {
      ++this->At;
    }
    if (this->At < this->Text.size() && std::strchr("[(", this->Text[this->At]))
    {
      this->At = start;
      node.Children.emplace_back();
      return this->Node(node.Children.back(), depth + 1);
    }
    node.Values.push_back(this->Text.substr(start, this->At - start));
    return true;
  }

  std::string Quoted()
  {
    std::string value;
    for (++this->At; this->At < this->Text.size(); ++this->At)
    {
      // WKT 2 writes a quote inside a string as two quotes.
      if (this->Text[this->At] == '"' &&
        !(this->At + 1 < this->Text.size() && this->Text[this->At + 1] == '"'))
      {
        ++this->At;
        break;
      }
      if (this->Text[this->At] == '"')
        ++this->At;
      value += this->Text[this->At];
    }
    return value;
  }

  void SkipSpace()
  {
    while (this->At < this->Text.size() &&
      std::isspace(static_cast<unsigned char>(this->Text[this->At])))
      ++this->At;
  }

  bool Take(const char* any)
  {
    this->SkipSpace();
    if (this->At < this->Text.size() && this->Text[this->At] != '\0' &&
      std::strchr(any, this->Text[this->At]))
    {
      ++this->At;
      return true;
    }
    return false;
  }

  const std::string& Text;
  std::size_t At = 0;
};

/// A unit node's name, by its conversion factor to metres when it is one of
/// the common ones (files spell them "metre", "meter", "Meter", "m", ...).
std::string UnitOf(const WktNode* unit)
{
  if (!unit || unit->Values.empty())
  {
    return std::string();
  }
  if (unit->Values.size() >= 2)
  {
    const double factor = std::strtod(unit->Values[1].c_str(), nullptr);
    if (std::fabs(factor - 1.0) < 1e-12)
      return "metre";
    if (std::fabs(factor - 0.3048) < 1e-12)
      return "foot";
    if (std::fabs(factor - 1200.0 / 3937.0) < 1e-12)
      return "US survey foot";
  }
  return unit->Values[0];
}

/// The length unit of a CRS node: its own UNIT / LENGTHUNIT, else (WKT 2)
/// its first axis's.
std::string LengthUnitOf(const WktNode& crs)
{
  const WktNode* unit = crs.Child({ "UNIT", "LENGTHUNIT" });
  const WktNode* axis = crs.Child({ "AXIS" });
  if (!unit && axis)
  {
    unit = axis->Child({ "UNIT", "LENGTHUNIT" });
  }
  return UnitOf(unit);
}

bool IsGeographic(const std::string& keyword)
{
  return keyword == "GEOGCS" || keyword == "GEOGCRS" || keyword == "GEODCRS" ||
    keyword == "GEOGRAPHICCRS";
}

} // namespace

//------------------------------------------------------------------------------
std::string UnitName(int code)
{
  switch (code)
  {
    case 9001:
      return "metre";
    case 9002:
      return "foot";
    case 9003:
      return "US survey foot";
    case 9036:
      return "kilometre";
    case 9102:
      return "degree";
    default:
      return "EPSG unit " + std::to_string(code);
  }
}

//------------------------------------------------------------------------------
CoordinateSystem FromGeoKeys(const std::vector<unsigned char>& directory,
  const std::vector<unsigned char>& asciiParameters)
{
  const GeoKeys keys = ParseKeys(directory, asciiParameters);
  CoordinateSystem crs;
  const int projected = keys.Get(ProjectedTypeKey);
  const int geographic = keys.Get(GeographicTypeKey);
  if (keys.Get(ProjectedUnitsKey) != 0)
    crs.LengthUnit = UnitName(keys.Get(ProjectedUnitsKey));
  else if (IsMetricProjection(projected))
    crs.LengthUnit = "metre";
  else if (keys.Get(ModelTypeKey) == 2 || (projected == 0 && geographic != 0))
    crs.LengthUnit = "degree";
  if (keys.Get(VerticalUnitsKey) != 0)
    crs.VerticalUnit = UnitName(keys.Get(VerticalUnitsKey));

  const int horizontal = projected != 0 ? projected : geographic;
  if (horizontal != 0 && horizontal != UserDefined)
  {
    crs.Description = "EPSG:" + std::to_string(horizontal);
    const int vertical = keys.Get(VerticalTypeKey);
    if (vertical != 0 && vertical != UserDefined)
      crs.Description += "+" + std::to_string(vertical);
  }
  else
  {
    for (int key : { ProjectedCitationKey, CitationKey })
    {
      const auto text = keys.Text.find(key);
      if (crs.Description.empty() && text != keys.Text.end())
        crs.Description = text->second;
    }
    if (crs.Description.empty() && !keys.Values.empty())
      crs.Description = "user-defined (GeoTIFF keys)";
  }
  return crs;
}

//------------------------------------------------------------------------------
CoordinateSystem FromWkt(const std::string& wkt)
{
  CoordinateSystem crs;
  const std::size_t end = wkt.find('\0');
  crs.Description = wkt.substr(0, end);
  while (
    !crs.Description.empty() && std::isspace(static_cast<unsigned char>(crs.Description.back())))
  {
    crs.Description.pop_back();
  }
  WktNode root;
  WktParser parser(crs.Description);
  if (!parser.Node(root))
  {
    return crs;
  }
  const WktNode* horizontal = &root;
  const WktNode* vertical = nullptr;
  if (root.Keyword == "COMPD_CS" || root.Keyword == "COMPOUNDCRS")
  {
    horizontal =
      root.Child({ "PROJCS", "PROJCRS", "PROJECTEDCRS", "GEOGCS", "GEOGCRS", "GEODCRS" });
    vertical = root.Child({ "VERT_CS", "VERTCRS", "VERTICALCRS" });
  }
  else if (root.Keyword == "VERT_CS" || root.Keyword == "VERTCRS")
  {
    vertical = &root;
    horizontal = nullptr;
  }
  if (horizontal)
    crs.LengthUnit = IsGeographic(horizontal->Keyword) ? "degree" : LengthUnitOf(*horizontal);
  if (vertical)
    crs.VerticalUnit = LengthUnitOf(*vertical);
  return crs;
}

//------------------------------------------------------------------------------
CoordinateSystem DescribeCoordinates(const std::vector<Vlr>& records)
{
  const std::vector<unsigned char>* directory = nullptr;
  const std::vector<unsigned char>* ascii = nullptr;
  for (const Vlr& record : records)
  {
    if (record.UserId != "LASF_Projection")
      continue;
    if (record.RecordId == 2112)
      return FromWkt(std::string(record.Data.begin(), record.Data.end()));
    if (record.RecordId == 34735)
      directory = &record.Data;
    if (record.RecordId == 34737)
      ascii = &record.Data;
  }
  return directory ? FromGeoKeys(*directory, ascii ? *ascii : std::vector<unsigned char>())
                   : CoordinateSystem();
}

} // namespace las
} // namespace pcurv
