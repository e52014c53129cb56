// Shared by the reader tests: files written from bytes made in the test, a
// reader's error messages caught, little-endian values appended.
#ifndef ReaderTestHelpers_h
#define ReaderTestHelpers_h

#include "vtkAlgorithm.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

/// Collects the error messages an algorithm sends.
class ErrorCatcher : public vtkCommand
{
public:
  static ErrorCatcher* New() { return new ErrorCatcher; }
  void Execute(vtkObject*, unsigned long, void* message) override
  {
    this->Messages += static_cast<const char*>(message);
  }
  std::string Messages;
};

/// Writes bytes to path; false if it cannot.
inline bool WriteBytes(const std::string& path, const std::string& bytes)
{
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file)
  {
    return false;
  }
  const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
  return std::fclose(file) == 0 && ok;
}

/// Appends value's bytes, little endian (the host's order on x86 and ARM).
template<typename T>
void Append(std::string& bytes, T value)
{
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  bytes.append(raw, sizeof(T));
}

/// Appends value's bytes in big-endian order.
template<typename T>
void AppendBigEndian(std::string& bytes, T value)
{
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  for (std::size_t i = sizeof(T); i-- > 0;)
  {
    bytes.push_back(raw[i]);
  }
}

/// The value of point i, component c, of the point-data array name; NaN if
/// there is no such array.
inline double ValueOf(vtkPolyData* cloud, const char* name, vtkIdType i, int c = 0)
{
  vtkDataArray* array = cloud->GetPointData()->GetArray(name);
  return array && i < array->GetNumberOfTuples() ? array->GetComponent(i, c) : std::nan("");
}

/// The data type of the point-data array name, or -1.
inline int TypeOf(vtkPolyData* cloud, const char* name)
{
  vtkDataArray* array = cloud->GetPointData()->GetArray(name);
  return array ? array->GetDataType() : -1;
}

#endif
