#include "Common/WorkRunner.h"

namespace pcurv
{

void SerialRunner::For(std::int64_t count, std::int64_t, const RangeWork& work)
{
  work(0, count);
}

void RunRanges(WorkRunner* runner, std::int64_t count, std::int64_t grain, const RangeWork& work)
{
  if (runner)
  {
    runner->For(count, grain, work);
  }
  else
  {
    work(0, count);
  }
}

} // namespace pcurv
