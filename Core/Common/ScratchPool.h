/**
 * @file ScratchPool.h
 * @brief Reusable per-thread state for work run by a WorkRunner: a range
 * leases an object no other range uses meanwhile and gives it back at its
 * end, so that a functor owns its threads' scratch and the runner stays
 * generic. Objects are made on demand (as many as ranges run at once) and
 * reused; which one a range gets must not change its results. No VTK.
 */
#ifndef ScratchPool_h
#define ScratchPool_h

#include <memory>
#include <mutex>
#include <vector>

namespace pcurv
{

template<typename Scratch>
class ScratchPool
{
public:
  /// An object of the pool, given back when the lease ends.
  class Lease
  {
  public:
    explicit Lease(ScratchPool& pool)
      : Pool(pool)
      , Object(pool.Take())
    {
    }
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    ~Lease() { this->Pool.GiveBack(std::move(this->Object)); }
    Scratch& operator*() const { return *this->Object; }
    Scratch* operator->() const { return this->Object.get(); }

  private:
    ScratchPool& Pool;
    std::unique_ptr<Scratch> Object;
  };

private:
  std::unique_ptr<Scratch> Take()
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    if (this->Free.empty())
    {
      return std::make_unique<Scratch>();
    }
    std::unique_ptr<Scratch> object = std::move(this->Free.back());
    this->Free.pop_back();
    return object;
  }

  void GiveBack(std::unique_ptr<Scratch> object)
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    this->Free.push_back(std::move(object));
  }

  std::mutex Mutex;
  std::vector<std::unique_ptr<Scratch>> Free;
};

} // namespace pcurv

#endif
