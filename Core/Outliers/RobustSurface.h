/**
 * @file RobustSurface.h
 * @brief The surface a point's neighbors sample, fitted robustly (a plane,
 * then a quadratic height, each time without the neighbors far off it),
 * in units of the neighborhood's radius: internal to the outliers'
 * verdicts. No VTK.
 */
#ifndef RobustSurface_h
#define RobustSurface_h

#include <Eigen/Dense>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace pcurv
{
namespace outliers
{

/// A neighbor of the point judged: its offset from it in units of the
/// neighborhood's radius, and its id in the cloud.
struct Neighbor
{
  double Squared;
  Eigen::Vector3d Offset;
  std::int64_t Id;
};

/// The buffers of the fits (one thread's).
struct FitScratch
{
  std::vector<Neighbor> Nearest;
  std::vector<double> Residuals, Magnitudes;
  std::vector<unsigned char> Kept;
  /// Kept neighbors by squared distance to the foot, as (distance, index
  /// among Nearest).
  std::vector<std::pair<double, std::size_t>> ByFoot;
};

/// A neighborhood's surface in units of its radius, about the point
/// judged: a frame (origin, two tangents and the normal as columns) and
/// the height over its plane, h = a + b u + c v + d u^2 + e u v + f v^2.
struct LocalSurface
{
  Eigen::Vector3d Origin = Eigen::Vector3d::Zero();
  Eigen::Matrix3d Frame = Eigen::Matrix3d::Identity();
  Eigen::Matrix<double, 6, 1> Height = Eigen::Matrix<double, 6, 1>::Zero();

  Eigen::Vector3d Local(const Eigen::Vector3d& offset) const
  {
    return this->Frame.transpose() * (offset - this->Origin);
  }
  double HeightAt(double u, double v) const
  {
    const Eigen::Matrix<double, 6, 1>& h = this->Height;
    return h[0] + h[1] * u + h[2] * v + h[3] * u * u + h[4] * u * v + h[5] * v * v;
  }
  /// Signed distance along the frame's normal from the height surface.
  double Residual(const Eigen::Vector3d& offset) const
  {
    const Eigen::Vector3d p = this->Local(offset);
    return p.z() - this->HeightAt(p.x(), p.y());
  }
  /// The surface's point over p's foot in the plane.
  Eigen::Vector3d FootOf(const Eigen::Vector3d& offset) const
  {
    const Eigen::Vector3d p = this->Local(offset);
    return this->Origin + this->Frame * Eigen::Vector3d(p.x(), p.y(), this->HeightAt(p.x(), p.y()));
  }
};

/// The plane through the kept neighbors by PCA (false with fewer than 3):
/// the frame of a surface of zero height.
bool FitPlane(const std::vector<Neighbor>& nearest,
  const std::vector<unsigned char>& kept,
  LocalSurface& surface);

/// The quadratic height over the surface's plane, least squares over the
/// kept neighbors; the height stays as it is with too few of them.
void FitHeight(const std::vector<Neighbor>& nearest,
  const std::vector<unsigned char>& kept,
  LocalSurface& surface);

/// The surface of scratch.Nearest: a plane through the nearer half (which
/// an outlier among them rarely reaches), refitted to the neighbors near
/// it, then a quadratic height fitted twice the same way (scratch.Kept: the
/// neighbors of the last fit); `deviation` gets the noise's robust standard
/// deviation. False where the neighbors span no plane.
bool FitRobustSurface(FitScratch& scratch, LocalSurface& surface, double& deviation);

/// The spacing of the kept neighbors (in units of the radius): the median
/// of their distances to their nearest kept neighbor. Whatever the shape
/// of the patch they sample (a disc, the strip along an edge).
double SpacingAmong(FitScratch& scratch);

/// The kept neighbors by distance to the surface's foot of the point
/// judged (at the origin), nearest first, into scratch.ByFoot.
void RankByFoot(const LocalSurface& surface, FitScratch& scratch);

} // namespace outliers
} // namespace pcurv

#endif
