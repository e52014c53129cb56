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

/// Why [p, end), the buffer after any byte order mark, is no text cloud
/// (empty, or holding a NUL byte), or an empty string.
std::string NotTextReason(const char* data, const char* p, const char* end)
{
  if (p == end)
  {
    return "the file is empty: no points";
  }
  if (const char* zero = static_cast<const char*>(std::memchr(p, '\0', end - p)))
  {
    const std::size_t line = static_cast<std::size_t>(std::count(p, zero, '\n')) + 1;
    return AtLine(line) + "a NUL byte (byte " + std::to_string(zero - data) + "): not a text file";
  }
  return std::string();
}

/// Takes the words of line lineNumber for the header of column names.
void ReadHeader(const std::vector<Token>& tokens,
  std::size_t lineNumber,
  TextCloud& cloud,
  std::string& header)
{
  for (const Token& token : tokens)
  {
    cloud.Names.push_back(ColumnName(token));
  }
  cloud.HeaderLine = lineNumber;
  header = Quoted(Token(tokens.front().first, tokens.back().second));
}

/// Checks the first data line and sets the cloud's column count from it;
/// what is wrong with the line, or an empty string.
std::string StartData(const std::vector<Token>& tokens,
  std::size_t lineNumber,
  std::size_t lines,
  bool firstRowOnly,
  const std::string& header,
  TextCloud& cloud)
{
  double value;
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
    return AtLine(lineNumber) + std::to_string(tokens.size()) + " columns, but the header (line " +
      std::to_string(cloud.HeaderLine) + ") names " + std::to_string(cloud.Names.size());
  }
  cloud.Columns = tokens.size();
  cloud.FirstDataLine = lineNumber;
  cloud.Values.reserve(firstRowOnly ? cloud.Columns : lines * cloud.Columns);
  return std::string();
}

/// Checks a data line's column count; the first data line sets it (see
/// StartData). What is wrong with the line, or an empty string.
std::string CheckDataLine(const std::vector<Token>& tokens,
  std::size_t lineNumber,
  std::size_t lines,
  bool firstRowOnly,
  const std::string& header,
  TextCloud& cloud)
{
  if (cloud.Columns == 0)
  {
    return StartData(tokens, lineNumber, lines, firstRowOnly, header, cloud);
  }
  if (tokens.size() != cloud.Columns)
  {
    return AtLine(lineNumber) + std::to_string(tokens.size()) + " columns, but line " +
      std::to_string(cloud.FirstDataLine) + " has " + std::to_string(cloud.Columns);
  }
  return std::string();
}

/// Appends the numbers of data line lineNumber to the cloud, noting a row
/// with a NaN or infinite one; a word that is not a number, or an empty
/// string.
std::string AppendRow(const std::vector<Token>& tokens, std::size_t lineNumber, TextCloud& cloud)
{
  double value;
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
  return std::string();
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
  const std::string notText = NotTextReason(data, p, end);
  if (!notText.empty())
  {
    return notText;
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
      ReadHeader(tokens, lineNumber, cloud, header);
      continue;
    }
    std::string error = CheckDataLine(tokens, lineNumber, lines, firstRowOnly, header, cloud);
    if (error.empty())
    {
      error = AppendRow(tokens, lineNumber, cloud);
    }
    if (!error.empty())
    {
      return error;
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

} // namespace pcurv
