/**
 * @file CloudData.h
 * @brief The VTK side of the filters' data (private to the module): a
 * vtkPointSet and its normals as the core's cloud, and the output's
 * geometry, unit and color ranges.
 */
#ifndef CloudData_h
#define CloudData_h

#include "Cloud/CloudPoints.h"

class vtkDataArray;
class vtkPointSet;
class vtkPolyData;

namespace pcurv
{

/// The input's points and normals (non-unit normals normalized; zero or
/// non-finite ones become zero: such points are not estimated). Without
/// normals (null) every normal is zero, for the core to estimate.
CloudPoints ReadCloud(vtkPointSet* input, vtkDataArray* normals);

/// The output's geometry: the input's points, its point data, the field
/// data that describes its coordinates (LAS_*, Coordinate_System,
/// Length_Unit, Vertical_Unit) and, for a vtkPolyData with cells, its
/// cells; otherwise one vertex cell per point, so that a cloud shows in a
/// render view.
void CopyGeometry(vtkPointSet* input, vtkPolyData* output);

/// What the curvature arrays are measured in, as ParaView shows it (the
/// Information panel lists field data): the string array Curvature_Unit,
/// "1/<unit>" when the field data's Length_Unit names the unit (as the LAS
/// reader does), else "1/length unit of the input coordinates".
void AddCurvatureUnit(vtkPolyData* output);

/**
 * The range that VTK reports for `array` (and ParaView colors a new
 * display over), set to [-clip, clip]: symmetric about zero, so that a
 * diverging color map's middle (white in Cool to Warm) is zero even where
 * only one tail was clipped (a torus's mean curvature is positive
 * everywhere, and its clipped array's own range put white at +0.31). VTK
 * keeps the range in the array's information and forgets it when the array
 * is modified. Nothing is set for a clip that is zero or not finite.
 */
void SetSymmetricRange(vtkDataArray* array, double clip);

} // namespace pcurv

#endif
