// The body of a PLY file after its header: elements skipped or read value by
// value, from binary (either byte order) or ascii, in buffered chunks.
#ifndef pcurv_PlyBody_h
#define pcurv_PlyBody_h

#include "FileFormats/PlyFile.h"

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace pcurv
{
namespace ply
{

class Body
{
public:
  /// Reads from file's current position on.
  Body(std::FILE* file, Format format);

  /// Reads past all records of element; an empty string, or what is wrong.
  std::string SkipElement(const Element& element);
  /// Reads the vertex records [0, end) and stores [begin, end) into the
  /// layout's columns (row 0 is vertex begin).
  std::string ReadVertices(const Element& vertex,
    const VertexLayout& layout,
    std::uint64_t begin,
    std::uint64_t end);

  /// Reads all records of element into rows, one value per property (a
  /// list's length for a list) and record after record.
  std::string ReadRows(const Element& element, std::vector<double>& rows);

private:
  /// The next value of type into value; false at the end of the file or
  /// (ascii) on a word that is not a number of that type, with Problem set.
  bool NextValue(Type type, double& value);
  bool NextBinary(Type type, double& value);
  bool NextText(Type type, double& value);
  /// Makes n more bytes available at Buffer[Position]; false at the end.
  bool Ensure(std::size_t n);
  /// Skips or reads one record's properties (values to Row, or nullptr).
  bool Record(const Element& element, double* row);
  std::string Failure(const Element& element, std::uint64_t record) const;

  std::FILE* Handle;
  Format BodyFormat;
  std::vector<char> Buffer;
  std::size_t Position = 0;
  std::size_t End = 0;
  std::string Problem;
};

/// Stores value (of the column's type, exactly) at row, component.
void Store(const Column& column, std::size_t row, int component, double value);

} // namespace ply
} // namespace pcurv

#endif
