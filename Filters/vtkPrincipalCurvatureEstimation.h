/**
 * @class   vtkPrincipalCurvatureEstimation
 * @brief   principal curvatures and directions of a point cloud with normals,
 *          by osculating-circle fitting in conformal geometric algebra
 *
 * For every input point x with normal n, the neighbours within the
 * surroundings-threshold s (or the k nearest) are sorted into 16 half planes
 * around n: a neighbour belongs to half plane i when it lies on the plane's
 * side and closer than the plane-distance-threshold p to it. In each half
 * plane a circle through x with its centre on the normal line is fitted in
 * conformal geometric algebra (Seibert et al. 2010; Getto & Hildenbrand,
 * WSCG 2011), giving one normal curvature per direction. A sine of period pi
 * fitted to these 16 values (IEEE Std 1241, three parameters) gives the
 * principal curvatures (its extremes) and directions (where they occur).
 *
 * Three circle fits are offered (SetFitMode): PREVIOUS, the eigenvector of the
 * smallest eigenvalue of the CGA matrix; NEW01, one closed-form equation;
 * NEW02, the better (by summed geometric distance) of two closed forms.
 *
 * Output: the input points and point data, vertex cells (or the input's
 * cells when the input is a vtkPolyData that has cells), and these point-data
 * arrays (doubles unless stated):
 * - Minimum_Curvature, Maximum_Curvature (1/length, Maximum >= Minimum),
 *   Mean_Curvature (their mean), Gauss_Curvature (their product). Sign:
 *   positive where the surface bends away from the normal, so a sphere with
 *   outward normals gives +1/R, as vtkCurvatures reports.
 * - Minimum_Curvature_Direction, Maximum_Curvature_Direction: unit 3-vectors
 *   orthogonal to each other (defined up to sign) and to the normal: the
 *   given one with the paper's fits, Fitted_Normal with OrientedCircles.
 * - Fitted_Normal (3-vector), Curvature_Standard_Error, with
 *   OrientedCircles only: the fitted surface's unit normal (the given one
 *   turned by the fit's tilt where it is the normal's error), and the
 *   curvatures' standard error (1/length).
 * - Curvature_Valid (unsigned char): 1 where estimated, 0 where not (then the
 *   curvatures are NaN and the directions zero vectors).
 * - Neighbor_Count (int), Valid_Direction_Count (int, 0..16),
 *   Sine_Fit_RMS (1/length), Surroundings_Threshold (the neighborhood
 *   radius at the point: its Neighbor_Count neighbors are closer than it)
 *   and Plane_Distance_Threshold (lengths, in the input's unit).
 * - Field data: Curvature_Unit (string, "1/length unit of the input
 *   coordinates") and the Unestimated_* counts. The range reported for
 *   Mean_Curvature_Clipped is [-c, c], symmetric about zero, so that a
 *   diverging colour map shows zero as its middle colour.
 * - Target_Neighbor_Count (int), with DynamicAdjustment only: the count the
 *   adjustment aimed at for the point (its target combination's N_t; 0
 *   where the point has no usable coordinate or normal).
 *
 * By default the thresholds are derived from the cloud: s is the median,
 * over a fixed sample of points, of the distance to the NumberOfNeighbors-th
 * nearest neighbour (so a typical point has about that many neighbours), and
 * p = PlaneDistanceRatio * s.
 *
 * The work is spread over all cores (the STDThread SMP backend is used when
 * the process default is the sequential one); every point is computed
 * independently, so results do not depend on the number of threads.
 *
 * @warning Normals need not be consistently oriented for the magnitudes, but
 * the signs of the curvatures follow the normals. Points with a missing,
 * zero or non-finite normal or non-finite coordinates are not estimated.
 *
 * @sa vtkCurvatures vtkPCACurvatureEstimation vtkPCANormalEstimation
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
    /// Beyond the paper: every neighbour's circle from its position and its
    /// normal, one sine fitted at the neighbours' own angles.
    ORIENTED_CIRCLES = 3
  };

  /// How the neighbours of a point are chosen.
  enum NeighborhoodModes
  {
    RADIUS = 0,    ///< all points closer than the surroundings-threshold
    K_NEAREST = 1, ///< the NumberOfNeighbors nearest points
    /// Per point, from the data (with ORIENTED_CIRCLES; RADIUS otherwise):
    /// the largest neighbourhood whose estimate agrees with those of the
    /// smaller ones within AutomaticScaleTolerance standard errors.
    AUTOMATIC_SCALE = 2
  };

  ///@{
  /**
   * The circle fit per direction. Default ORIENTED_CIRCLES (with the
   * AUTOMATIC_SCALE neighbourhood), beyond the paper: the most accurate on
   * the shared suite (Study/REPORT.md). Of the paper's three, NEW01 is as
   * accurate as PREVIOUS without noise, the most accurate with noise, and
   * the fastest; NEW02's choice between its two closed forms picks the
   * noise-biased one too often.
   */
  vtkSetClampMacro(FitMode, int, PREVIOUS, ORIENTED_CIRCLES);
  vtkGetMacro(FitMode, int);
  void SetFitModeToPrevious() { this->SetFitMode(PREVIOUS); }
  void SetFitModeToNew01() { this->SetFitMode(NEW01); }
  void SetFitModeToNew02() { this->SetFitMode(NEW02); }
  void SetFitModeToOrientedCircles() { this->SetFitMode(ORIENTED_CIRCLES); }
  ///@}

  ///@{
  /**
   * RADIUS (default) or K_NEAREST neighbourhoods.
   */
  vtkSetClampMacro(NeighborhoodMode, int, RADIUS, AUTOMATIC_SCALE);
  vtkGetMacro(NeighborhoodMode, int);
  void SetNeighborhoodModeToRadius() { this->SetNeighborhoodMode(RADIUS); }
  void SetNeighborhoodModeToKNearest() { this->SetNeighborhoodMode(K_NEAREST); }
  void SetNeighborhoodModeToAutomaticScale() { this->SetNeighborhoodMode(AUTOMATIC_SCALE); }
  ///@}

  ///@{
  /**
   * AUTOMATIC_SCALE: how many standard errors the estimates of two radii may
   * differ by for the larger radius to be kept (default 2). Larger values
   * smooth more (larger neighbourhoods), smaller values follow small
   * features more closely.
   */
  vtkSetClampMacro(AutomaticScaleTolerance, double, 0.1, 100.0);
  vtkGetMacro(AutomaticScaleTolerance, double);
  ///@}

  ///@{
  /**
   * AUTOMATIC_SCALE: a point near an anchor point whose neighbourhood is
   * wide (noisy clouds) takes the anchor's fitted surface, evaluated at its
   * own position, instead of fitting nearly the same neighbours again
   * (default on; docs/method.md). Off: every point fits its own
   * neighbourhood, at several times the cost on noisy clouds.
   */
  vtkSetMacro(ShareFits, bool);
  vtkGetMacro(ShareFits, bool);
  vtkBooleanMacro(ShareFits, bool);
  ///@}

  ///@{
  /**
   * When on (default), the surroundings-threshold s and the
   * plane-distance-threshold p are derived from the cloud (see the class
   * description) and SurroundingsThreshold / PlaneDistanceThreshold are
   * ignored. In K_NEAREST mode, p = PlaneDistanceRatio times the distance to
   * the farthest of the point's neighbours.
   */
  vtkSetMacro(AutomaticThresholds, bool);
  vtkGetMacro(AutomaticThresholds, bool);
  vtkBooleanMacro(AutomaticThresholds, bool);
  ///@}

  ///@{
  /**
   * Target number of neighbours for the automatic surroundings-threshold, and
   * k in K_NEAREST mode. Default 375 (the paper's target).
   */
  vtkSetClampMacro(NumberOfNeighbors, int, 3, 1000000);
  vtkGetMacro(NumberOfNeighbors, int);
  ///@}

  ///@{
  /**
   * The surroundings-threshold s (a radius, in the cloud's length unit) used
   * when AutomaticThresholds is off in RADIUS mode. Default 1.
   */
  vtkSetClampMacro(SurroundingsThreshold, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(SurroundingsThreshold, double);
  ///@}

  ///@{
  /**
   * The plane-distance-threshold p (a length) used when AutomaticThresholds
   * is off. Default 0.1.
   */
  vtkSetClampMacro(PlaneDistanceThreshold, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(PlaneDistanceThreshold, double);
  ///@}

  ///@{
  /**
   * p / s when AutomaticThresholds is on. Default 0.1.
   */
  vtkSetClampMacro(PlaneDistanceRatio, double, 0.001, 1.0);
  vtkGetMacro(PlaneDistanceRatio, double);
  ///@}

  ///@{
  /**
   * Fewest points a direction needs for its circle fit. Default 3 (the least
   * that determines a circle).
   */
  vtkSetClampMacro(MinimumPointsPerDirection, int, 3, 1000000);
  vtkGetMacro(MinimumPointsPerDirection, int);
  ///@}

  ///@{
  /**
   * Upper bound on the number of threads; 0 (default) uses all cores.
   */
  vtkSetClampMacro(NumberOfThreads, int, 0, 4096);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /**
   * Output size. SinglePrecisionOutput (default off) writes the curvature
   * arrays, directions, shape index, curvedness, diagnostics and estimated
   * normals as float instead of double (the points stay as they are:
   * coordinates far from the origin need their precision).
   * DiagnosticArrays (default on) adds the arrays that say how each point
   * was estimated: Neighbor_Count, Valid_Direction_Count, Sine_Fit_RMS,
   * Surroundings_Threshold, Plane_Distance_Threshold,
   * Curvature_Standard_Error and Target_Neighbor_Count, and the display
   * array Mean_Curvature_Clipped (the active scalars; without it,
   * Mean_Curvature is).
   */
  vtkSetMacro(SinglePrecisionOutput, bool);
  vtkGetMacro(SinglePrecisionOutput, bool);
  vtkBooleanMacro(SinglePrecisionOutput, bool);
  vtkSetMacro(DiagnosticArrays, bool);
  vtkGetMacro(DiagnosticArrays, bool);
  vtkBooleanMacro(DiagnosticArrays, bool);
  ///@}

  ///@{
  /**
   * Dynamic variable adjustment (Getto & Hildenbrand 2011, section 5): the
   * surroundings-threshold found for one point is used for the next and
   * adapted to reach a target neighbour count, the plane-distance-threshold
   * follows the count found, and the targets step between three
   * combinations as s shrinks or grows. When on, NeighborhoodMode,
   * AutomaticThresholds, SurroundingsThreshold and PlaneDistance* are
   * ignored. Points are processed in the neighbour grid's spatially coherent
   * order, grouped into blocks (cells of a lattice in space) that each start
   * like the paper's first point (initial s, first targets, the first
   * search repeated with the adjusted s): see AdjustmentBlockLength. Default
   * off.
   */
  vtkSetMacro(DynamicAdjustment, bool);
  vtkGetMacro(DynamicAdjustment, bool);
  vtkBooleanMacro(DynamicAdjustment, bool);
  ///@}

  ///@{
  /**
   * The length unit L that multiplies every length of the adjustment
   * (initial s, switch lengths, target plane distances). With
   * AutomaticLengthUnit on (default), L is derived from the cloud so that
   * the initial s (4 L) holds about TargetNeighborCounts[0] points: the
   * method is then scale free. Off, LengthUnit is used (default 1: the
   * paper's absolute values).
   */
  vtkSetMacro(AutomaticLengthUnit, bool);
  vtkGetMacro(AutomaticLengthUnit, bool);
  vtkBooleanMacro(AutomaticLengthUnit, bool);
  vtkSetClampMacro(LengthUnit, double, 1e-300, VTK_DOUBLE_MAX);
  vtkGetMacro(LengthUnit, double);
  ///@}

  ///@{
  /**
   * The adjustment's constants (the paper's by default): the initial s (4,
   * in units of L), the target neighbour counts (375, 750, 1500) and plane
   * distances (0.1, 0.05, 0.025, in units of L) of the three combinations,
   * and the switch lengths (2: to the second combination below it; 1: to
   * the third below it; 4: one combination back above it; in units of L).
   */
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
  /**
   * Set TargetNeighborCounts, TargetPlaneDistances and SwitchLengths at
   * once: to the paper's constants, or to the "banded ladder"
   * (docs/dynamic-adjustment.md): counts firstCount, 2 firstCount,
   * 4 firstCount, plane distance planeDistance L at every level, switch
   * lengths next to the initial s (pcurv::BandedLadder), so that the target
   * count doubles where the density grows and the radius stays in a band.
   * The documentation gives the measured settings for clean and noisy
   * clouds.
   */
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
  /**
   * The surroundings-threshold never grows beyond this factor times the
   * initial one (the paper has no bound; without one a far sparser region
   * would grow it without limit, and a parallel run must know how far a
   * query can reach). Default 4.
   */
  vtkSetClampMacro(MaximumSurroundingsFactor, double, 1.0, 1e6);
  vtkGetMacro(MaximumSurroundingsFactor, double);
  ///@}

  ///@{
  /**
   * Side of the adjustment's blocks, in units of L (default 8: a block then
   * holds about 500 points of a surface at the first target). Blocks are
   * the cells of a lattice fixed in space; the points of a block are
   * processed in the neighbour grid's order and each block starts afresh.
   * The block length, not the number of threads or processes, decides the
   * result.
   */
  vtkSetClampMacro(AdjustmentBlockLength, double, 1e-6, 1e6);
  vtkGetMacro(AdjustmentBlockLength, double);
  ///@}

  ///@{
  /**
   * Where the normals come from (default AUTOMATIC_NORMALS: real input
   * normals when there are some, estimated otherwise). A chosen array that
   * is not normals (an integer type such as RGB colours, all zero, or
   * lengths that vary like colours do) is an error that says how to
   * estimate normals instead. Estimated normals are fitted by PCA to the
   * NormalNeighbors nearest points, oriented consistently over a minimum
   * spanning tree, signed by NormalOrientation, and written to the output
   * as the "Normals" array (the active normals).
   */
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
  /**
   * What the last execution used and found: the surroundings-threshold and
   * plane-distance-threshold in RADIUS mode (0 in K_NEAREST mode, where they
   * vary per point), the length unit L of the dynamic adjustment, and the
   * number of points that could not be estimated.
   */
  vtkGetMacro(UsedSurroundingsThreshold, double);
  vtkGetMacro(UsedLengthUnit, double);
  vtkGetMacro(UsedPlaneDistanceThreshold, double);
  vtkGetMacro(NumberOfUnestimatedPoints, vtkIdType);
  ///@}

  /**
   * After an update with ShareFits: the points (of every process) that took
   * the fits of anchor points near them instead of fitting their own; the
   * output's field data "Shared_Fit_Points" holds it too.
   */
  vtkGetMacro(NumberOfSharedFitPoints, vtkIdType);

  /**
   * After an update with the automatic neighborhood: whether the cloud's
   * normals follow the surface as exact normals do (on most points of a
   * sample), so that the neighborhoods of 256 neighbors and more also fitted the
   * surface's fourth order where it shows (docs/method.md, section 10); the
   * output's field data "Fourth_Order_Fits" holds it too (1 or 0).
   */
  vtkGetMacro(FourthOrderFits, bool);

  /**
   * After an update with the automatic neighborhood: the points (of every
   * process) whose estimate is a fourth-order height jet of their 20
   * nearest neighbors, where the positions have little or no noise
   * (docs/method.md, section 10); the output's field data "Jet_Fit_Points"
   * holds it too.
   */
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
