/**
 * Little-endian values in LAS files, read and written byte by byte so that
 * the code works on any host and on unaligned records. No VTK here.
 */
#ifndef pcurv_LasBytes_h
#define pcurv_LasBytes_h

#include <cstdint>
#include <cstring>
#include <string>

namespace pcurv
{
namespace las
{

inline std::uint16_t U16(const unsigned char* p)
{
  return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}

inline std::uint32_t U32(const unsigned char* p)
{
  return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8) |
    (static_cast<std::uint32_t>(p[2]) << 16) | (static_cast<std::uint32_t>(p[3]) << 24);
}

inline std::uint64_t U64(const unsigned char* p)
{
  return static_cast<std::uint64_t>(U32(p)) | (static_cast<std::uint64_t>(U32(p + 4)) << 32);
}

/// The bits of an unsigned integer of the same size as T, as a T.
template<typename T, typename Bits>
inline T FromBits(Bits bits)
{
  static_assert(sizeof(T) == sizeof(Bits), "same size");
  T value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

inline double F64(const unsigned char* p)
{
  return FromBits<double>(U64(p));
}

inline std::int32_t I32(const unsigned char* p)
{
  return FromBits<std::int32_t>(U32(p));
}

/// Writes the low `size` bytes of bits at p, least significant first.
inline void PutBits(unsigned char* p, std::uint64_t bits, int size)
{
  for (int i = 0; i < size; ++i)
  {
    p[i] = static_cast<unsigned char>(bits >> (8 * i));
  }
}

/// Writes value (an integer or floating type) at p, little endian.
template<typename T>
inline void Put(unsigned char* p, T value)
{
  std::uint64_t bits = 0;
  if (sizeof(T) == 8)
  {
    std::memcpy(&bits, &value, 8);
  }
  else if (sizeof(T) == 4)
  {
    std::uint32_t b32;
    std::memcpy(&b32, &value, 4);
    bits = b32;
  }
  else if (sizeof(T) == 2)
  {
    std::uint16_t b16;
    std::memcpy(&b16, &value, 2);
    bits = b16;
  }
  else
  {
    std::uint8_t b8;
    std::memcpy(&b8, &value, 1);
    bits = b8;
  }
  PutBits(p, bits, static_cast<int>(sizeof(T)));
}

/// A fixed-size text field (user id, names): its text up to the first NUL.
inline std::string TextField(const unsigned char* p, std::size_t size)
{
  std::size_t n = 0;
  while (n < size && p[n] != 0)
  {
    ++n;
  }
  return std::string(reinterpret_cast<const char*>(p), n);
}

/// Writes text into a fixed-size field, the rest NUL (as the specification
/// asks); text longer than the field is cut.
inline void PutText(unsigned char* p, const std::string& text, std::size_t size)
{
  std::memset(p, 0, size);
  std::memcpy(p, text.data(), text.size() < size ? text.size() : size);
}

} // namespace las
} // namespace pcurv

#endif
