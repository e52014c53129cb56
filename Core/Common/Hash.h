/**
 * @file Hash.h
 * @brief A 64-bit mixer for hashing values: the same hash on every process
 * and platform, unlike std::hash. No VTK.
 */
#ifndef Hash_h
#define Hash_h

#include <cstdint>

namespace pcurv
{

/// splitmix64's finalizer: every input bit affects every output bit.
inline std::uint64_t Mix(std::uint64_t z)
{
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

} // namespace pcurv

#endif
