/**
 * @file MeshOrientation.h
 * @brief Which side a mesh's normals point to, decided apart from reading
 * the file: the OFF reader turns the normals it computes from the faces
 * outward with it. No VTK.
 */
#ifndef MeshOrientation_h
#define MeshOrientation_h

#include <cstddef>

namespace pcurv
{

/**
 * Whether most normals point towards the centroid of the points (the median
 * of (p - centroid) . n is negative): a closed, roughly star-shaped mesh
 * whose faces are ordered clockwise. n points and normals, 3 values each.
 */
bool NormalsMostlyInward(const double* points, const double* normals, std::size_t n);

} // namespace pcurv

#endif
