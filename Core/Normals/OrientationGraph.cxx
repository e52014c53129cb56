#include "Normals/OrientationGraph.h"

namespace pcurv
{

void DropRepeatedEdges(PlaneFits& fits, WorkRunner& runner)
{
  const int k = fits.GraphNeighbors;
  const std::int64_t n = static_cast<std::int64_t>(fits.Normals.size() / 3);
  std::vector<unsigned char> repeated(static_cast<std::size_t>(fits.Neighbors.Size()), 0);
  runner.For(n,
    4096,
    [&](std::int64_t begin, std::int64_t end)
    {
      fits.Neighbors.Visit(
        [&](const auto* ids)
        {
          for (std::int64_t a = begin; a < end; ++a)
          {
            for (int e = 0; e < k; ++e)
            {
              const std::int64_t b = ids[a * k + e];
              if (b > a)
              {
                const auto* back = ids + b * k;
                repeated[a * k + e] = std::find(back, back + k, a) != back + k;
              }
            }
          }
        });
    });
  runner.For(fits.Neighbors.Size(),
    1 << 16,
    [&](std::int64_t begin, std::int64_t end)
    {
      for (std::int64_t i = begin; i < end; ++i)
      {
        if (repeated[i])
        {
          fits.Neighbors.Set(i, -1);
        }
      }
    });
}

} // namespace pcurv
