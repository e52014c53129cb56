/**
 * What the core's file readers share: the stream handling of the binary
 * formats (LAS, PLY), which read a file in parts after checking its header,
 * and the lower-casing of the names that files spell in either case. No VTK
 * here.
 */
#ifndef pcurv_FileInput_h
#define pcurv_FileInput_h

#include <cstdint>
#include <cstdio>
#include <string>

namespace pcurv
{

/// The text in ASCII lower case (file extensions, PLY property names).
std::string LowerCase(std::string text);

/**
 * A file that a format reader opens, checks the header of, then reads in
 * parts: Open measures the file and calls the format's ReadHeader; the
 * stream stays open for the format's reads and is closed with the reader.
 */
class InputFile
{
public:
  virtual ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  /// Opens and checks the file; an empty string, or what is wrong.
  std::string Open(const char* fileName);
  /// The same on an open stream (which this then closes; for example
  /// fmemopen's, as the fuzz target does).
  std::string Open(std::FILE* stream);

protected:
  InputFile() = default;
  std::FILE* Stream() const { return this->Handle; }

private:
  /// Reads and checks the format's header from the stream, which is at the
  /// start of the file's fileSize bytes; an empty string, or what is wrong.
  virtual std::string ReadHeader(std::uint64_t fileSize) = 0;

  std::FILE* Handle = nullptr;
};

} // namespace pcurv

#endif
