/**
 * @class   vtkCurvatureLines
 * @brief   ridge and valley lines of a point cloud, as polylines, from its
 *          principal curvatures
 *
 * Input: the output of vtkPrincipalCurvatureEstimation (a vtkPointSet with
 * the point-data arrays Maximum_Curvature, Minimum_Curvature,
 * Maximum_Curvature_Direction and the normals: Fitted_Normal, else the
 * normals attribute or an array named Normals; optional:
 * Curvature_Standard_Error, Surroundings_Threshold, Curvature_Valid).
 *
 * Output: the extremal lines of the principal curvatures (ridges in
 * Porteous' sense: where a principal curvature is extremal along its own
 * direction) as polylines, placed where the curvature's derivative crosses
 * zero between the points. Cell data: Line_Kind (unsigned char, see
 * LineKinds), Line_Strength (the integral of |k| along the line, in
 * radians) and Line_Length; point data: Line_Curvature, the extremal
 * curvature at each line point (1/length, the curvature filter's sign).
 *
 * Lines are kept only where the extremum stands out of the curvatures'
 * standard error and the curvature changes along its direction (none on a
 * torus, a cylinder or a plane), and when they are longer than
 * MinimumLength neighborhood radii and stronger than MinimumStrength.
 *
 * @warning In parallel each process finds the lines of its own piece:
 * lines stop at the pieces' borders.
 *
 * @sa vtkPrincipalCurvatureEstimation
 */
#ifndef vtkCurvatureLines_h
#define vtkCurvatureLines_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkPrincipalCurvatureFiltersModule.h" // for export macro

class VTKPRINCIPALCURVATUREFILTERS_EXPORT vtkCurvatureLines : public vtkPolyDataAlgorithm
{
public:
  static vtkCurvatureLines* New();
  vtkTypeMacro(vtkCurvatureLines, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Values of Line_Kind.
  enum LineKinds
  {
    RIDGE = 0,              ///< k_max maximal along its direction, k_max > |k_min|
    VALLEY = 1,             ///< k_min minimal along its direction, k_min < -|k_max|
    MAXIMUM_OF_MAXIMUM = 2, ///< k_max maximal, not dominant
    MINIMUM_OF_MAXIMUM = 3,
    MAXIMUM_OF_MINIMUM = 4,
    MINIMUM_OF_MINIMUM = 5 ///< k_min minimal, not dominant
  };

  /// Which kinds of lines to extract.
  enum KindSelections
  {
    RIDGES_AND_VALLEYS = 0,
    RIDGES = 1,
    VALLEYS = 2,
    ALL_EXTREMAL_LINES = 3 ///< every kind of LineKinds
  };

  ///@{
  /// Which kinds of lines to extract (default RIDGES_AND_VALLEYS).
  vtkSetClampMacro(Kinds, int, RIDGES_AND_VALLEYS, ALL_EXTREMAL_LINES);
  vtkGetMacro(Kinds, int);
  ///@}

  ///@{
  /// Lines shorter than this many neighborhood radii (the median of
  /// Surroundings_Threshold) are dropped. Default 3.
  vtkSetClampMacro(MinimumLength, double, 0.0, 1.0e6);
  vtkGetMacro(MinimumLength, double);
  ///@}

  ///@{
  /// Lines whose strength (the integral of |k| along them, in radians:
  /// how far the surface turns along the line, summed) is below this are
  /// dropped. Default 0.
  vtkSetClampMacro(MinimumStrength, double, 0.0, 1.0e6);
  vtkGetMacro(MinimumStrength, double);
  ///@}

  ///@{
  /// How many standard errors an extremum must stand out by. Default 2.
  vtkSetClampMacro(Significance, double, 0.0, 100.0);
  vtkGetMacro(Significance, double);
  ///@}

protected:
  vtkCurvatureLines();
  ~vtkCurvatureLines() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Kinds = RIDGES_AND_VALLEYS;
  double MinimumLength = 3.0;
  double MinimumStrength = 0.0;
  double Significance = 2.0;

private:
  vtkCurvatureLines(const vtkCurvatureLines&) = delete;
  void operator=(const vtkCurvatureLines&) = delete;
};

#endif
