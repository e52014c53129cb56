/**
 * @class   vtkPLYPointCloudReader
 * @brief   reads the vertices of a PLY file (.ply) as a point cloud, keeping
 *          double coordinates and every vertex property
 *
 * ascii, binary_little_endian and binary_big_endian. Unlike vtkPLYReader,
 * which stores the points as float, drops most vertex properties and
 * crashes on a vertex element without x, y, z:
 * - the points are double when the file's x y z are double (or any other
 *   type than float), float when all three are float;
 * - `Normals` (the normals attribute) from nx ny nz, normal_x normal_y
 *   normal_z, normalx normaly normalz or n_x n_y n_z, float or double as
 *   the points;
 * - `RGB` (unsigned char, 3 components, the scalars) from uchar red green
 *   blue;
 * - every other scalar vertex property as a point-data array of its name
 *   and type (e.g. `label`, `quality`, `alpha`; a name clashing with the
 *   arrays above gets _<index>). List properties of the vertex are skipped;
 * - the arrays that the header's "array" comments describe (as
 *   vtkPLYPointCloudWriter writes them: the properties Name_x Name_y Name_z
 *   of a 3-component array, a name with spaces) as those arrays, in their
 *   properties' type, and Normals and RGB under the name a comment gives;
 * - the header's "field" comments as field data (numbers as a double
 *   array, other text as a string array: `Curvature_Unit`).
 * An edge element with integer vertex1 and vertex2 (segments, as MeshLab
 * and the command-line tool's curvature lines have them) gives one line
 * cell per edge instead of the vertex cells, its other scalar properties
 * cell data of their names and types (in a piece, the edges between two of
 * its vertices). Other elements (faces, ...) are skipped: the output is the
 * cloud, with one vertex cell per point. Piece requests are honored.
 *
 * Errors, one vtkErrorMacro naming the file and then what is wrong: not a
 * PLY file, a header line that is wrong (with its number; an unknown format
 * or property type, no end_header), no vertex element, a vertex element
 * without x, y or z (naming the missing ones and the properties there
 * are), an edge naming a vertex the file does not have, a truncated body or a value that is not a
 * number of its type (the element and record). The output is then empty and GetErrorCode() is set.
 *
 * The parsing is pcurv::ply (FileFormats/PlyFile.h), free of VTK.
 *
 * @sa vtkPLYReader vtkLASPointCloudReader
 */
#ifndef vtkPLYPointCloudReader_h
#define vtkPLYPointCloudReader_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkPrincipalCurvatureIOModule.h" // for export macro

class VTKPRINCIPALCURVATUREIO_EXPORT vtkPLYPointCloudReader : public vtkPolyDataAlgorithm
{
public:
  static vtkPLYPointCloudReader* New();
  vtkTypeMacro(vtkPLYPointCloudReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The file to read.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  /**
   * 1 if the file can be opened: a bad PLY file is accepted too, so that
   * ParaView's reader factory gives it to this reader, which says what is
   * wrong, rather than to vtkPLYReader, which may crash on it.
   */
  int CanReadFile(const char* fileName);

protected:
  vtkPLYPointCloudReader();
  ~vtkPLYPointCloudReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;

private:
  vtkPLYPointCloudReader(const vtkPLYPointCloudReader&) = delete;
  void operator=(const vtkPLYPointCloudReader&) = delete;
};

#endif
