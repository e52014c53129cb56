/**
 * @file ScaledCovariance.h
 * @brief The covariance of a neighborhood's offsets in units of its size
 * (the PCA of the normals, the height jet's plane). No VTK.
 */
#ifndef ScaledCovariance_h
#define ScaledCovariance_h

#include <Eigen/Dense>

#include <cstddef>

namespace pcurv
{

/// The sum of the outer products of `count` offsets (dx, dy, dz) about
/// their mean, the offsets multiplied by `inverseScale` first: in units of
/// the neighborhood's size, its entries neither underflow nor overflow
/// whatever the coordinates' unit. The sums run in the offsets' order, one
/// accumulator an entry.
inline Eigen::Matrix3d ScaledCovariance(const double* dx,
  const double* dy,
  const double* dz,
  std::size_t count,
  double inverseScale)
{
  double mx = 0.0, my = 0.0, mz = 0.0;
  for (std::size_t i = 0; i < count; ++i)
  {
    mx += dx[i] * inverseScale;
    my += dy[i] * inverseScale;
    mz += dz[i] * inverseScale;
  }
  const double size = static_cast<double>(count);
  mx /= size;
  my /= size;
  mz /= size;
  double xx = 0.0, yx = 0.0, zx = 0.0, yy = 0.0, zy = 0.0, zz = 0.0;
  for (std::size_t i = 0; i < count; ++i)
  {
    const double x = dx[i] * inverseScale - mx;
    const double y = dy[i] * inverseScale - my;
    const double z = dz[i] * inverseScale - mz;
    xx += x * x;
    yx += y * x;
    zx += z * x;
    yy += y * y;
    zy += z * y;
    zz += z * z;
  }
  Eigen::Matrix3d covariance;
  covariance << xx, yx, zx, yx, yy, zy, zx, zy, zz;
  return covariance;
}

} // namespace pcurv

#endif
