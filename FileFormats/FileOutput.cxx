#include "FileFormats/FileOutput.h"

#include <cerrno>
#include <cstring>

namespace pcurv
{

//------------------------------------------------------------------------------
OutputFile::~OutputFile()
{
  if (this->Handle)
  {
    std::fclose(this->Handle);
  }
}

//------------------------------------------------------------------------------
std::string OutputFile::Open(const char* fileName)
{
  this->Handle = fileName && *fileName ? std::fopen(fileName, "wb") : nullptr;
  if (!this->Handle)
  {
    return std::string("cannot create the file: ") +
      (fileName && *fileName ? std::strerror(errno) : "no file name");
  }
  return std::string();
}

//------------------------------------------------------------------------------
std::string OutputFile::Flush()
{
  if (!this->Handle)
  {
    return "the file is not open";
  }
  const std::size_t written =
    std::fwrite(this->Pending.data(), 1, this->Pending.size(), this->Handle);
  const bool complete = written == this->Pending.size();
  this->Pending.clear();
  return complete ? std::string() : std::string("cannot write the file: ") + std::strerror(errno);
}

//------------------------------------------------------------------------------
std::string OutputFile::FlushIfFull()
{
  // Large writes, few calls; a few megabytes is little beside a cloud.
  return this->Pending.size() < (std::size_t(4) << 20) ? std::string() : this->Flush();
}

//------------------------------------------------------------------------------
std::string OutputFile::Close()
{
  std::string error = this->Flush();
  if (this->Handle && std::fclose(this->Handle) != 0 && error.empty())
  {
    error = std::string("cannot write the file: ") + std::strerror(errno);
  }
  this->Handle = nullptr;
  return error;
}

} // namespace pcurv
