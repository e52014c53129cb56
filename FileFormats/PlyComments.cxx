#include "FileFormats/PlyComments.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <sstream>

namespace pcurv
{
namespace ply
{
namespace
{

/// The text's first word (up to a space) and the rest after that space.
bool FirstWord(const std::string& text, std::string& word, std::string& rest)
{
  const std::size_t space = text.find(' ');
  if (space == std::string::npos || space == 0)
  {
    return false;
  }
  word = text.substr(0, space);
  rest = text.substr(space + 1);
  return true;
}

/// The word after "<keyword> " at the start of text, and the rest.
bool SplitWord(const std::string& text, const char* keyword, std::string& word, std::string& rest)
{
  const std::string prefix = std::string(keyword) + " ";
  return text.compare(0, prefix.size(), prefix) == 0 &&
    FirstWord(text.substr(prefix.size()), word, rest);
}

} // namespace

//------------------------------------------------------------------------------
std::string FormatArrayComment(const ArrayComment& comment)
{
  return "array " + comment.FirstProperty + " " + std::to_string(comment.Components) + " " +
    comment.Name;
}

//------------------------------------------------------------------------------
bool ParseArrayComment(const std::string& text, ArrayComment& comment)
{
  std::string count, name;
  if (!SplitWord(text, "array", comment.FirstProperty, name) ||
    !FirstWord(name, count, comment.Name))
  {
    return false;
  }
  const char* end = count.c_str() + count.size();
  return std::from_chars(count.c_str(), end, comment.Components).ptr == end &&
    comment.Components >= 1 && !comment.Name.empty();
}

//------------------------------------------------------------------------------
std::string FormatFieldComment(const std::string& name, const std::string& value)
{
  std::string word = name.empty() ? std::string("Field") : name;
  std::replace_if(
    word.begin(),
    word.end(),
    [](char c) { return std::isspace(static_cast<unsigned char>(c)); },
    '_');
  std::string text = value;
  std::replace_if(
    text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  return "field " + word + " " + text;
}

//------------------------------------------------------------------------------
bool ParseFieldComment(const std::string& text, std::string& name, std::string& value)
{
  return SplitWord(text, "field", name, value);
}

//------------------------------------------------------------------------------
bool ParseFieldCommentLine(const char* begin,
  const char* end,
  std::string& name,
  std::string& value)
{
  while (begin < end && (*begin == ' ' || *begin == '\t'))
  {
    ++begin;
  }
  if (begin < end && end[-1] == '\r')
  {
    --end;
  }
  const std::string prefix = "# ";
  if (static_cast<std::size_t>(end - begin) <= prefix.size() ||
    std::string(begin, prefix.size()) != prefix)
  {
    return false;
  }
  return ParseFieldComment(std::string(begin + prefix.size(), end), name, value);
}

//------------------------------------------------------------------------------
bool ParseNumbers(const std::string& text, std::vector<double>& numbers)
{
  std::istringstream words(text);
  numbers.clear();
  for (std::string word; words >> word;)
  {
    double value = 0;
    const char* end = word.c_str() + word.size();
    if (std::from_chars(word.c_str(), end, value).ptr != end)
    {
      return false;
    }
    numbers.push_back(value);
  }
  return !numbers.empty();
}

} // namespace ply
} // namespace pcurv
