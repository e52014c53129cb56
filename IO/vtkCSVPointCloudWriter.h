/**
 * @class   vtkCSVPointCloudWriter
 * @brief   writes a point set's points and point data as comma-separated
 *          text with every value exact
 *
 * A header line of column names, then one line per point: `x,y,z` (in
 * the points' type, or float with PointsAsFloat), the normals (as
 * vtkPLYPointCloudWriter chooses them) as `nx,ny,nz`, colors as `red,green,blue`, every other
 * point-data array as `<name>` (one component), `<name>_x,_y,_z` (three)
 * or `<name>_0,_1,...`, named as vtkPLYPointCloudWriter names its
 * properties. Every value is written exactly, in the fewest digits that
 * read back to the same number (at most 17 significant digits for double,
 * 9 for float; integers in full, a char array as numbers), so that
 * coordinates far from the origin keep every digit, unlike vtkCSVWriter's
 * default precision of 5. Arrays that are not numbers (strings) are left
 * out with a warning; cells are not written. With FieldDataComments on,
 * the field data (the unit, the class names) goes before the header as
 * comment lines `# field <name> <value>`, which vtkTextPointCloudReader
 * reads back; off (the default), the file is a plain table whose first
 * line is the header, as spreadsheets and `loadtxt(skiprows=1)` expect.
 *
 * Errors (no file name, an input that is not a point set, a file that
 * cannot be created or written) are one vtkErrorMacro naming the file,
 * with GetErrorCode() set.
 *
 * The writing is pcurv::csv::WriteFile (FileFormats/CsvWriter.h), free of
 * VTK.
 *
 * @sa vtkPLYPointCloudWriter vtkTextPointCloudReader vtkCSVWriter
 */
#ifndef vtkCSVPointCloudWriter_h
#define vtkCSVPointCloudWriter_h

#include "vtkPrincipalCurvatureIOModule.h" // for export macro
#include "vtkWriter.h"

class VTKPRINCIPALCURVATUREIO_EXPORT vtkCSVPointCloudWriter : public vtkWriter
{
public:
  static vtkCSVPointCloudWriter* New();
  vtkTypeMacro(vtkCSVPointCloudWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

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
  /// On: the field data as `# field <name> <value>` lines before the
  /// header (a round trip through vtkTextPointCloudReader keeps it). Off
  /// (the default): the header is the first line.
  vtkSetMacro(FieldDataComments, bool);
  vtkGetMacro(FieldDataComments, bool);
  vtkBooleanMacro(FieldDataComments, bool);
  ///@}

protected:
  vtkCSVPointCloudWriter();
  ~vtkCSVPointCloudWriter() override;

  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  char* FileName = nullptr;
  char* NormalsArray = nullptr;
  bool PointsAsFloat = false;
  bool FieldDataComments = false;

private:
  vtkCSVPointCloudWriter(const vtkCSVPointCloudWriter&) = delete;
  void operator=(const vtkCSVPointCloudWriter&) = delete;
};

#endif
