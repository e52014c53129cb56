#include "FileFormats/TextPointCloud.h"

#include "FileFormats/FileInput.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>

namespace pcurv
{
namespace
{

/// The index of the column with each of the names (ignoring case), or an
/// empty vector if one is missing.
std::vector<std::size_t> NamedColumns(const std::vector<std::string>& lowerNames,
  std::initializer_list<const char*> wanted)
{
  std::vector<std::size_t> found;
  for (const char* name : wanted)
  {
    const auto at = std::find(lowerNames.begin(), lowerNames.end(), name);
    if (at == lowerNames.end())
    {
      return {};
    }
    found.push_back(static_cast<std::size_t>(at - lowerNames.begin()));
  }
  return found;
}

bool IsByteColumn(const TextCloud& cloud, std::size_t column)
{
  const std::size_t rows = cloud.Rows();
  for (std::size_t row = 0; row < rows; ++row)
  {
    const double v = cloud.Values[row * cloud.Columns + column];
    if (!(v >= 0 && v <= 255 && v == std::floor(v)))
    {
      return false;
    }
  }
  return true;
}

/// Integers in 0..255, some above 1: colors (`x y z r g b`), never
/// normals. Axis-aligned unit normals (0 and 1 only) stay normals.
bool AreColors(const TextCloud& cloud, const std::vector<std::size_t>& columns)
{
  bool aboveOne = false;
  for (std::size_t column : columns)
  {
    if (!IsByteColumn(cloud, column))
    {
      return false;
    }
    for (std::size_t row = 0; row < cloud.Rows() && !aboveOne; ++row)
    {
      aboveOne = cloud.Values[row * cloud.Columns + column] > 1.0;
    }
  }
  return aboveOne;
}

/// Sets the position and normal columns: by the header's names (lower:
/// lower case), or with no header columns 3 to 5 for normals unless they
/// are colors or a PTS file's.
void ChooseGeometryColumns(const TextCloud& cloud,
  const std::vector<std::string>& lower,
  bool pts,
  bool ptsLayout,
  ColumnLayout& layout)
{
  if (!lower.empty())
  {
    std::vector<std::size_t> position = NamedColumns(lower, { "x", "y", "z" });
    if (!position.empty())
    {
      layout.Position = position;
    }
    for (auto triple : { NamedColumns(lower, { "nx", "ny", "nz" }),
           NamedColumns(lower, { "normal_x", "normal_y", "normal_z" }),
           NamedColumns(lower, { "normalx", "normaly", "normalz" }),
           NamedColumns(lower, { "n_x", "n_y", "n_z" }) })
    {
      if (!triple.empty())
      {
        layout.Normal = triple;
        break;
      }
    }
  }
  else if (cloud.Columns >= 6 && !(pts && ptsLayout) && !AreColors(cloud, { 3, 4, 5 }))
  {
    layout.Normal = { 3, 4, 5 };
  }
}

/// The columns that are neither position nor normal, in order.
std::vector<std::size_t> RemainingColumns(const TextCloud& cloud, const ColumnLayout& layout)
{
  std::vector<std::size_t> remaining;
  for (std::size_t column = 0; column < cloud.Columns; ++column)
  {
    const auto used = [column](const std::vector<std::size_t>& columns)
    { return std::find(columns.begin(), columns.end(), column) != columns.end(); };
    if (!used(layout.Position) && !used(layout.Normal))
    {
      remaining.push_back(column);
    }
  }
  return remaining;
}

/// Whether the columns are three, each of integers in 0..255.
bool AreByteTriple(const TextCloud& cloud, const std::vector<std::size_t>& columns)
{
  return columns.size() == 3 &&
    std::all_of(columns.begin(),
      columns.end(),
      [&cloud](std::size_t column) { return IsByteColumn(cloud, column); });
}

/// Sets the color columns among the remaining ones: named r g b (or red
/// green blue), or with no header the last three, if they hold bytes.
void ChooseColorColumns(const TextCloud& cloud,
  const std::vector<std::string>& lower,
  const std::vector<std::size_t>& remaining,
  bool pts,
  bool ptsLayout,
  ColumnLayout& layout)
{
  if (!lower.empty())
  {
    for (auto triple :
      { NamedColumns(lower, { "r", "g", "b" }), NamedColumns(lower, { "red", "green", "blue" }) })
    {
      const bool free = std::all_of(triple.begin(),
        triple.end(),
        [&remaining](std::size_t c)
        { return std::find(remaining.begin(), remaining.end(), c) != remaining.end(); });
      if (free && AreByteTriple(cloud, triple))
      {
        layout.Color = triple;
        break;
      }
    }
  }
  else if (remaining.size() == 3 || (pts && ptsLayout && remaining.size() == 4))
  {
    std::vector<std::size_t> last(remaining.end() - 3, remaining.end());
    if (AreByteTriple(cloud, last))
    {
      layout.Color = last;
    }
  }
}

/// Makes the remaining columns that are not colors scalars, each named
/// after its header word (or Intensity, or Column_<index>) and unique.
void NameScalarColumns(const TextCloud& cloud,
  const std::vector<std::size_t>& remaining,
  bool pts,
  bool ptsLayout,
  ColumnLayout& layout)
{
  // Array names in use: a header column named like one gets its index too.
  std::vector<std::string> used;
  if (!layout.Normal.empty())
  {
    used.emplace_back("Normals");
  }
  if (!layout.Color.empty())
  {
    used.emplace_back("RGB");
  }
  for (std::size_t column : remaining)
  {
    if (std::find(layout.Color.begin(), layout.Color.end(), column) != layout.Color.end())
    {
      continue;
    }
    std::string name;
    if (!cloud.Names.empty())
    {
      name = cloud.Names[column];
    }
    else if (pts && ptsLayout && column == 3)
    {
      name = "Intensity";
    }
    else
    {
      name = "Column_" + std::to_string(column);
    }
    if (name.empty() || std::find(used.begin(), used.end(), name) != used.end())
    {
      name += "_" + std::to_string(column);
    }
    used.push_back(name);
    layout.Scalars.emplace_back(column, name);
  }
}

} // namespace

//------------------------------------------------------------------------------
ColumnLayout ChooseColumnLayout(const TextCloud& cloud, bool pts)
{
  ColumnLayout layout;
  // Leica PTS: x y z intensity [r g b], colors integers in 0..255.
  const bool ptsLayout = cloud.Columns == 4 ||
    (cloud.Columns == 7 && IsByteColumn(cloud, 4) && IsByteColumn(cloud, 5) &&
      IsByteColumn(cloud, 6));
  std::vector<std::string> lower;
  for (const std::string& name : cloud.Names)
  {
    lower.push_back(LowerCase(name));
  }
  ChooseGeometryColumns(cloud, lower, pts, ptsLayout, layout);
  const std::vector<std::size_t> remaining = RemainingColumns(cloud, layout);
  ChooseColorColumns(cloud, lower, remaining, pts, ptsLayout, layout);
  NameScalarColumns(cloud, remaining, pts, ptsLayout, layout);
  return layout;
}

//------------------------------------------------------------------------------
std::vector<std::size_t> NonFinitePositionLines(const TextCloud& cloud, const ColumnLayout& layout)
{
  std::vector<std::size_t> lines;
  for (const auto& row : cloud.NonFiniteRows)
  {
    const double* values = cloud.Values.data() + row.first * cloud.Columns;
    const bool bad = std::any_of(layout.Position.begin(),
      layout.Position.end(),
      [values](std::size_t column) { return !std::isfinite(values[column]); });
    if (bad)
    {
      lines.push_back(row.second);
    }
  }
  return lines;
}

} // namespace pcurv
