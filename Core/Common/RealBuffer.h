/**
 * @file RealBuffer.h
 * @brief A caller's buffer of real values, in double or in single
 * precision. No VTK.
 */
#ifndef RealBuffer_h
#define RealBuffer_h

#include <cstddef>
#include <cstdint>

namespace pcurv
{

/// Where per-point results go, in the precision the caller keeps them:
/// single-precision output is written as such, with no double copy of
/// every array held beside it (on large clouds that copy was most of the
/// peak memory). Values are computed in double and rounded once, on Set.
class RealBuffer
{
public:
  RealBuffer() = default;
  RealBuffer(std::nullptr_t) {}
  RealBuffer(double* values)
    : Double(values)
  {
  }
  RealBuffer(float* values)
    : Single(values)
  {
  }

  explicit operator bool() const { return this->Double || this->Single; }

  double Get(std::int64_t i) const
  {
    return this->Double ? this->Double[i] : static_cast<double>(this->Single[i]);
  }
  void Set(std::int64_t i, double value) const
  {
    if (this->Double)
    {
      this->Double[i] = value;
    }
    else
    {
      this->Single[i] = static_cast<float>(value);
    }
  }
  /// Values i to i + count - 1 from `values`.
  void SetRange(std::int64_t i, const double* values, int count) const
  {
    for (int c = 0; c < count; ++c)
    {
      this->Set(i + c, values[c]);
    }
  }
  /// Value `to` gets value `from`, `count` values on.
  void CopyRange(std::int64_t from, std::int64_t to, int count) const
  {
    for (int c = 0; c < count; ++c)
    {
      this->Set(to + c, this->Get(from + c));
    }
  }
  /// Asks for the cache line of value i, to be written.
  void Prefetch(std::int64_t i) const
  {
    if (this->Double)
    {
      __builtin_prefetch(this->Double + i, 1);
    }
    else
    {
      __builtin_prefetch(this->Single + i, 1);
    }
  }

private:
  double* Double = nullptr;
  float* Single = nullptr;
};

} // namespace pcurv

#endif
