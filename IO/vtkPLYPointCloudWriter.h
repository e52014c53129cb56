/**
 * @class   vtkPLYPointCloudWriter
 * @brief   writes a point set as a PLY file (.ply) keeping double
 *          coordinates and every point-data array
 *
 * Unlike vtkPLYWriter, which writes float x y z, normals and colors only:
 * - `x y z` in the points' own type (double, or float when the points are
 *   float; other types as double), or as float with PointsAsFloat;
 * - the normals (NormalsArray, else the normals attribute, else an array
 *   named Normals, of 3 floating point components) as `nx ny nz`, which other tools read as
 *   normals; colors (the scalars, else an array named RGB, of 3 unsigned
 *   chars) as uchar `red green blue`;
 * - every other point-data array as vertex properties of its own type
 *   (char, uchar, short, ushort, int, uint, float, double), one per
 *   component: `<name>` for one component, `<name>_x _y _z` for three,
 *   `<name>_0 _1 ...` otherwise. 64-bit integers (long long, vtkIdType)
 *   and bit arrays are written as double, exact up to 2^53 (a warning
 *   names an array beyond). A name becomes printable ASCII without white
 *   space, commas or quotes ('_' instead), unique;
 * - a header comment "array <first property> <components> <name>" for each
 *   array of several components or with a changed name, from which
 *   vtkPLYPointCloudReader restores the array (name, type and components);
 * - a header comment "field <name> <value>" for each field-data value: a
 *   string array's values one comment each (`Curvature_Unit`,
 *   `Shape_Class_Names`), numbers of one tuple one comment (the counts);
 * - a polydata's polygons as the face element (vertex_indices).
 * Arrays that are not numbers (strings), numeric field data of more than
 * one tuple, lines, strips and the cells of other point sets are left out,
 * with one warning naming them.
 *
 * Binary little endian by default; SetFileTypeToASCII writes text, every
 * value exactly (the fewest digits that read back to the same number).
 * Errors (no file name, an input that is not a point set, a file that
 * cannot be created or written) are one vtkErrorMacro naming the file,
 * with GetErrorCode() set.
 *
 * The writing is pcurv::ply::WriteFile (FileFormats/PlyWriter.h), free of
 * VTK.
 *
 * @sa vtkPLYPointCloudReader vtkCSVPointCloudWriter vtkPLYWriter
 */
#ifndef vtkPLYPointCloudWriter_h
#define vtkPLYPointCloudWriter_h

#include "vtkPrincipalCurvatureIOModule.h" // for export macro
#include "vtkWriter.h"

class VTKPRINCIPALCURVATUREIO_EXPORT vtkPLYPointCloudWriter : public vtkWriter
{
public:
  static vtkPLYPointCloudWriter* New();
  vtkTypeMacro(vtkPLYPointCloudWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum FileTypes
  {
    ASCII = 1,
    BINARY = 2
  };

  ///@{
  /// The file to write.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// The array written as the normals (nx ny nz); none (the default): the
  /// normals attribute, else an array named Normals.
  vtkSetStringMacro(NormalsArray);
  vtkGetStringMacro(NormalsArray);
  ///@}

  ///@{
  /// Off (the default): x y z in the points' own type. On: as float, for a
  /// smaller file where float keeps the coordinates (not so far from the
  /// origin: float has 7 significant digits).
  vtkSetMacro(PointsAsFloat, bool);
  vtkGetMacro(PointsAsFloat, bool);
  vtkBooleanMacro(PointsAsFloat, bool);
  ///@}

  ///@{
  /// BINARY (binary_little_endian, the default) or ASCII.
  vtkSetClampMacro(FileType, int, ASCII, BINARY);
  vtkGetMacro(FileType, int);
  void SetFileTypeToASCII() { this->SetFileType(ASCII); }
  void SetFileTypeToBinary() { this->SetFileType(BINARY); }
  ///@}

protected:
  vtkPLYPointCloudWriter();
  ~vtkPLYPointCloudWriter() override;

  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  char* FileName = nullptr;
  char* NormalsArray = nullptr;
  bool PointsAsFloat = false;
  int FileType = BINARY;

private:
  vtkPLYPointCloudWriter(const vtkPLYPointCloudWriter&) = delete;
  void operator=(const vtkPLYPointCloudWriter&) = delete;
};

#endif
