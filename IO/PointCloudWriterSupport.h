// What the plugin's file writers (PLY, CSV) share on the VTK side: the
// input's points, point arrays, field data and polygons as a cloud of
// typed columns for the writing core (FileFormats/CloudTable.h), and the
// steps of WriteData around the writing itself.
#ifndef PointCloudWriterSupport_h
#define PointCloudWriterSupport_h

#include <functional>
#include <string>
#include <utility>
#include <vector>

class vtkFieldData;
class vtkWriter;

namespace pcurv
{
namespace table
{
struct Cloud;
}

namespace writers
{

/// Writes the cloud to the file; an empty string, or what went wrong.
using WriteFunction = std::function<std::string(const char* fileName, table::Cloud& cloud)>;

/// What the writers let their user choose.
struct WriteOptions
{
  bool WithFaces = false;     // a polydata's polygons (PLY)
  bool WithFieldData = false; // the field data (FieldTextsOf), as comments
  bool PointsAsFloat = false; // x y z as float, whatever the points' type
  std::string NormalsArray;   // written as nx ny nz; empty: the normals attribute, else Normals
};

/**
 * The field data as (name, value text) pairs, as files keep it (PLY and
 * CSV comments, a LAS record; PlyComments.h): a string array one pair per
 * value, in order (Shape_Class_Names' seven names); a numeric array of one
 * tuple one pair, its components separated by spaces. Numeric arrays of
 * more tuples are named in `skipped` instead.
 */
std::vector<std::pair<std::string, std::string>> FieldTextsOf(vtkFieldData* fields,
  std::vector<std::string>& skipped);

/**
 * WriteData of a writer: the writer's input (a vtkPointSet) as a cloud
 * (with the options), one warning naming the arrays and cells a file
 * cannot hold, then `write`. Errors (no file name, no point
 * set, what `write` reports, out of memory) are one vtkErrorMacro naming
 * the file. Returns the error code for the writer to set (NoError, ...;
 * the setter is protected).
 */
unsigned long WriteInput(vtkWriter* writer,
  const char* fileName,
  const WriteOptions& options,
  const WriteFunction& write);

} // namespace writers
} // namespace pcurv

#endif
