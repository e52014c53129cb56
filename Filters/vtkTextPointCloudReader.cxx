#include "vtkTextPointCloudReader.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkTextPointCloudReader);

namespace
{

using Token = std::pair<const char*, const char*>;

/// The numbers of the data lines, row by row, and what came before them.
struct TextCloud
{
  std::size_t Columns = 0;
  std::vector<double> Values;     // Rows() x Columns, row major
  std::vector<std::string> Names; // the header's column names, or empty
  std::size_t HeaderLine = 0;
  std::size_t FirstDataLine = 0;

  std::size_t Rows() const { return this->Columns ? this->Values.size() / this->Columns : 0; }
};

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

std::string Quoted(const Token& token)
{
  std::string word(token.first, std::min<std::size_t>(token.second - token.first, 40));
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

std::string Lower(std::string text)
{
  std::transform(text.begin(),
    text.end(),
    text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

/**
 * Reads the lines of [data, data + size) into cloud. Returns an empty string
 * on success, else "line N: what is wrong". With firstRowOnly, stops after
 * the first data line (for CanReadFile).
 */
std::string ParseText(const char* data,
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
  // Reserve for as many rows as the buffer has lines.
  const std::size_t lines = static_cast<std::size_t>(std::count(p, end, '\n')) + 1;
  bool firstLine = true;
  std::vector<Token> tokens;
  std::size_t lineNumber = 0;
  while (p < end)
  {
    const char* lineEnd = static_cast<const char*>(std::memchr(p, '\n', end - p));
    if (!lineEnd)
    {
      lineEnd = end;
    }
    ++lineNumber;
    Tokenize(p, lineEnd, tokens);
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
      continue;
    }
    if (beforeData)
    {
      if (tokens.size() < 3)
      {
        return "line " + std::to_string(lineNumber) + ": " + std::to_string(tokens.size()) +
          " number(s); a point needs at least x y z";
      }
      if (!cloud.Names.empty() && cloud.Names.size() != tokens.size())
      {
        return "line " + std::to_string(lineNumber) + ": " + std::to_string(tokens.size()) +
          " columns, but the header (line " + std::to_string(cloud.HeaderLine) + ") names " +
          std::to_string(cloud.Names.size());
      }
      cloud.Columns = tokens.size();
      cloud.FirstDataLine = lineNumber;
      cloud.Values.reserve(firstRowOnly ? cloud.Columns : lines * cloud.Columns);
    }
    else if (tokens.size() != cloud.Columns)
    {
      return "line " + std::to_string(lineNumber) + ": " + std::to_string(tokens.size()) +
        " columns, but line " + std::to_string(cloud.FirstDataLine) + " has " +
        std::to_string(cloud.Columns);
    }
    for (const Token& token : tokens)
    {
      if (!ParseNumber(token.first, token.second, value))
      {
        return "line " + std::to_string(lineNumber) + ": " + Quoted(token) + " is not a number";
      }
      cloud.Values.push_back(value);
    }
    if (firstRowOnly)
    {
      break;
    }
  }
  if (cloud.Columns == 0)
  {
    return "no points (no line of numbers in " + std::to_string(lineNumber) + " lines)";
  }
  return std::string();
}

/// The whole file in buffer, or false with the reason in error.
bool ReadFile(const char* fileName, std::size_t limit, std::string& buffer, std::string& error)
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

std::string Extension(const char* fileName)
{
  const std::string name(fileName);
  const std::size_t dot = name.find_last_of('.');
  const std::size_t slash = name.find_last_of("/\\");
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
  {
    return std::string();
  }
  return Lower(name.substr(dot + 1));
}

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

/// What each column of the file becomes.
struct Layout
{
  std::vector<std::size_t> Position = { 0, 1, 2 };
  std::vector<std::size_t> Normal;                          // 3 columns or none
  std::vector<std::size_t> Colour;                          // 3 columns or none
  std::vector<std::pair<std::size_t, std::string>> Scalars; // the others, named
};

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

/// Integers in 0..255, some above 1: colours (`x y z r g b`), never
/// normals. Axis-aligned unit normals (0 and 1 only) stay normals.
bool AreColours(const TextCloud& cloud, const std::vector<std::size_t>& columns)
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

Layout ChooseLayout(const TextCloud& cloud, bool pts)
{
  Layout layout;
  // Leica PTS: x y z intensity [r g b], colours integers in 0..255.
  const bool ptsLayout = cloud.Columns == 4 ||
    (cloud.Columns == 7 && IsByteColumn(cloud, 4) && IsByteColumn(cloud, 5) &&
      IsByteColumn(cloud, 6));
  std::vector<std::string> lower;
  for (const std::string& name : cloud.Names)
  {
    lower.push_back(Lower(name));
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
  else if (cloud.Columns >= 6 && !(pts && ptsLayout) && !AreColours(cloud, { 3, 4, 5 }))
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
        layout.Colour = triple;
        break;
      }
    }
  }
  else if (remaining.size() == 3 || (pts && ptsLayout && remaining.size() == 4))
  {
    std::vector<std::size_t> last(remaining.end() - 3, remaining.end());
    if (bytes(last))
    {
      layout.Colour = last;
    }
  }
  // Array names in use: a header column named like one gets its index too.
  std::vector<std::string> used;
  if (!layout.Normal.empty())
  {
    used.emplace_back("Normals");
  }
  if (!layout.Colour.empty())
  {
    used.emplace_back("RGB");
  }
  for (std::size_t column : remaining)
  {
    if (std::find(layout.Colour.begin(), layout.Colour.end(), column) != layout.Colour.end())
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

/// Rows [begin, end) of the given columns as an array of doubles.
vtkSmartPointer<vtkDoubleArray> DoubleColumns(const TextCloud& cloud,
  const std::vector<std::size_t>& columns,
  std::size_t begin,
  std::size_t end,
  const char* name)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  const int components = static_cast<int>(columns.size());
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(static_cast<vtkIdType>(end - begin));
  if (name)
  {
    array->SetName(name);
  }
  double* out = array->GetPointer(0);
  const double* in = cloud.Values.data();
  for (std::size_t row = begin; row < end; ++row)
  {
    for (std::size_t c : columns)
    {
      *out++ = in[row * cloud.Columns + c];
    }
  }
  return array;
}

} // namespace

//------------------------------------------------------------------------------
vtkTextPointCloudReader::vtkTextPointCloudReader()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkTextPointCloudReader::~vtkTextPointCloudReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
int vtkTextPointCloudReader::CanReadFile(const char* fileName)
{
  if (!fileName || !*fileName)
  {
    return 0;
  }
  std::string buffer, error;
  if (!ReadFile(fileName, 1 << 16, buffer, error))
  {
    return 0;
  }
  TextCloud cloud;
  return ParseText(buffer.data(), buffer.size(), Extension(fileName) == "pts", true, cloud).empty()
    ? 1
    : 0;
}

//------------------------------------------------------------------------------
int vtkTextPointCloudReader::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  outputVector->GetInformationObject(0)->Set(vtkAlgorithm::CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkTextPointCloudReader::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outInfo);
  if (!output)
  {
    return 0;
  }
  this->SetErrorCode(vtkErrorCode::NoError);
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro(<< "No FileName to read.");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return 1;
  }
  const bool pts = Extension(this->FileName) == "pts";
  try
  {
    TextCloud cloud;
    {
      std::string buffer, error;
      if (!ReadFile(this->FileName, static_cast<std::size_t>(-1), buffer, error))
      {
        vtkErrorMacro(<< this->FileName << ": cannot read the file: " << error);
        this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
        return 1;
      }
      error = ParseText(buffer.data(), buffer.size(), pts, false, cloud);
      if (!error.empty())
      {
        vtkErrorMacro(<< this->FileName << ": " << error);
        this->SetErrorCode(vtkErrorCode::FileFormatError);
        return 1;
      }
    }
    cloud.Values.shrink_to_fit();
    const Layout layout = ChooseLayout(cloud, pts);

    // This piece's consecutive range of the rows.
    const std::size_t rows = cloud.Rows();
    int piece = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER());
    int pieces = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES());
    if (pieces < 1 || piece < 0 || piece >= pieces)
    {
      piece = 0;
      pieces = 1;
    }
    const std::size_t begin = rows * piece / pieces;
    const std::size_t end = rows * (piece + 1) / pieces;
    const vtkIdType count = static_cast<vtkIdType>(end - begin);

    vtkNew<vtkPoints> points;
    points->SetData(DoubleColumns(cloud, layout.Position, begin, end, nullptr));
    output->SetPoints(points);

    vtkNew<vtkIdTypeArray> offsets, connectivity;
    offsets->SetNumberOfValues(count + 1);
    connectivity->SetNumberOfValues(count);
    for (vtkIdType i = 0; i < count; ++i)
    {
      offsets->SetValue(i, i);
      connectivity->SetValue(i, i);
    }
    offsets->SetValue(count, count);
    vtkNew<vtkCellArray> vertices;
    vertices->SetData(offsets, connectivity);
    output->SetVerts(vertices);

    vtkPointData* pointData = output->GetPointData();
    if (!layout.Normal.empty())
    {
      pointData->SetNormals(DoubleColumns(cloud, layout.Normal, begin, end, "Normals"));
    }
    if (!layout.Colour.empty())
    {
      vtkNew<vtkUnsignedCharArray> colours;
      colours->SetName("RGB");
      colours->SetNumberOfComponents(3);
      colours->SetNumberOfTuples(count);
      unsigned char* out = colours->GetPointer(0);
      for (std::size_t row = begin; row < end; ++row)
      {
        for (std::size_t c : layout.Colour)
        {
          *out++ = static_cast<unsigned char>(cloud.Values[row * cloud.Columns + c]);
        }
      }
      pointData->SetScalars(colours);
    }
    for (const auto& scalar : layout.Scalars)
    {
      pointData->AddArray(
        DoubleColumns(cloud, { scalar.first }, begin, end, scalar.second.c_str()));
    }
  }
  catch (const std::bad_alloc&)
  {
    output->Initialize();
    vtkErrorMacro(<< this->FileName << ": out of memory");
    this->SetErrorCode(vtkErrorCode::UnknownError);
    return 1;
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkTextPointCloudReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
