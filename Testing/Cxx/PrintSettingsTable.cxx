// Prints the one table of settings (Core/Settings/SettingsTable.h) as JSON,
// for the checks and the docs that cannot include C++:
//   PrintSettingsTable > settings.json
#include "Settings/SettingsTable.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>

namespace
{
std::string Quoted(const char* text)
{
  std::string out = "\"";
  for (const char* c = text; c && *c; ++c)
  {
    if (*c == '"' || *c == '\\')
    {
      out += '\\';
    }
    out += *c;
  }
  return out + "\"";
}

const char* TypeName(pcurv::SettingType type)
{
  switch (type)
  {
    case pcurv::SettingType::Bool:
      return "bool";
    case pcurv::SettingType::Int:
      return "int";
    case pcurv::SettingType::Enum:
      return "enum";
    case pcurv::SettingType::Double:
      return "double";
    case pcurv::SettingType::Double3:
      return "double3";
  }
  return "";
}

/// A bound as JSON: the largest doubles as null (no bound).
std::string Bound(double value)
{
  if (std::fabs(value) == std::numeric_limits<double>::max())
  {
    return "null";
  }
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}
} // namespace

int main()
{
  std::cout.precision(17);
  std::cout << "[\n";
  for (std::size_t i = 0; i < pcurv::settings::Count; ++i)
  {
    const pcurv::SettingSpec& s = pcurv::settings::Table[i];
    const int components = s.Type == pcurv::SettingType::Double3 ? 3 : 1;
    std::cout << "  {\"name\": " << Quoted(s.Name) << ", \"normals_name\": "
              << (s.NormalsName ? Quoted(s.NormalsName) : std::string("null"))
              << ", \"group\": " << Quoted(s.Group) << ", \"type\": \"" << TypeName(s.Type)
              << "\", \"default\": [";
    for (int c = 0; c < components; ++c)
    {
      std::cout << (c ? ", " : "") << s.Default[c];
    }
    std::cout << "], \"minimum\": " << Bound(s.Minimum) << ", \"maximum\": " << Bound(s.Maximum)
              << ", \"unit\": " << Quoted(s.Unit) << ", \"choices\": " << Quoted(s.Choices)
              << ", \"doc\": " << Quoted(s.Doc) << "}"
              << (i + 1 < pcurv::settings::Count ? "," : "") << "\n";
  }
  std::cout << "]\n";
  return 0;
}
