/**
 * @file IndexList.h
 * @brief A list of point indices (or -1 for none), 32-bit where the
 * largest index allows: per-point lists of indices are among the largest
 * arrays of an estimate, and no cloud a process holds comes near 2^31
 * points in practice, yet one that does still works.
 */
#ifndef IndexList_h
#define IndexList_h

#include <cstdint>
#include <limits>
#include <vector>

namespace pcurv
{

class IndexList
{
public:
  /// `count` entries of `value` (-1: none), able to hold indices up to
  /// `largest`.
  void Assign(std::int64_t count, std::int64_t largest, std::int32_t value = -1)
  {
    this->Wide = largest > std::numeric_limits<std::int32_t>::max();
    this->Long.assign(this->Wide ? count : 0, value);
    this->Short.assign(this->Wide ? 0 : count, value);
  }
  std::int64_t Size() const
  {
    return static_cast<std::int64_t>(this->Wide ? this->Long.size() : this->Short.size());
  }
  std::int64_t operator[](std::int64_t i) const
  {
    return this->Wide ? this->Long[i] : this->Short[i];
  }
  /// Calls `visit` with the indices as a pointer to their stored type.
  template<typename Visitor>
  void Visit(Visitor&& visit)
  {
    if (this->Wide)
    {
      visit(this->Long.data());
    }
    else
    {
      visit(this->Short.data());
    }
  }
  template<typename Visitor>
  void Visit(Visitor&& visit) const
  {
    if (this->Wide)
    {
      visit(this->Long.data());
    }
    else
    {
      visit(this->Short.data());
    }
  }
  void Set(std::int64_t i, std::int64_t index)
  {
    if (this->Wide)
    {
      this->Long[i] = index;
    }
    else
    {
      this->Short[i] = static_cast<std::int32_t>(index);
    }
  }

private:
  bool Wide = false;
  std::vector<std::int32_t> Short;
  std::vector<std::int64_t> Long;
};

} // namespace pcurv

#endif
