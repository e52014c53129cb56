/**
 * @class   vtkLASPointCloudWriter
 * @brief   writes a point set as a LAS 1.4 lidar point file (.las)
 *
 * Point data format 6, or 7 when the input has Red, Green and Blue arrays,
 * or 8 with Infrared too. The point-data arrays named as
 * vtkLASPointCloudReader names them fill the standard fields: Intensity,
 * ReturnNumber, NumberOfReturns, ClassFlags, ScannerChannel,
 * ScanDirectionFlag, EdgeOfFlightLine, Classification, UserData,
 * PointSourceId, ScanAngle (degrees; else ScanAngleRank, whole degrees),
 * GpsTime, Red, Green, Blue, Infrared. The 8-bit RGB the reader derives
 * from Red, Green and Blue is not written when those are there. Every
 * other numeric array (the
 * curvatures, directions, normals, flags, ...) is kept as extra bytes in
 * its own type, described by an Extra Bytes record (LASF_Spec 4): one
 * dimension per component, a 3-component array as <name>_X, _Y, _Z, others
 * as <name>_0, _1, ...; names cut to 32 characters and made unique.
 * vtkLASPointCloudReader reads them back as arrays (vectors joined again).
 *
 * The coordinates are stored with the scale and offset of the LAS file the
 * input was read from (field data LAS_Scale and LAS_Offset, which
 * vtkLASPointCloudReader writes and filters pass on), else with an offset at
 * the points' minimum and the finest power-of-ten scale with which the
 * extent spans at most 10^9 units. The coordinate system records of the
 * input file (field data LAS_Projection_<record id>) are copied; a WKT
 * Coordinate_System from elsewhere is written as a WKT record. The
 * global-encoding WKT bit is set when a WKT record is written. The other
 * field data (Curvature_Unit, Shape_Class_Names, counts) is written as a
 * record of the plugin's own (user id PCurv_FieldData), which
 * vtkLASPointCloudReader turns back into field data.
 *
 * Errors (one vtkErrorMacro, nothing written): no input points, a point
 * whose coordinates do not fit the scale and offset, a value a standard
 * field cannot hold (Intensity 70000, ReturnNumber 16, ...), a file that
 * cannot be written. Arrays that are not numeric are left out with a
 * warning.
 *
 * In ParaView, Plugin/PointCloudWriterLAS.xml makes it the writer of .las
 * files, and in parallel sessions wraps it in vtkParallelSerialWriter,
 * which gathers the pieces on the first rank.
 *
 * The file format is pcurv::las (FileFormats/LasWriter.h), free of VTK.
 */
#ifndef vtkLASPointCloudWriter_h
#define vtkLASPointCloudWriter_h

#include "vtkPrincipalCurvatureIOModule.h" // for export macro
#include "vtkWriter.h"

class vtkPointSet;

class VTKPRINCIPALCURVATUREIO_EXPORT vtkLASPointCloudWriter : public vtkWriter
{
public:
  static vtkLASPointCloudWriter* New();
  vtkTypeMacro(vtkLASPointCloudWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The file to write.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

protected:
  vtkLASPointCloudWriter();
  ~vtkLASPointCloudWriter() override;

  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  char* FileName = nullptr;

private:
  vtkLASPointCloudWriter(const vtkLASPointCloudWriter&) = delete;
  void operator=(const vtkLASPointCloudWriter&) = delete;
};

#endif
