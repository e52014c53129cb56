#include "FileFormats/FileInput.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>

namespace pcurv
{

//------------------------------------------------------------------------------
std::string LowerCase(std::string text)
{
  std::transform(text.begin(),
    text.end(),
    text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

//------------------------------------------------------------------------------
InputFile::~InputFile()
{
  if (this->Handle)
  {
    std::fclose(this->Handle);
  }
}

//------------------------------------------------------------------------------
std::string InputFile::Open(const char* fileName)
{
  std::FILE* stream = std::fopen(fileName, "rb");
  if (!stream)
  {
    return std::string("cannot open the file: ") + std::strerror(errno);
  }
  return this->Open(stream);
}

//------------------------------------------------------------------------------
std::string InputFile::Open(std::FILE* stream)
{
  this->Handle = stream;
  // The size first: the formats check the counts in their headers against it.
  long size = -1;
  if (std::fseek(this->Handle, 0, SEEK_END) == 0)
  {
    size = std::ftell(this->Handle);
  }
  if (size < 0 || std::fseek(this->Handle, 0, SEEK_SET) != 0)
  {
    return std::string("cannot read the file: ") + std::strerror(errno);
  }
  return this->ReadHeader(static_cast<std::uint64_t>(size));
}

} // namespace pcurv
