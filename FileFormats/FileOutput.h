/**
 * A file the writers (PLY, CSV) fill through a buffer: text or bytes are
 * appended to Buffer(), written out in large pieces, and every failure
 * (the file cannot be created, the disk is full) is a message naming the
 * system's reason. No VTK here.
 */
#ifndef pcurv_FileOutput_h
#define pcurv_FileOutput_h

#include <cstdio>
#include <string>

namespace pcurv
{

class OutputFile
{
public:
  OutputFile() = default;
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  /// Creates (or truncates) the file; an empty string, or what is wrong.
  std::string Open(const char* fileName);
  /// What is appended here goes to the file.
  std::string& Buffer() { return this->Pending; }
  /// Writes the buffer out once it holds a few megabytes.
  std::string FlushIfFull();
  /// Writes the rest and closes the file; an empty string, or what failed.
  std::string Close();

private:
  std::string Flush();

  std::FILE* Handle = nullptr;
  std::string Pending;
};

} // namespace pcurv

#endif
