#include "NormalsChoice.h"

#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

namespace pcurv
{
namespace normals_choice
{

/// The array is meant as normals: the normals attribute, or a name that
/// says so ("Normals", "normal", "Normals_PCA"...). Colors, RGB or any other
/// 3-component array are not.
bool NamedLikeNormals(vtkDataArray* array, vtkPointSet* input)
{
  if (!array)
  {
    return false;
  }
  if (array == input->GetPointData()->GetNormals())
  {
    return true;
  }
  std::string name = array->GetName() ? array->GetName() : "";
  std::transform(
    name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
  return name.find("normal") != std::string::npos;
}

/// Why `normals` (3 components) cannot be normals, or empty: an integer
/// type (colors), all zero, or lengths that vary like colors do (normals
/// scaled alike, even by 1e-170, are fine: they are normalized).
std::string NotNormalsReason(vtkDataArray* normals)
{
  if (normals->GetDataType() != VTK_FLOAT && normals->GetDataType() != VTK_DOUBLE)
  {
    return std::string("is of type ") + normals->GetDataTypeAsString() +
      ", as colors are; normals are floating-point";
  }
  const vtkIdType count = normals->GetNumberOfTuples();
  const vtkIdType stride = std::max<vtkIdType>(1, count / 4096);
  std::vector<double> lengths;
  for (vtkIdType i = 0; i < count; i += stride)
  {
    double n[3];
    normals->GetTuple(i, n);
    // Scaled by the largest component first: lengths of 1e-170 do not
    // underflow, nor 1e170 overflow.
    const double largest = std::max({ std::fabs(n[0]), std::fabs(n[1]), std::fabs(n[2]) });
    const double length =
      largest > 0.0 ? largest * std::hypot(n[0] / largest, n[1] / largest, n[2] / largest) : 0.0;
    if (length > 0.0 && std::isfinite(length))
    {
      lengths.push_back(length);
    }
  }
  if (lengths.empty())
  {
    return "has no non-zero finite vector (all normals zero)";
  }
  std::sort(lengths.begin(), lengths.end());
  const double low = lengths[lengths.size() / 10], high = lengths[lengths.size() * 9 / 10];
  const double median = lengths[lengths.size() / 2];
  if (high > 2.0 * low && (median < 0.5 || median > 2.0))
  {
    return "has lengths from " + std::to_string(low) + " to " + std::to_string(high) +
      " (10th to 90th percentile), as colors or other data have; normals have one length";
  }
  return "";
}

} // namespace normals_choice
} // namespace pcurv
