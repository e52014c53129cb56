#include "Cloud/Collectives.h"

namespace pcurv
{

std::vector<double> Collectives::Gather(const std::vector<double>& values,
  std::vector<std::int64_t>* lengths) const
{
  if (lengths)
  {
    lengths->assign(1, static_cast<std::int64_t>(values.size()));
  }
  return values;
}

} // namespace pcurv
