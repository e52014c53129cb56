/**
 * @file WorkRunner.h
 * @brief The core's parallel loop: a runner hands out ranges of work items
 * to threads (the caller's: VTK's SMP tools in the filter, plain threads in
 * the tests). The runner knows nothing of the work: state a thread needs
 * belongs to the caller's functor (ScratchPool.h). No VTK.
 */
#ifndef WorkRunner_h
#define WorkRunner_h

#include <cstdint>
#include <functional>

namespace pcurv
{

/// Work on the items [begin, end) of a range.
using RangeWork = std::function<void(std::int64_t begin, std::int64_t end)>;

/// Runs the work items [0, count), possibly on several threads.
class WorkRunner
{
public:
  virtual ~WorkRunner() = default;
  /// Calls `work` on ranges of at least `grain` items (except the last)
  /// that together cover [0, count) once, possibly several at a time.
  virtual void For(std::int64_t count, std::int64_t grain, const RangeWork& work) = 0;
};

/// All items in the calling thread.
class SerialRunner : public WorkRunner
{
public:
  void For(std::int64_t count, std::int64_t grain, const RangeWork& work) override;
};

/// The items in `runner` when there is one, else in the calling thread.
void RunRanges(WorkRunner* runner, std::int64_t count, std::int64_t grain, const RangeWork& work);

} // namespace pcurv

#endif
