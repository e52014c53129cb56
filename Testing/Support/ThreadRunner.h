/**
 * @file ThreadRunner.h
 * @brief A WorkRunner on plain threads, for the tests and benchmarks of the
 * core (the filter uses VTK's SMP tools): ranges of `grain` items handed out
 * to the threads in turn.
 */
#ifndef ThreadRunner_h
#define ThreadRunner_h

#include "Common/WorkRunner.h"

#include <algorithm>
#include <cstdint>
#include <thread>
#include <vector>

namespace pcurv
{
namespace testing
{

class ThreadRunner : public WorkRunner
{
public:
  explicit ThreadRunner(int threads)
    : Threads(threads)
  {
  }

  void For(std::int64_t count, std::int64_t grain, const RangeWork& work) override
  {
    std::vector<std::thread> pool;
    for (int t = 0; t < this->Threads; ++t)
    {
      pool.emplace_back(
        [&, t]()
        {
          for (std::int64_t begin = t * grain; begin < count; begin += this->Threads * grain)
          {
            work(begin, std::min(count, begin + grain));
          }
        });
    }
    for (std::thread& thread : pool)
    {
      thread.join();
    }
  }

private:
  int Threads;
};

} // namespace testing
} // namespace pcurv

#endif
