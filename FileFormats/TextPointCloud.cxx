#include "FileFormats/TextPointCloud.h"

#include "FileFormats/FileInput.h"
#include "FileFormats/PlyComments.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <initializer_list>

namespace pcurv
{
namespace
{

using Token = std::pair<const char*, const char*>;

inline bool IsSeparator(char c)
{
  return c == ' ' || c == '\t' || c == ',' || c == ';' || c == '\r' || c == '\v' || c == '\f';
}

inline bool StartsComment(const char* p, const char* end)
{
  return *p == '#' || (*p == '/' && p + 1 < end && p[1] == '/');
}

/// The words of the line [p, end) before any comment, in tokens.
void Tokenize(const char* p, const char* end, std::vector<Token>& tokens)
{
  tokens.clear();
  while (p < end)
  {
    while (p < end && IsSeparator(*p))
    {
      ++p;
    }
    if (p == end || StartsComment(p, end))
    {
      return;
    }
    const char* begin = p;
    while (p < end && !IsSeparator(*p) && !StartsComment(p, end))
    {
      ++p;
    }
    tokens.emplace_back(begin, p);
  }
}

/// Parses the whole of [begin, end) as a number (a leading '+' allowed).
bool ParseNumber(const char* begin, const char* end, double& value)
{
  const char* p = begin;
  if (p < end && *p == '+')
  {
    ++p; // std::from_chars takes no plus sign
  }
  if (p == end || (p != begin && *p == '-'))
  {
    return false;
  }
  const std::from_chars_result result = std::from_chars(p, end, value);
  if (result.ptr != end)
  {
    return false;
  }
  if (result.ec == std::errc::result_out_of_range)
  {
    // Beyond the double range: what strtod makes of it (+-HUGE_VAL or a
    // denormal / zero), as other readers do.
    const std::string copy(begin, end);
    value = std::strtod(copy.c_str(), nullptr);
    return true;
  }
  return result.ec == std::errc();
}

bool IsCount(const Token& token)
{
  const std::size_t length = token.second - token.first;
  return length > 0 && length < 19 &&
    std::all_of(token.first, token.second, [](char c) { return c >= '0' && c <= '9'; });
}

/// The word in quotes, cut at 40 characters, bytes that are not printable
/// ASCII as \xNN (an error message must stay readable whatever the file).
std::string Quoted(const Token& token)
{
  static const char hex[] = "0123456789abcdef";
  std::string word;
  const std::size_t length = std::min<std::size_t>(token.second - token.first, 40);
  for (std::size_t i = 0; i < length; ++i)
  {
    const unsigned char c = static_cast<unsigned char>(token.first[i]);
    if (c >= 0x20 && c < 0x7f)
    {
      word += static_cast<char>(c);
    }
    else
    {
      word += std::string("\\x") + hex[c >> 4] + hex[c & 15];
    }
  }
  return "'" + word + (token.second - token.first > 40 ? "...'" : "'");
}

/// A header word without surrounding double quotes (as some CSV files have).
std::string ColumnName(const Token& token)
{
  std::string name(token.first, token.second);
  if (name.size() >= 2 && name.front() == '"' && name.back() == '"')
  {
    name = name.substr(1, name.size() - 2);
  }
  return name;
}

std::string AtLine(std::size_t line)
{
  return "line " + std::to_string(line) + ": ";
}

/// Why a file gave no line of numbers, from what its lines were.
std::string NoPointsReason(const TextCloud& cloud,
  std::size_t lines,
  std::size_t countLine,
  const std::string& header)
{
  if (cloud.HeaderLine)
  {
    return AtLine(cloud.HeaderLine) + header +
      " is not numbers (taken for a header of column names) and no line of numbers follows: "
      "no points";
  }
  if (countLine)
  {
    return AtLine(countLine) + "only a point count, and no line of numbers follows: no points";
  }
  return "no points: its " + std::to_string(lines) + " line(s) are blank or comments";
}

} // namespace

//------------------------------------------------------------------------------
bool LooksLikePlot3d(const char* data, std::size_t size)
{
  if (size < 16 || !std::memchr(data, '\0', size))
  {
    return false;
  }
  for (bool swap : { false, true })
  {
    const auto word = [data, swap](std::size_t at)
    {
      unsigned char b[4];
      std::memcpy(b, data + at, 4);
      if (swap)
      {
        std::swap(b[0], b[3]);
        std::swap(b[1], b[2]);
      }
      // Assembled little endian first; `swap` reads big endian.
      return static_cast<std::int64_t>(static_cast<std::int32_t>(
        b[0] | (b[1] << 8) | (b[2] << 16) | (static_cast<std::uint32_t>(b[3]) << 24)));
    };
    const std::int64_t first = word(0);
    const bool record = first >= 4 && first <= 64 && first % 4 == 0 &&
      size >= static_cast<std::size_t>(first) + 8 &&
      word(static_cast<std::size_t>(first) + 4) == first;
    const auto small = [](std::int64_t v) { return v >= 1 && v <= 1000000; };
    if (record || (small(first) && small(word(4)) && small(word(8))))
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
bool LooksLikeMolecule(const char* data, std::size_t size)
{
  // XYZ molecule files: "N", a free comment line, then "Symbol x y z" lines.
  std::vector<Token> tokens;
  const char* p = data;
  const char* const end = data + size;
  for (int line = 0; line < 3 && p < end; ++line)
  {
    const char* lineEnd = static_cast<const char*>(std::memchr(p, '\n', end - p));
    lineEnd = lineEnd ? lineEnd : end;
    Tokenize(p, lineEnd, tokens);
    p = lineEnd + 1;
    if (line == 0 && !(tokens.size() == 1 && IsCount(tokens[0])))
    {
      return false;
    }
    if (line == 2)
    {
      double value;
      return tokens.size() >= 4 && std::isalpha(static_cast<unsigned char>(*tokens[0].first)) &&
        tokens[0].second - tokens[0].first <= 3 &&
        ParseNumber(tokens[1].first, tokens[1].second, value) &&
        ParseNumber(tokens[2].first, tokens[2].second, value) &&
        ParseNumber(tokens[3].first, tokens[3].second, value);
    }
  }
  return false;
}

//------------------------------------------------------------------------------
std::string ParseTextCloud(const char* data,
  std::size_t size,
  bool pts,
  bool firstRowOnly,
  TextCloud& cloud)
{
  const char* p = data;
  const char* const end = data + size;
  if (size >= 3 && std::memcmp(p, "\xEF\xBB\xBF", 3) == 0)
  {
    p += 3; // UTF-8 byte order mark
  }
  if (p == end)
  {
    return "the file is empty: no points";
  }
  if (const char* zero = static_cast<const char*>(std::memchr(p, '\0', end - p)))
  {
    const std::size_t line = static_cast<std::size_t>(std::count(p, zero, '\n')) + 1;
    return AtLine(line) + "a NUL byte (byte " + std::to_string(zero - data) + "): not a text file";
  }
  // Reserve for as many rows as the buffer has lines.
  const std::size_t lines = static_cast<std::size_t>(std::count(p, end, '\n')) + 1;
  bool firstLine = true;
  std::vector<Token> tokens;
  std::size_t lineNumber = 0;
  std::size_t countLine = 0;
  std::string header; // the header line's start, quoted, for messages
  std::string fieldName, fieldValue;
  while (p < end)
  {
    const char* lineEnd = static_cast<const char*>(std::memchr(p, '\n', end - p));
    if (!lineEnd)
    {
      lineEnd = end;
    }
    ++lineNumber;
    Tokenize(p, lineEnd, tokens);
    if (tokens.empty() && cloud.Columns == 0 &&
      ply::ParseFieldCommentLine(p, lineEnd, fieldName, fieldValue))
    {
      cloud.Fields.emplace_back(fieldName, fieldValue);
    }
    p = lineEnd + 1;
    if (tokens.empty())
    {
      continue;
    }
    const bool beforeData = cloud.Columns == 0;
    // A point count: the first line of a PTS file (every scan's, in .pts).
    if (tokens.size() == 1 && IsCount(tokens[0]) && ((beforeData && firstLine) || pts))
    {
      firstLine = false;
      countLine = countLine ? countLine : lineNumber;
      continue;
    }
    firstLine = false;
    double value;
    if (beforeData && cloud.Names.empty() && !ParseNumber(tokens[0].first, tokens[0].second, value))
    {
      // A header of column names.
      for (const Token& token : tokens)
      {
        cloud.Names.push_back(ColumnName(token));
      }
      cloud.HeaderLine = lineNumber;
      header = Quoted(Token(tokens.front().first, tokens.back().second));
      continue;
    }
    if (beforeData)
    {
      // Words first: "2 numbers" would mislead about a line of words.
      for (const Token& token : tokens)
      {
        if (!ParseNumber(token.first, token.second, value))
        {
          return AtLine(lineNumber) + Quoted(token) + " is not a number" +
            (cloud.HeaderLine ? " (line " + std::to_string(cloud.HeaderLine) + ", " + header +
                  ", was taken for a header of column names)"
                              : std::string());
        }
      }
      if (tokens.size() < 3)
      {
        return AtLine(lineNumber) + std::to_string(tokens.size()) +
          " number(s); a point needs at least x y z";
      }
      if (!cloud.Names.empty() && cloud.Names.size() != tokens.size())
      {
        return AtLine(lineNumber) + std::to_string(tokens.size()) +
          " columns, but the header (line " + std::to_string(cloud.HeaderLine) + ") names " +
          std::to_string(cloud.Names.size());
      }
      cloud.Columns = tokens.size();
      cloud.FirstDataLine = lineNumber;
      cloud.Values.reserve(firstRowOnly ? cloud.Columns : lines * cloud.Columns);
    }
    else if (tokens.size() != cloud.Columns)
    {
      return AtLine(lineNumber) + std::to_string(tokens.size()) + " columns, but line " +
        std::to_string(cloud.FirstDataLine) + " has " + std::to_string(cloud.Columns);
    }
    bool finite = true;
    for (const Token& token : tokens)
    {
      if (!ParseNumber(token.first, token.second, value))
      {
        return AtLine(lineNumber) + Quoted(token) + " is not a number";
      }
      finite = finite && std::isfinite(value);
      cloud.Values.push_back(value);
    }
    if (!finite)
    {
      cloud.NonFiniteRows.emplace_back(cloud.Rows() - 1, lineNumber);
    }
    if (firstRowOnly)
    {
      break;
    }
  }
  if (cloud.Columns == 0)
  {
    return NoPointsReason(cloud, lineNumber, countLine, header);
  }
  return std::string();
}

//------------------------------------------------------------------------------
bool ReadTextFile(const char* fileName, std::size_t limit, std::string& buffer, std::string& error)
{
  std::FILE* file = std::fopen(fileName, "rb");
  if (!file)
  {
    error = std::strerror(errno);
    return false;
  }
  if (std::fseek(file, 0, SEEK_END) == 0)
  {
    const long size = std::ftell(file);
    if (size > 0)
    {
      buffer.reserve(std::min<std::size_t>(static_cast<std::size_t>(size), limit));
    }
    std::fseek(file, 0, SEEK_SET);
  }
  char chunk[1 << 16];
  while (buffer.size() < limit)
  {
    const std::size_t got =
      std::fread(chunk, 1, std::min<std::size_t>(sizeof(chunk), limit - buffer.size()), file);
    buffer.append(chunk, got);
    if (got == 0)
    {
      break;
    }
  }
  const bool failed = std::ferror(file) != 0;
  if (failed)
  {
    error = std::strerror(errno);
  }
  std::fclose(file);
  return !failed;
}

//------------------------------------------------------------------------------
std::string LowerExtension(const char* fileName)
{
  const std::string name(fileName);
  const std::size_t dot = name.find_last_of('.');
  const std::size_t slash = name.find_last_of("/\\");
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
  {
    return std::string();
  }
  return LowerCase(name.substr(dot + 1));
}

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
  const auto bytes = [&cloud](const std::vector<std::size_t>& columns)
  {
    return columns.size() == 3 &&
      std::all_of(columns.begin(),
        columns.end(),
        [&cloud](std::size_t column) { return IsByteColumn(cloud, column); });
  };
  if (!lower.empty())
  {
    for (auto triple :
      { NamedColumns(lower, { "r", "g", "b" }), NamedColumns(lower, { "red", "green", "blue" }) })
    {
      const bool free = std::all_of(triple.begin(),
        triple.end(),
        [&remaining](std::size_t c)
        { return std::find(remaining.begin(), remaining.end(), c) != remaining.end(); });
      if (free && bytes(triple))
      {
        layout.Color = triple;
        break;
      }
    }
  }
  else if (remaining.size() == 3 || (pts && ptsLayout && remaining.size() == 4))
  {
    std::vector<std::size_t> last(remaining.end() - 3, remaining.end());
    if (bytes(last))
    {
      layout.Color = last;
    }
  }
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
