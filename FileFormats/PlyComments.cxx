#include "FileFormats/PlyComments.h"

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
  return "field " + name + " " + value;
}

//------------------------------------------------------------------------------
bool ParseFieldComment(const std::string& text, std::string& name, std::string& value)
{
  return SplitWord(text, "field", name, value);
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
