/**
 * @class   vtkTextPointCloudReader
 * @brief   reads a point cloud stored as text, one point per line:
 *          x y z [nx ny nz] [more columns] (.xyz .pwn .txt .pts .csv)
 *
 * The file is read into memory at once and its numbers are parsed with
 * std::from_chars (locale independent; a million 6-column lines take well
 * under a second).
 *
 * Lines:
 * - Numbers are separated by white space, commas or semicolons (runs of
 *   separators count as one, as in `x, y, z`).
 * - Blank lines are skipped; `#` or `//` starts a comment that runs to the
 *   end of the line (whole-line and trailing comments). A comment line
 *   `# field <name> <value>` before the data (vtkCSVPointCloudWriter writes
 *   them) becomes field data: numbers a double array, other text a string
 *   array, lines of one name the values of one array.
 * - A first line holding a single non-negative integer is a point count (the
 *   Leica PTS header) and is skipped; in a `.pts` file every such line is
 *   skipped (PTS files that concatenate scans repeat it).
 * - The first remaining line may be a header of column names (it is one when
 *   its first word is not a number), as the command-line tool
 *   Tools/estimate_curvatures.py has always accepted.
 * - Every other line must hold the same number of numbers, at least 3.
 *
 * Columns (the rules the command-line tool applied before it used this
 * reader, extended by colors and extra columns):
 * - Points (double): the columns named x, y, z in a header (ignoring case),
 *   else the first three.
 * - `Normals` (double, 3 components, the active normals attribute): the
 *   columns named nx ny nz, normal_x normal_y normal_z, normalx normaly
 *   normalz or n_x n_y n_z in a header; without a header, columns 4-6 of any
 *   file with 6 or more columns, unless they are colors (integers in
 *   0..255, some above 1: `x y z r g b` gives RGB and no normals; the
 *   curvature filter then estimates normals) or the file is a `.pts` in the
 *   Leica layout `x y z intensity r g b` (7 columns, the last 3 integers in
 *   0..255). A header that names no normals gives none.
 * - The remaining columns, in file order: with a header, named by it
 *   (double), except that three columns named r g b or red green blue with
 *   integer values in 0..255 become `RGB`; without a header, exactly three
 *   remaining columns with integer values in 0..255 become `RGB` (unsigned
 *   char, 3 components, the active scalars); in a `.pts` file of 4 columns
 *   or the 7-column layout above, column 4 is `Intensity` and columns 5-7
 *   `RGB`; any other column i (counted from 0 in the file) is `Column_<i>`
 *   (double). So `x y z nx ny nz r g b` gives Normals and RGB,
 *   `x y z nx ny nz` Normals, `x y z nx ny nz q` Normals and Column_6.
 *
 * Output: a vtkPolyData with the points (double), one vertex cell per point
 * (so that it renders) and the arrays above. Piece requests are honored: piece
 * p of n gets the p-th of n consecutive ranges of the points.
 *
 * Errors: a missing or unreadable file, an empty file, a binary file, a
 * non-numeric word, fewer than 3 numbers on the first data line, a line
 * with a different number of columns than the first, no line of numbers
 * (only comments, a point count or a header), an XYZ molecule file. Each is
 * reported with vtkErrorMacro naming the file, the line number where a
 * line is to blame, and what is wrong; the output is then empty and
 * GetErrorCode() is not vtkErrorCode::NoError (CannotOpenFileError,
 * FileFormatError, ...). RequestData still returns success, so that the
 * pipeline adds no second, unhelpful message; check the point count or the
 * error code. The parsing itself is pcurv::ParseTextCloud
 * (FileFormats/TextPointCloud.h, no VTK).
 *
 * NaN or infinite numbers are numbers: a point with such a coordinate is
 * kept, with one warning for all of them naming the first line (the
 * curvature filter leaves such points unestimated and counts them in
 * Unestimated_Bad_Coordinate); a line with too few numbers is an error at
 * that line, never skipped. The command-line tool reads text through this
 * reader, so the same policy holds there.
 *
 * @sa vtkSimplePointsReader vtkDelimitedTextReader
 */
#ifndef vtkTextPointCloudReader_h
#define vtkTextPointCloudReader_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkPrincipalCurvatureIOModule.h" // for export macro

#include <cstddef> // for std::size_t
#include <vector>  // for the lines of WarnAboutNonFinitePositions

class VTKPRINCIPALCURVATUREIO_EXPORT vtkTextPointCloudReader : public vtkPolyDataAlgorithm
{
public:
  static vtkTextPointCloudReader* New();
  vtkTypeMacro(vtkTextPointCloudReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The file to read.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  /**
   * Whether to offer this reader for the file; ParaView's reader factory
   * asks before choosing it. A .xyz, .pwn or .pts file: 1 whatever it holds
   * (a bad one then gets this reader's error naming the line, rather than
   * reaching the PLOT3D reader, which crashes on text), except a binary
   * file that starts as a PLOT3D grid. Any other file (.txt, shared with the
   * CSV reader, .csv): 1 only if its first data line (after comments, a
   * point count and a header of names) holds at least 3 numbers, so that
   * tables stay with the CSV reader. Reads only the start of the file.
   */
  int CanReadFile(const char* fileName);

protected:
  vtkTextPointCloudReader();
  ~vtkTextPointCloudReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;

private:
  /// One warning for all points with a NaN or infinite coordinate.
  void WarnAboutNonFinitePositions(const std::vector<std::size_t>& lines);

  vtkTextPointCloudReader(const vtkTextPointCloudReader&) = delete;
  void operator=(const vtkTextPointCloudReader&) = delete;
};

#endif
