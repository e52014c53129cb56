/**
 * @file PrincipalCurvatureCore.h
 * @brief Numeric core of principal curvature estimation by osculating-circle
 * fitting in conformal geometric algebra (Seibert et al. 2010, Getto &
 * Hildenbrand 2011). No VTK types: this header can be used, tested and
 * profiled on its own.
 *
 * Conventions (docs/method.md describes the method as implemented):
 * - Circle fits work in the paper's sign: a circle whose center lies on the
 *   normal's side has positive curvature.
 * - Results leaving the core (PointCurvature) are in the output sign:
 *   positive where the surface bends away from the normal, so a sphere with
 *   outward normals has k_min = k_max = +1/R.
 */
#ifndef PrincipalCurvatureCore_h
#define PrincipalCurvatureCore_h

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "Fits/FitResults.h"
#include "Kernels/SimdKernels.h"

namespace pcurv
{

/// Running sums of one direction from which the CGA matrix B is formed:
///   B = [a b c; b d e; c e f], a = sum h^2, b = -sum h, c = -1/2 sum h D,
///   d = N, e = 1/2 sum D, f = 1/4 sum D^2.
struct CgaSums
{
  double SumH2 = 0.0;
  double SumH = 0.0;
  double SumHD = 0.0;
  double SumD = 0.0;
  double SumD2 = 0.0;
  int Count = 0;
  /// Farthest reach of the direction's points along it (t . v_i).
  double Extent = 0.0;

  void Add(double h, double squaredDistance, double along = 0.0)
  {
    this->Extent = std::max(this->Extent, along);
    this->SumH2 += h * h;
    this->SumH += h;
    this->SumHD += h * squaredDistance;
    this->SumD += squaredDistance;
    this->SumD2 += squaredDistance * squaredDistance;
    ++this->Count;
  }
};

/// Result of one circle fit, paper sign.
struct CircleFit
{
  bool Valid = false;
  double Curvature = 0.0;
};

/// Previous fit: eigenvector S of the smallest eigenvalue of B,
/// kappa = sign(s_n) s_0 / sqrt(s_n^2 - 2 s_inf s_0). Invalid for an
/// imaginary sphere (negative radicand).
CircleFit FitPrevious(const CgaSums& sums);

/// The same fit with the eigenvector from Eigen's iterative symmetric
/// eigensolver alone: FitPrevious's fallback, and its reference in tests.
CircleFit FitPreviousWithEigenSolver(const CgaSums& sums);

/// kappa_12 = (a d - b^2) / (b e - c d): least squares with s_0 = 1.
CircleFit FitEquations12(const CgaSums& sums);

/// kappa_23 = (c d - b e) / (e^2 - f d): regression of h on D/2 (New01).
CircleFit FitEquations23(const CgaSums& sums);

/// Geometric distance of a point (height h, squared distance D from the
/// query point) to the circle through the query point whose center is
/// normal / kappa; stable for kappa -> 0.
inline double DistanceToCircle(double kappa, double h, double squaredDistance)
{
  const double radicand = kappa * kappa * squaredDistance - 2.0 * kappa * h + 1.0;
  return std::fabs(kappa * squaredDistance - 2.0 * h) /
    (1.0 + std::sqrt(radicand > 0.0 ? radicand : 0.0));
}

/// Three-parameter least-squares sine fit of known frequency (IEEE Std 1241)
/// of the paper-sign curvatures kappa_i = C + Ac cos(2 theta_i) + As sin(2 theta_i).
struct SineFit
{
  bool Valid = false;
  double Offset = 0.0;
  double CosineAmplitude = 0.0;
  double SineAmplitude = 0.0;
  double RmsResidual = 0.0;
  int ValidDirections = 0;
};

/// Fits over the valid directions only. Requires at least three distinct
/// values of 2 theta that are not contained in any closed half-turn, i.e.
/// the largest circular gap between them is below pi; otherwise Valid=false.
SineFit FitSine(const std::array<double, NumberOfDirections>& curvature,
  const std::array<bool, NumberOfDirections>& valid);

/// Converts a sine fit (paper sign) in the frame into output-sign principal
/// curvatures and directions.
void PrincipalCurvaturesFromSine(const SineFit& fit,
  const TangentFrame& frame,
  PointCurvature& out);

/**
 * Estimates the principal curvatures at one point from its neighbors.
 * Reuse one instance per thread: it keeps its scratch buffers.
 *
 * Usage: Begin(x, n, p); AddNeighbor(q) for each neighbor; Estimate(settings).
 * All geometry is taken relative to x and divided by the largest neighbor
 * distance before fitting, so results do not depend on where the cloud sits
 * or on its unit (up to the unit of the curvature).
 */
class PointCurvatureEstimator
{
public:
  /// Starts a query at `point` with unit normal `unitNormal`, the
  /// plane-distance-threshold `planeDistance` and the neighborhood's size
  /// `scale` (the surroundings-threshold; lengths > 0). Lengths are divided
  /// by `scale` before anything is summed, so that the CGA matrix is well
  /// conditioned and the result does not depend on the cloud's unit.
  void Begin(const Vector3& point, const Vector3& unitNormal, double planeDistance, double scale);

  /// Adds `count` neighbors (xyz triplets) in one pass: coordinates in the
  /// tangent frame, half-plane membership and the six sums of each
  /// direction. A neighbor that coincides with the query point carries no
  /// information about the curvature and is ignored.
  void AddNeighbors(const double* coordinates, std::size_t count);
  void AddNeighbor(const double q[3]) { this->AddNeighbors(q, 1); }

  /// The same for neighbors given as offsets q - x from the query point,
  /// one array per axis (as PointGrid::GatherOffsetsWithinRadius writes
  /// them): the same results as AddNeighbors, without the copy.
  void AddNeighborOffsets(const double* dx, const double* dy, const double* dz, std::size_t count);

  /// Number of neighbors added so far (coincident points excluded).
  int GetNumberOfNeighbors() const { return static_cast<int>(this->NumberOfAdded); }

  /// Forms each direction's sums from the neighbors binned into its half
  /// plane, fits a circle per direction and a sine over the directions.
  PointCurvature Estimate(const FitSettings& settings);

  /// Bit i is set when a neighbor at tangent coordinates (tx, ty) belongs
  /// to direction i for the plane-distance-threshold p: t . v_i > 0 and
  /// |t . (n x v_i)| < p. Binned by polar angle: only the few directions
  /// near the neighbor's angle are tested.
  static std::uint32_t DirectionMask(double tx, double ty, double p);

private:
  /// Makes room for `neighbors` neighbors in all, keeping those added.
  void Reserve(std::size_t neighbors);
  /// The six sums of each direction from its banks and rare record.
  void SumBanks();
  /// The circle of each direction and its curvature (DirectionValid,
  /// DirectionCurvature) by the settings' mode.
  void FitDirections(const FitSettings& settings);
  /// New02: where a direction has both circles, the one closer to its
  /// points into `candidate23`.
  void KeepCloserCircles(const std::array<CircleFit, NumberOfDirections>& candidate12,
    std::array<CircleFit, NumberOfDirections>& candidate23);
  /// The heights and squared distances of the neighbors of each `wanted`
  /// direction side by side in DirectionH and DirectionD (a row of
  /// `stride` per direction), and their `count` per row.
  void GatherDirections(std::uint32_t wanted,
    std::size_t stride,
    std::array<std::size_t, NumberOfDirections + 1>& count);

  Vector3 Point{ { 0.0, 0.0, 0.0 } };
  TangentFrame Frame{};
  double InverseScale = 0.0;
  double ScaledPlaneDistance = 0.0;

  /// The neighbors added so far, in the order added (units of the scale):
  /// height above the tangent plane, squared distance, tangent coordinates,
  /// and the directions each is in (New02's second pass reads them). A
  /// neighbor at the query point takes a slot but no direction, and is not
  /// counted in NumberOfAdded.
  std::size_t NumberOfSlots = 0;
  std::size_t NumberOfAdded = 0;
  std::size_t Capacity = 0;
  std::vector<double> AddedH, AddedD, AddedTx, AddedTy;
  std::vector<std::int64_t> AddedMask;

  /// The running sums the classification adds every neighbor to
  /// (binning::Block): banks by slot for those in one half plane, one
  /// record per direction for the rare others. Adding each neighbor into
  /// sums picked at run time made each add wait for the previous one's
  /// store (36 ns per neighbor in the first version); direction lists
  /// summed afterwards halved that; banks by slot, with a vector add per
  /// neighbor, need no lists.
  std::vector<double> Banks;
  binning::Block Binned;

  /// New02: each direction's heights and squared distances side by side.
  std::vector<double> DirectionH, DirectionD;

  std::array<CgaSums, NumberOfDirections> Sums{};
  std::array<double, NumberOfDirections> DirectionCurvature{};
  std::array<bool, NumberOfDirections> DirectionValid{};
};

} // namespace pcurv

#endif
