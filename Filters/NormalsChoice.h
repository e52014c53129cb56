/**
 * @file NormalsChoice.h
 * @brief Whether an input array can be the normals: private to the
 * filters, which take a scan's colors for normals never.
 */
#ifndef NormalsChoice_h
#define NormalsChoice_h

#include <string>

class vtkDataArray;
class vtkPointSet;

namespace pcurv
{
namespace normals_choice
{

/// The array is meant as normals: the normals attribute, or a name that
/// says so ("Normals", "normal", "Normals_PCA"...). Colors, RGB or any other
/// 3-component array are not.
bool NamedLikeNormals(vtkDataArray* array, vtkPointSet* input);

/// Why `normals` (3 components) cannot be normals, or empty: an integer
/// type (colors), all zero, or lengths that vary like colors do (normals
/// scaled alike, even by 1e-170, are fine: they are normalized).
std::string NotNormalsReason(vtkDataArray* normals);

} // namespace normals_choice
} // namespace pcurv

#endif
