/**
 * @class   vtkPrincipalCurvatureEstimation
 * @brief   principal curvatures and directions of a point cloud, by
 *          osculating circles in conformal geometric algebra
 *
 * The method of Getto & Hildenbrand (WSCG 2011), on Seibert et al. (2010):
 * the neighbors of each point are sorted into 16 half planes around its
 * normal, a circle through the point is fitted in each (FitMode PREVIOUS,
 * NEW01 or NEW02), and a sine fitted to the 16 normal curvatures gives the
 * principal curvatures and directions. Beyond the paper, and the default:
 * ORIENTED_CIRCLES, every neighbor's circle from its position and its
 * normal, over a neighborhood chosen per point from the data
 * (AUTOMATIC_SCALE). docs/method.md describes the method as implemented.
 *
 * Input: any vtkPointSet. Normals are optional: the input's are used when
 * it has real ones, and they are estimated otherwise (NormalsSource). The
 * curvatures' signs follow the normals: positive where the surface bends
 * away from the normal, so a sphere with outward normals gives +1/R, as
 * vtkCurvatures reports.
 *
 * Output: the input's points and point data, its cells (or one vertex per
 * point), and point-data arrays: Minimum_Curvature, Maximum_Curvature,
 * Mean_Curvature, Gauss_Curvature, their directions, Shape_Index,
 * Curvedness, Curvature_Valid, and with ORIENTED_CIRCLES
 * Curvature_Standard_Error, Curvature_Trusted, Shape_Class (flat, dome,
 * cup, ridge, valley, saddle, named by the field data Shape_Class_Names)
 * and Fitted_Normal; the
 * diagnostic arrays with DiagnosticArrays; field data with the unit and the
 * counts of points not estimated, by reason. docs/output-arrays.md lists
 * them all.
 *
 * Every setting, its default and range: docs/settings.md (one table,
 * Core/Settings/SettingsTable.h). Results do not depend on the number of
 * threads, the SIMD kernels or how ParaView splits the cloud among
 * processes. Points with non-finite coordinates, or with a normal that is
 * zero or not finite, are not estimated (Curvature_Valid 0, NaN curvatures).
 *
 * @sa vtkPointCloudNormalEstimation vtkCurvatures vtkPCACurvatureEstimation
 */
#ifndef vtkPrincipalCurvatureEstimation_h
#define vtkPrincipalCurvatureEstimation_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkPrincipalCurvatureFiltersModule.h" // for export macro

class vtkDataArray;
class vtkPointSet;

class VTKPRINCIPALCURVATUREFILTERS_EXPORT vtkPrincipalCurvatureEstimation
  : public vtkPolyDataAlgorithm
{
public:
  static vtkPrincipalCurvatureEstimation* New();
  vtkTypeMacro(vtkPrincipalCurvatureEstimation, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Where the normals come from.
  enum NormalsSources
  {
    /// The input's normals when it has real ones (the normals attribute, or
    /// the chosen array when its name says normals), estimated otherwise.
    AUTOMATIC_NORMALS = 0,
    INPUT_NORMALS = 1,    ///< the chosen array (or the normals attribute); an error without
    ESTIMATED_NORMALS = 2 ///< always estimated (PCA, oriented), whatever the input has
  };

  /// How estimated normals are oriented.
  enum NormalOrientations
  {
    OUTWARD = 0,           ///< away from each connected part's inside (up where undecided)
    TOWARDS_VIEWPOINT = 1, ///< towards Viewpoint, point by point
    ALONG_AXIS = 2         ///< a positive component along OrientationAxis, point by point
  };

  /// The osculating-circle fits of the paper.
  enum FitModes
  {
    PREVIOUS = 0,
    NEW01 = 1,
    NEW02 = 2,
    /// Beyond the paper: every neighbor's circle from its position and its
    /// normal, one sine fitted at the neighbors' own angles.
    ORIENTED_CIRCLES = 3
  };

  /// How the neighbors of a point are chosen.
  enum NeighborhoodModes
  {
    RADIUS = 0,    ///< all points closer than the surroundings-threshold
    K_NEAREST = 1, ///< the NumberOfNeighbors nearest points
    /// Per point, from the data (with ORIENTED_CIRCLES; RADIUS otherwise):
    /// the largest neighborhood whose estimate agrees with those of the
    /// smaller ones within AutomaticScaleTolerance standard errors.
    AUTOMATIC_SCALE = 2
  };

  ///@{
  /// The fit: ORIENTED_CIRCLES (default), or the paper's PREVIOUS, NEW01, NEW02.
  vtkSetClampMacro(FitMode, int, PREVIOUS, ORIENTED_CIRCLES);
  vtkGetMacro(FitMode, int);
  void SetFitModeToPrevious() { this->SetFitMode(PREVIOUS); }
  void SetFitModeToNew01() { this->SetFitMode(NEW01); }
  void SetFitModeToNew02() { this->SetFitMode(NEW02); }
  void SetFitModeToOrientedCircles() { this->SetFitMode(ORIENTED_CIRCLES); }
  ///@}

  ///@{
  /// AUTOMATIC_SCALE (default; RADIUS with the paper's fits or fixed
  /// thresholds), RADIUS or K_NEAREST.
  vtkSetClampMacro(NeighborhoodMode, int, RADIUS, AUTOMATIC_SCALE);
  vtkGetMacro(NeighborhoodMode, int);
  void SetNeighborhoodModeToRadius() { this->SetNeighborhoodMode(RADIUS); }
  void SetNeighborhoodModeToKNearest() { this->SetNeighborhoodMode(K_NEAREST); }
  void SetNeighborhoodModeToAutomaticScale() { this->SetNeighborhoodMode(AUTOMATIC_SCALE); }
  ///@}

  ///@{
  /// AUTOMATIC_SCALE: standard errors two radii's estimates may differ by.
  vtkSetClampMacro(AutomaticScaleTolerance, double, 0.1, 100.0);
  vtkGetMacro(AutomaticScaleTolerance, double);
  ///@}

  ///@{
  /// AUTOMATIC_SCALE: points near an anchor take its fitted surface.
  vtkSetMacro(ShareFits, bool);
  vtkGetMacro(ShareFits, bool);
  vtkBooleanMacro(ShareFits, bool);
  ///@}

  ///@{
  /// AUTOMATIC_SCALE with normals given: where the positions are noisy, the
  /// curvatures from a fit of the normal field. Off by default.
  vtkSetMacro(NormalFieldFit, bool);
  vtkGetMacro(NormalFieldFit, bool);
  vtkBooleanMacro(NormalFieldFit, bool);
  ///@}

  ///@{
  /// Derive the thresholds s and p from the cloud (default on).
  vtkSetMacro(AutomaticThresholds, bool);
  vtkGetMacro(AutomaticThresholds, bool);
  vtkBooleanMacro(AutomaticThresholds, bool);
  ///@}

  ///@{
  /// Neighbors for the automatic s, and k of K_NEAREST.
  vtkSetClampMacro(NumberOfNeighbors, int, 3, 1000000);
  vtkGetMacro(NumberOfNeighbors, int);
  ///@}

  ///@{
  /// s, a length, when AutomaticThresholds is off.
  vtkSetClampMacro(SurroundingsThreshold, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(SurroundingsThreshold, double);
  ///@}

  ///@{
  /// p, a length, when AutomaticThresholds is off (the paper's fits).
  vtkSetClampMacro(PlaneDistanceThreshold, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(PlaneDistanceThreshold, double);
  ///@}

  ///@{
  /// p / s when AutomaticThresholds is on (the paper's fits).
  vtkSetClampMacro(PlaneDistanceRatio, double, 0.001, 1.0);
  vtkGetMacro(PlaneDistanceRatio, double);
  ///@}

  ///@{
  /// Fewest points for a direction's circle fit.
  vtkSetClampMacro(MinimumPointsPerDirection, int, 3, 1000000);
  vtkGetMacro(MinimumPointsPerDirection, int);
  ///@}

  ///@{
  /// At most this many threads; 0 uses all cores.
  vtkSetClampMacro(NumberOfThreads, int, 0, 4096);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /// Float output arrays instead of double; the diagnostic arrays or not.
  vtkSetMacro(SinglePrecisionOutput, bool);
  vtkGetMacro(SinglePrecisionOutput, bool);
  vtkBooleanMacro(SinglePrecisionOutput, bool);
  vtkSetMacro(DiagnosticArrays, bool);
  vtkGetMacro(DiagnosticArrays, bool);
  vtkBooleanMacro(DiagnosticArrays, bool);
  ///@}

  ///@{
  /// The paper's dynamic variable adjustment instead of the neighborhood
  /// settings above (docs/dynamic-adjustment.md).
  vtkSetMacro(DynamicAdjustment, bool);
  vtkGetMacro(DynamicAdjustment, bool);
  vtkBooleanMacro(DynamicAdjustment, bool);
  ///@}

  ///@{
  /// The adjustment's length unit L: from the cloud, or LengthUnit.
  vtkSetMacro(AutomaticLengthUnit, bool);
  vtkGetMacro(AutomaticLengthUnit, bool);
  vtkBooleanMacro(AutomaticLengthUnit, bool);
  vtkSetClampMacro(LengthUnit, double, 1e-300, VTK_DOUBLE_MAX);
  vtkGetMacro(LengthUnit, double);
  ///@}

  ///@{
  /// The adjustment's constants (the paper's by default; lengths in L).
  vtkSetClampMacro(InitialSurroundingsThreshold, double, 1e-300, VTK_DOUBLE_MAX);
  vtkGetMacro(InitialSurroundingsThreshold, double);
  vtkSetVector3Macro(TargetNeighborCounts, double);
  vtkGetVector3Macro(TargetNeighborCounts, double);
  vtkSetVector3Macro(TargetPlaneDistances, double);
  vtkGetVector3Macro(TargetPlaneDistances, double);
  vtkSetVector3Macro(SwitchLengths, double);
  vtkGetVector3Macro(SwitchLengths, double);
  ///@}

  ///@{
  /// The adjustment's counts, plane distances and switch lengths at once:
  /// the paper's, or the banded ladder (docs/dynamic-adjustment.md).
  void SetAdjustmentConstantsToPaper();
  void SetAdjustmentConstantsToBandedLadder(double firstCount, double planeDistance);
  ///@}

  /// The named sets of adjustment constants (pcurv::AdjustmentPreset).
  enum AdjustmentPresets
  {
    PAPER_CONSTANTS = 0, ///< the paper's
    LADDER = 1,          ///< SetAdjustmentConstantsToBandedLadder(375, 0.2): clean clouds
    NOISY_LADDER = 2     ///< SetAdjustmentConstantsToBandedLadder(1000, 0.6): noise of h / 2
  };

  /// Sets TargetNeighborCounts, TargetPlaneDistances and SwitchLengths to
  /// one of AdjustmentPresets (clamped to the range).
  void SetAdjustmentConstantsToPreset(int preset);

  ///@{
  /// s never exceeds this times the adjustment's initial s.
  vtkSetClampMacro(MaximumSurroundingsFactor, double, 1.0, 1e6);
  vtkGetMacro(MaximumSurroundingsFactor, double);
  ///@}

  ///@{
  /// Side of the adjustment's blocks of points, in units of L.
  vtkSetClampMacro(AdjustmentBlockLength, double, 1e-6, 1e6);
  vtkGetMacro(AdjustmentBlockLength, double);
  ///@}

  ///@{
  /// Where the normals come from (default: the input's real normals, else
  /// estimated), and how estimated normals are made and signed.
  vtkSetClampMacro(NormalsSource, int, AUTOMATIC_NORMALS, ESTIMATED_NORMALS);
  vtkGetMacro(NormalsSource, int);
  void SetNormalsSourceToAutomatic() { this->SetNormalsSource(AUTOMATIC_NORMALS); }
  void SetNormalsSourceToInput() { this->SetNormalsSource(INPUT_NORMALS); }
  void SetNormalsSourceToEstimated() { this->SetNormalsSource(ESTIMATED_NORMALS); }
  vtkSetClampMacro(NormalOrientation, int, OUTWARD, ALONG_AXIS);
  vtkGetMacro(NormalOrientation, int);
  vtkSetVector3Macro(Viewpoint, double);
  vtkGetVector3Macro(Viewpoint, double);
  vtkSetVector3Macro(OrientationAxis, double);
  vtkGetVector3Macro(OrientationAxis, double);
  vtkSetClampMacro(NormalNeighbors, int, 3, 100000);
  vtkGetMacro(NormalNeighbors, int);
  /// True when the last execution estimated the normals.
  vtkGetMacro(UsedEstimatedNormals, bool);
  ///@}

  ///@{
  /// What the last execution used and found.
  vtkGetMacro(UsedSurroundingsThreshold, double);
  vtkGetMacro(UsedLengthUnit, double);
  vtkGetMacro(UsedPlaneDistanceThreshold, double);
  vtkGetMacro(NumberOfUnestimatedPoints, vtkIdType);
  ///@}

  /// After an update with AUTOMATIC_SCALE (also in the field data): the
  /// points that took an anchor's fit, whether the wide radii fitted the
  /// surface's fourth order, and the points estimated by a height jet.
  vtkGetMacro(NumberOfSharedFitPoints, vtkIdType);
  vtkGetMacro(FourthOrderFits, bool);
  vtkGetMacro(NumberOfJetFitPoints, vtkIdType);

protected:
  vtkPrincipalCurvatureEstimation();
  ~vtkPrincipalCurvatureEstimation() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  /// One error (and false) unless `normals` has 3 components per point
  /// and looks like normals (see SetNormalsSource).
  bool CheckNormals(vtkDataArray* normals, vtkIdType numberOfPoints);
  /// The input normals to use; null with `estimate` set to estimate them,
  /// or null after an error.
  vtkDataArray* ChooseNormals(vtkInformationVector** inputVector,
    vtkPointSet* input,
    bool& estimate);
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  // Defaults: Core/Settings/SettingsTable.h, through
  // pcurv::EstimationSettings, copied by the constructor.
  int FitMode;
  int NeighborhoodMode;
  bool AutomaticThresholds;
  int NumberOfNeighbors;
  double SurroundingsThreshold;
  double PlaneDistanceThreshold;
  double PlaneDistanceRatio;
  int MinimumPointsPerDirection;
  double AutomaticScaleTolerance;
  bool ShareFits;
  bool NormalFieldFit;
  int NumberOfThreads;
  bool SinglePrecisionOutput;
  bool DiagnosticArrays;
  bool DynamicAdjustment;
  bool AutomaticLengthUnit;
  double LengthUnit;
  double InitialSurroundingsThreshold;
  double TargetNeighborCounts[3];
  double TargetPlaneDistances[3];
  double SwitchLengths[3];
  double MaximumSurroundingsFactor;
  double AdjustmentBlockLength;
  int NormalsSource;
  int NormalOrientation;
  double Viewpoint[3];
  double OrientationAxis[3];
  int NormalNeighbors;
  bool UsedEstimatedNormals = false;

  double UsedLengthUnit = 0.0;
  double UsedSurroundingsThreshold = 0.0;
  double UsedPlaneDistanceThreshold = 0.0;
  vtkIdType NumberOfUnestimatedPoints = 0;
  vtkIdType NumberOfSharedFitPoints = 0;
  vtkIdType NumberOfJetFitPoints = 0;
  bool FourthOrderFits = false;

private:
  vtkPrincipalCurvatureEstimation(const vtkPrincipalCurvatureEstimation&) = delete;
  void operator=(const vtkPrincipalCurvatureEstimation&) = delete;
};

#endif
