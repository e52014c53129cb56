/**
 * @class   vtkPointSetGather
 * @brief   the pieces of a point set gathered from MPI ranks as one, for
 *          the plugin's writers in a parallel session
 *
 * ParaView's parallel-serial writer (vtkParallelSerialWriter) gathers the
 * pieces of a distributed data set on one rank and hands them to this
 * filter (its PostGatherHelper), then writes the output with the plugin's
 * PLY or CSV writer. One input is passed as it is (its type, cells and
 * field data; the serial case); several are appended, polydata into a
 * polydata (vtkAppendPolyData), other point sets into an unstructured grid
 * (vtkAppendFilter), with the first piece's field data (the curvature
 * unit and counts: the filter's field data are the same on every rank).
 *
 * @sa vtkPLYPointCloudWriter vtkCSVPointCloudWriter
 */
#ifndef vtkPointSetGather_h
#define vtkPointSetGather_h

#include "vtkPointSetAlgorithm.h"
#include "vtkPrincipalCurvatureIOModule.h" // for export macro

class VTKPRINCIPALCURVATUREIO_EXPORT vtkPointSetGather : public vtkPointSetAlgorithm
{
public:
  static vtkPointSetGather* New();
  vtkTypeMacro(vtkPointSetGather, vtkPointSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkPointSetGather() = default;
  ~vtkPointSetGather() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkPointSetGather(const vtkPointSetGather&) = delete;
  void operator=(const vtkPointSetGather&) = delete;
};

#endif
