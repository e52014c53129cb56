/**
 * @class   vtkLASPointCloudReader
 * @brief   reads LAS 1.0-1.4 lidar point files (.las), point data formats 0-10
 *
 * The points are the records' int32 coordinates times the header's scale
 * plus its offset, in double (georeferenced coordinates keep every digit the
 * file has). Point-data arrays, named as PDAL names them:
 * - `Intensity` (unsigned short), `ReturnNumber`, `NumberOfReturns`,
 *   `Classification`, `UserData` (unsigned char), `PointSourceId` (unsigned
 *   short), in every format. Formats 6-10 keep 4-bit return numbers and a
 *   whole classification byte; formats 0-5 3-bit ones and the class in the
 *   low 5 bits.
 * - `ClassFlags` (unsigned char: synthetic, key-point, withheld, overlap in
 *   bits 0-3, as LAS 1.4 stores them), `ScanDirectionFlag`,
 *   `EdgeOfFlightLine`, and `ScannerChannel` in formats 6-10.
 * - `ScanAngleRank` (short, whole degrees; a short rather than a signed
 *   char, which writers print as a character) in formats 0-5, `ScanAngle`
 *   (float, degrees: the file's 0.006-degree units) in formats 6-10.
 * - `GpsTime` (double) in formats 1 and 3-10.
 * - `Red`, `Green`, `Blue` (unsigned short, as stored: LAS colors are
 *   16-bit) in formats 2, 3, 5, 7, 8, 10, and `Infrared` in 8 and 10. Three
 *   arrays, as PDAL names them, which vtkLASPointCloudWriter writes back.
 * - `RGB` (unsigned char, 3 components), the active scalars, with those:
 *   the colors at 8 bits, for display (ParaView colors by it at the first
 *   Apply; with Map Scalars off it shows the true colors). 16-bit colors
 *   are scaled (65535 to 255); files that store 8-bit values in the 16-bit
 *   fields (no value above 255 in the piece read) are taken as they are.
 * - The extra bytes an Extra Bytes record (LASF_Spec 4) describes: an array
 *   per dimension of its name and type (double when the descriptor scales
 *   or offsets it); three dimensions <name>_X, _Y, _Z of one type as one
 *   3-component array <name> (the normals when it is "Normals"), as
 *   vtkLASPointCloudWriter writes vectors. Names taken already get "_2".
 * Wave packets (formats 4, 5, 9, 10) and undocumented extra bytes are
 * skipped. One vertex cell per point. Piece requests are honored
 * (consecutive ranges).
 *
 * Field data: `LAS_Scale`, `LAS_Offset` (double, 3 components),
 * `LAS_Global_Encoding`, the payload of each LASF_Projection record as
 * `LAS_Projection_<record id>` (unsigned char), which vtkLASPointCloudWriter
 * reuses; and the strings `Coordinate_System` (the WKT, or "EPSG:<code>"
 * from GeoTIFF keys), `Length_Unit` ("metre", "foot", "US survey foot",
 * ...) and `Vertical_Unit` when the file declares them; then what a
 * PCurv_FieldData record (vtkLASPointCloudWriter's) kept: the unit, the
 * class names, the counts of the data set written.
 *
 * The points are read in chunks of 64k records straight into the output
 * arrays: the file is never held in memory.
 *
 * Errors (the file named, then what is wrong: not a LAS file, a truncated
 * file, an unknown version or point format, LAZ compression, a header that
 * claims more points than the file holds, an offset beyond the file, a
 * record length too small for the format) are one vtkErrorMacro; the output
 * is then empty and GetErrorCode() is set. RequestData still succeeds, as in
 * vtkTextPointCloudReader.
 *
 * The parsing is pcurv::las (FileFormats/LasFile.h), free of VTK.
 */
#ifndef vtkLASPointCloudReader_h
#define vtkLASPointCloudReader_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkPrincipalCurvatureIOModule.h" // for export macro

class VTKPRINCIPALCURVATUREIO_EXPORT vtkLASPointCloudReader : public vtkPolyDataAlgorithm
{
public:
  static vtkLASPointCloudReader* New();
  vtkTypeMacro(vtkLASPointCloudReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The file to read.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  /**
   * 1 if the file can be opened. A file that is not a good LAS file is
   * accepted too, so that ParaView's reader factory gives it to this reader,
   * which says what is wrong, rather than to the GDAL raster reader.
   */
  int CanReadFile(const char* fileName);

protected:
  vtkLASPointCloudReader();
  ~vtkLASPointCloudReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;

private:
  vtkLASPointCloudReader(const vtkLASPointCloudReader&) = delete;
  void operator=(const vtkLASPointCloudReader&) = delete;
};

#endif
