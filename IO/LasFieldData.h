// The VTK side of what a LAS file says beyond its points, shared by the LAS
// reader and writer (private to the module): the field data that carries
// the scale, offset and coordinate system from a read file to a written
// one, and the extra-bytes dimensions as point-data arrays.
#ifndef LasFieldData_h
#define LasFieldData_h

#include "FileFormats/LasFile.h"
#include "FileFormats/LasWriter.h"

#include "vtkType.h"

#include <string>
#include <vector>

class vtkFieldData;
class vtkPointData;

namespace pcurv
{
namespace readers
{

/**
 * The file's description in field data: LAS_Scale and LAS_Offset (double,
 * 3 components), LAS_Global_Encoding (unsigned short), each coordinate
 * system record's payload as LAS_Projection_<record id> (unsigned char),
 * and the strings Coordinate_System, Length_Unit and Vertical_Unit when
 * the records say them; then the field data the plugin's own record kept
 * (LasVlr.h's FieldDataRecord: Curvature_Unit, Shape_Class_Names, ...).
 */
void AddFileDescription(vtkFieldData* field,
  const las::Header& header,
  const std::vector<las::Vlr>& records);

/// The scale, offset, GPS time type and coordinate system that field (as
/// AddFileDescription writes it; a WKT Coordinate_System too) asks to keep.
void KeepFileDescription(vtkFieldData* field, las::FileSettings& settings);

/// The field data that is not the file's description (AddFileDescription's
/// arrays) as settings.Fields, for the plugin's own record; what a record
/// cannot hold is named in `skipped`.
void KeepFieldData(vtkFieldData* field,
  las::FileSettings& settings,
  std::vector<std::string>& skipped);

/**
 * Point-data arrays (count tuples) for the extra fields, named as the file
 * names them (made unique among pointData's arrays); three consecutive
 * fields <name>_X, _Y, _Z of one type become one 3-component array <name>,
 * as the writer splits vectors. Returns the buffers the core fills.
 */
std::vector<las::PointBuffers::Extra> AddExtraArrays(vtkPointData* pointData,
  const std::vector<las::ExtraField>& fields,
  vtkIdType count);

} // namespace readers
} // namespace pcurv

#endif
