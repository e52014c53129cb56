/**
 * @class   vtkOFFMeshReader
 * @brief   reads a text OFF mesh (Geomview's Object File Format, as CGAL's
 *          demo scans come: .off) with point normals from its faces
 *
 * ParaView 5.11 has no OFF reader. The output is a vtkPolyData with the
 * vertices (double), the faces as polygons, and point `Normals` computed
 * from the faces (vtkPolyDataNormals: averaged face normals, made
 * consistent, no splitting) and turned to point away from the centroid when
 * most pointed towards it, for a closed, roughly star-shaped scan such as
 * the Stanford bunny: the same normals the command-line tool
 * Tools/estimate_curvatures.py gives an .off input, which it reads with
 * this reader. A file without faces gives its vertices, one vertex cell
 * each, and no normals (the curvature filter then estimates them).
 *
 * The parsing is pcurv::ParseOffMesh (FileFormats/OffMesh.h, no VTK), which
 * has the accepted syntax. A bad file (not OFF, binary OFF, missing or
 * malformed counts, vertices or faces, an index out of range) is one
 * vtkErrorMacro naming the file, the line and what is wrong; the output is
 * then empty and GetErrorCode() is not vtkErrorCode::NoError.
 *
 * @sa vtkTextPointCloudReader vtkPolyDataNormals
 */
#ifndef vtkOFFMeshReader_h
#define vtkOFFMeshReader_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkPrincipalCurvatureIOModule.h" // for export macro

class VTKPRINCIPALCURVATUREIO_EXPORT vtkOFFMeshReader : public vtkPolyDataAlgorithm
{
public:
  static vtkOFFMeshReader* New();
  vtkTypeMacro(vtkOFFMeshReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The file to read.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

protected:
  vtkOFFMeshReader();
  ~vtkOFFMeshReader() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;

private:
  vtkOFFMeshReader(const vtkOFFMeshReader&) = delete;
  void operator=(const vtkOFFMeshReader&) = delete;
};

#endif
