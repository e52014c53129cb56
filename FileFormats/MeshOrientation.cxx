#include "FileFormats/MeshOrientation.h"

#include <algorithm>
#include <vector>

namespace pcurv
{

bool NormalsMostlyInward(const double* points, const double* normals, std::size_t n)
{
  if (n == 0)
  {
    return false;
  }
  double centroid[3] = { 0.0, 0.0, 0.0 };
  for (std::size_t i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      centroid[c] += points[3 * i + c] / static_cast<double>(n);
    }
  }
  std::vector<double> outward(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    double dot = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      dot += (points[3 * i + c] - centroid[c]) * normals[3 * i + c];
    }
    outward[i] = dot;
  }
  // The median, as numpy.median takes it (the mean of the middle two).
  const std::size_t middle = n / 2;
  std::nth_element(outward.begin(), outward.begin() + middle, outward.end());
  double median = outward[middle];
  if (n % 2 == 0)
  {
    median = 0.5 * (median + *std::max_element(outward.begin(), outward.begin() + middle));
  }
  return median < 0.0;
}

} // namespace pcurv
