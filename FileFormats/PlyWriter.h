/**
 * A cloud (CloudTable.h) as a PLY file: a vertex element with one property
 * per column in the array's own type (x y z double or float as given),
 * then, if the cloud has polygons, a face element (vertex_indices).
 * Comments carry what PLY properties cannot: "array" comments for arrays
 * of several components or with renamed names (PlyFile.h, which the
 * plugin's PLY reader follows), "field" comments for the field data. No
 * VTK here; vtkPLYPointCloudWriter is the VTK glue.
 */
#ifndef pcurv_PlyWriter_h
#define pcurv_PlyWriter_h

#include "FileFormats/CloudTable.h"

#include <string>

namespace pcurv
{
namespace ply
{

/// The header text, from "ply" to "end_header\n" (NameColumns first).
std::string WriterHeader(const table::Cloud& cloud, Format format);

/// Writes the file (binary_little_endian or ascii; NameColumns first): an
/// empty string, or what went wrong (the file cannot be created, the disk
/// is full).
std::string WriteFile(const char* fileName, const table::Cloud& cloud, Format format);

} // namespace ply
} // namespace pcurv

#endif
