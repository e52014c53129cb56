/**
 * @class   vtkPointCloudNormalEstimation
 * @brief   consistently oriented normals of a point cloud, for clouds that
 *          have none (most scans)
 *
 * For every point a plane is fitted by PCA to its NumberOfNeighbors nearest
 * neighbors; the normals' signs are then made consistent by propagation
 * over a minimum spanning tree of normal agreement (Hoppe et al. 1992), one
 * tree per connected part, and each part's sign is chosen by Orientation:
 * OUTWARD (away from the part's inside; up, +z, on a scan seen from above,
 * such as an airborne tile, except for the closed objects in it),
 * TOWARDS_VIEWPOINT (towards where the scanner was, point by
 * point) or ALONG_AXIS (a positive component along Axis, point by point).
 *
 * Output: the input points and point data, vertex cells (or the input's
 * cells when the input is a vtkPolyData that has cells), and the unit
 * "Normals" (double, 3 components, the active normals; zero where a point
 * has too few neighbors or non-finite coordinates).
 *
 * The same numbers for any number of threads or MPI processes: points are
 * handled in an order that depends only on the coordinates. The numeric
 * work is pcurv::EstimateCloudNormals (Core/); vtkPrincipalCurvatureEstimation
 * runs the same estimation when its input has no normals.
 *
 * @sa vtkPrincipalCurvatureEstimation vtkPCANormalEstimation
 */
#ifndef vtkPointCloudNormalEstimation_h
#define vtkPointCloudNormalEstimation_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkPrincipalCurvatureFiltersModule.h" // for export macro

class VTKPRINCIPALCURVATUREFILTERS_EXPORT vtkPointCloudNormalEstimation
  : public vtkPolyDataAlgorithm
{
public:
  static vtkPointCloudNormalEstimation* New();
  vtkTypeMacro(vtkPointCloudNormalEstimation, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// How each connected part's sign is chosen (as pcurv::NormalOrientation).
  enum Orientations
  {
    OUTWARD = 0,
    TOWARDS_VIEWPOINT = 1,
    ALONG_AXIS = 2
  };

  ///@{
  /// Neighbors of each point's plane fit (default 30).
  vtkSetClampMacro(NumberOfNeighbors, int, 3, 100000);
  vtkGetMacro(NumberOfNeighbors, int);
  ///@}

  ///@{
  /// How the normals are signed (default OUTWARD), and the viewpoint or axis
  /// the other two modes use (defaults: the origin; +z).
  vtkSetClampMacro(Orientation, int, OUTWARD, ALONG_AXIS);
  vtkGetMacro(Orientation, int);
  void SetOrientationToOutward() { this->SetOrientation(OUTWARD); }
  void SetOrientationToTowardsViewpoint() { this->SetOrientation(TOWARDS_VIEWPOINT); }
  void SetOrientationToAlongAxis() { this->SetOrientation(ALONG_AXIS); }
  vtkSetVector3Macro(Viewpoint, double);
  vtkGetVector3Macro(Viewpoint, double);
  vtkSetVector3Macro(Axis, double);
  vtkGetVector3Macro(Axis, double);
  ///@}

  ///@{
  /// The most threads to use; 0 (default) for all cores.
  vtkSetClampMacro(NumberOfThreads, int, 0, 4096);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /// What the last execution found: the connected parts oriented (OUTWARD
  /// only) and the points whose normal could not be determined.
  vtkGetMacro(NumberOfParts, vtkIdType);
  vtkGetMacro(NumberOfUndeterminedNormals, vtkIdType);
  ///@}

protected:
  vtkPointCloudNormalEstimation();
  ~vtkPointCloudNormalEstimation() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  // Defaults: Core/Settings/SettingsTable.h, through pcurv::NormalSettings.
  int NumberOfNeighbors;
  int Orientation;
  double Viewpoint[3];
  double Axis[3];
  int NumberOfThreads;
  vtkIdType NumberOfParts = 0;
  vtkIdType NumberOfUndeterminedNormals = 0;

private:
  vtkPointCloudNormalEstimation(const vtkPointCloudNormalEstimation&) = delete;
  void operator=(const vtkPointCloudNormalEstimation&) = delete;
};

#endif
