#include "FileFormats/CsvWriter.h"

#include "FileFormats/FileOutput.h"
#include "FileFormats/PlyComments.h"

namespace pcurv
{
namespace csv
{

//------------------------------------------------------------------------------
std::string WriteFile(const char* fileName, const table::Cloud& cloud)
{
  OutputFile file;
  std::string error = file.Open(fileName);
  std::string& out = file.Buffer();
  for (const auto& field : cloud.Fields)
  {
    out += "# " + ply::FormatFieldComment(field.first, field.second) + "\n";
  }
  bool firstColumn = true;
  for (const table::Array& array : cloud.Arrays)
  {
    for (const std::string& name : array.ColumnNames)
    {
      out += (firstColumn ? "" : ",") + name;
      firstColumn = false;
    }
  }
  out += "\n";
  for (std::uint64_t point = 0; point < cloud.Count && error.empty(); ++point)
  {
    bool first = true;
    for (const table::Array& array : cloud.Arrays)
    {
      for (int c = 0; c < array.Components; ++c)
      {
        out += first ? "" : ",";
        table::AppendValue(array, point * array.Components + c, out);
        first = false;
      }
    }
    out += "\n";
    error = file.FlushIfFull();
  }
  return error.empty() ? file.Close() : error;
}

} // namespace csv
} // namespace pcurv
