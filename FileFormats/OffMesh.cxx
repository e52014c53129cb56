#include "FileFormats/OffMesh.h"

#include <algorithm>
#include <charconv>
#include <cstring>

namespace pcurv
{
namespace
{

/// The lines of a text, their words split at white space, '#' comments cut.
class LineReader
{
public:
  LineReader(const char* data, std::size_t size)
    : P(data)
    , End(data + size)
  {
  }

  /// The next line holding a word, in words; false at the end of the text.
  bool Next(std::vector<std::string>& words)
  {
    while (this->P < this->End)
    {
      const char* lineEnd =
        static_cast<const char*>(std::memchr(this->P, '\n', this->End - this->P));
      lineEnd = lineEnd ? lineEnd : this->End;
      ++this->Line;
      words.clear();
      const char* p = this->P;
      this->P = lineEnd + 1;
      while (p < lineEnd && *p != '#')
      {
        while (p < lineEnd && (*p == ' ' || *p == '\t' || *p == '\r'))
        {
          ++p;
        }
        const char* begin = p;
        while (p < lineEnd && *p != ' ' && *p != '\t' && *p != '\r' && *p != '#')
        {
          ++p;
        }
        if (p > begin)
        {
          words.emplace_back(begin, p);
        }
      }
      if (!words.empty())
      {
        return true;
      }
    }
    return false;
  }

  std::string At() const { return "line " + std::to_string(this->Line) + ": "; }

private:
  const char* P;
  const char* End;
  std::size_t Line = 0;
};

bool ToDouble(const std::string& word, double& value)
{
  const char* begin = word.data() + (!word.empty() && word[0] == '+' ? 1 : 0);
  const auto result = std::from_chars(begin, word.data() + word.size(), value);
  return result.ec == std::errc() && result.ptr == word.data() + word.size();
}

bool ToCount(const std::string& word, std::int64_t& value)
{
  const auto result = std::from_chars(word.data(), word.data() + word.size(), value);
  return result.ec == std::errc() && result.ptr == word.data() + word.size() && value >= 0;
}

std::string Quoted(const std::string& word)
{
  return "'" + word.substr(0, 40) + (word.size() > 40 ? "...'" : "'");
}

/// Reads the vertex lines' x y z into mesh.Points; what is wrong, or an
/// empty string.
std::string ReadVertices(LineReader& lines,
  std::vector<std::string>& words,
  std::int64_t vertices,
  OffMesh& mesh)
{
  for (std::int64_t v = 0; v < vertices; ++v)
  {
    if (!lines.Next(words))
    {
      return "the file ends after " + std::to_string(v) + " of its " + std::to_string(vertices) +
        " vertices";
    }
    if (words.size() < 3)
    {
      return lines.At() + "vertex " + std::to_string(v) + ": " + std::to_string(words.size()) +
        " number(s); a vertex needs x y z";
    }
    for (int c = 0; c < 3; ++c)
    {
      double value;
      if (!ToDouble(words[c], value))
      {
        return lines.At() + "vertex " + std::to_string(v) + ": " + Quoted(words[c]) +
          " is not a number";
      }
      mesh.Points.push_back(value);
    }
  }
  return std::string();
}

/// Reads the face lines into mesh.Connectivity and mesh.Offsets; what is
/// wrong, or an empty string.
std::string ReadFaces(LineReader& lines,
  std::vector<std::string>& words,
  std::int64_t vertices,
  std::int64_t faces,
  OffMesh& mesh)
{
  for (std::int64_t f = 0; f < faces; ++f)
  {
    if (!lines.Next(words))
    {
      return "the file ends after " + std::to_string(f) + " of its " + std::to_string(faces) +
        " faces";
    }
    std::int64_t n = 0;
    if (!ToCount(words[0], n) || n < 3 || static_cast<std::size_t>(n) + 1 > words.size())
    {
      return lines.At() + "face " + std::to_string(f) + ": '" + words[0] + "' then " +
        std::to_string(words.size() - 1) +
        " word(s); a face is its vertex count (at least 3), then as many vertex indices";
    }
    for (std::int64_t i = 1; i <= n; ++i)
    {
      std::int64_t index = 0;
      if (!ToCount(words[i], index) || index >= vertices)
      {
        return lines.At() + "face " + std::to_string(f) + ": " + Quoted(words[i]) +
          " is not a vertex index (0 to " + std::to_string(vertices - 1) + ")";
      }
      mesh.Connectivity.push_back(index);
    }
    mesh.Offsets.push_back(static_cast<std::int64_t>(mesh.Connectivity.size()));
  }
  return std::string();
}

} // namespace

//------------------------------------------------------------------------------
std::string ParseOffMesh(const char* data, std::size_t size, OffMesh& mesh)
{
  LineReader lines(data, size);
  std::vector<std::string> words;
  if (!lines.Next(words))
  {
    return "the file is empty (no OFF header)";
  }
  const std::string& header = words[0];
  if (header.size() < 3 || header.compare(header.size() - 3, 3, "OFF") != 0)
  {
    return lines.At() + Quoted(header) + " where the OFF header belongs: not an OFF file";
  }
  if (words.size() > 1 && words[1] == "BINARY")
  {
    return lines.At() + "binary OFF, which this reader does not read (only text OFF)";
  }
  words.erase(words.begin());
  if (words.empty() && !lines.Next(words))
  {
    return lines.At() +
      "the file ends after the header: the counts 'vertices faces edges' are missing";
  }
  std::int64_t vertices = 0, faces = 0;
  if (words.size() < 2 || !ToCount(words[0], vertices) || !ToCount(words[1], faces))
  {
    return lines.At() + "the counts 'vertices faces [edges]' expected, found " + Quoted(words[0]);
  }
  // A vertex line takes at least 6 bytes ("0 0 0\n"): a count beyond what
  // the file can hold must not reserve memory for it.
  mesh.Points.reserve(3 * std::min(static_cast<std::size_t>(vertices), size / 6 + 1));
  const std::string error = ReadVertices(lines, words, vertices, mesh);
  if (!error.empty())
  {
    return error;
  }
  return ReadFaces(lines, words, vertices, faces, mesh);
}

//------------------------------------------------------------------------------

} // namespace pcurv
