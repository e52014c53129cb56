/**
 * A cloud (CloudTable.h) as comma-separated text: its field data as lines
 * "# field <name> <value>" (PlyComments.h), a header line of the column
 * names (x y z, nx ny nz, ... as in PLY), then one line per point,
 * every value written exactly (integers in full, floating point values in
 * the fewest digits that read back to the same value). No VTK here;
 * vtkCSVPointCloudWriter is the VTK glue.
 */
#ifndef pcurv_CsvWriter_h
#define pcurv_CsvWriter_h

#include "FileFormats/CloudTable.h"

#include <string>

namespace pcurv
{
namespace csv
{

/// Writes the file (NameColumns first): an empty string, or what went
/// wrong.
std::string WriteFile(const char* fileName, const table::Cloud& cloud);

} // namespace csv
} // namespace pcurv

#endif
