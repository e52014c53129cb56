/**
 * A point cloud on its way out to a file (PLY, CSV): its arrays as typed
 * columns in the caller's memory, the name each component gets in the
 * file, and the exact text of a value. The writers (PlyWriter.h,
 * CsvWriter.h) share it. No VTK here; the VTK writers in IO/ fill it.
 */
#ifndef pcurv_CloudTable_h
#define pcurv_CloudTable_h

#include "FileFormats/PlyFile.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace pcurv
{
namespace table
{

using ply::Type;

/// What an array is to the formats, which name the components of each in
/// their own way.
enum class Role
{
  Points,  // x y z
  Normals, // nx ny nz: what other tools take for normals
  Colors,  // red green blue [alpha], unsigned char
  Other    // <name> for one component, <name>_x _y _z for 3, <name>_0 ... else
};

/// One array: Count x Components values of ValueType at Data, a point
/// after another (as VTK stores them).
struct Array
{
  std::string Name;
  Role Kind = Role::Other;
  Type ValueType = Type::Float64;
  int Components = 1;
  const void* Data = nullptr;
  std::vector<std::string> ColumnNames; // one per component: NameColumns sets them
};

/// The cloud: its points (Arrays[0], Role::Points), its point arrays, its
/// field data as (name, text) and its polygons (PLY faces: the vertex ids
/// of face f are FaceIds[FaceOffsets[f], FaceOffsets[f + 1])).
struct Cloud
{
  std::uint64_t Count = 0;
  std::vector<Array> Arrays;
  std::vector<std::pair<std::string, std::string>> Fields;
  std::vector<std::uint64_t> FaceOffsets;
  std::vector<std::uint64_t> FaceIds;
};

/**
 * Names every array's columns by its role (above). A name becomes printable
 * ASCII without white space, commas or quotes (a character else is '_'; an
 * empty name Array_<index>), and unique (a clash gets _2, _3, ...), so that
 * it is one word of a PLY header and one CSV header cell.
 */
void NameColumns(Cloud& cloud);

/// Whether the array's columns need a PLY "array" comment to come back as
/// the array: more than one component, or a name its column does not keep.
bool NeedsArrayComment(const Array& array);

/// Appends value `index` (counted over all components) of the array as
/// text that reads back to the same value: integers in full, floating
/// point values in the fewest digits that round-trip (at most 9
/// significant for float, 17 for double; nan, inf, -inf).
void AppendValue(const Array& array, std::uint64_t index, std::string& text);

/// The text as one line (a header comment, a CSV cell): line ends become
/// spaces.
std::string OneLine(std::string text);

} // namespace table
} // namespace pcurv

#endif
