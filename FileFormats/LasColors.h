/**
 * @file LasColors.h
 * @brief A LAS file's colors as 8-bit RGB, the form a display shows
 * directly. No VTK.
 */
#ifndef LasColors_h
#define LasColors_h

#include <cstdint>
#include <cstddef>

namespace pcurv
{
namespace las
{

/// The LAS specification stores Red, Green and Blue as 16-bit values
/// (0-65535), but many writers put 8-bit values (0-255) in those fields.
/// True when some value exceeds 255: the colors are then 16-bit.
bool HasSixteenBitColors(const std::uint16_t* red,
  const std::uint16_t* green,
  const std::uint16_t* blue,
  std::size_t count);

/// `rgb` (3 values per point, interleaved) from the three channels: 16-bit
/// values scaled to 0-255 (65535 to 255, rounded), 8-bit ones kept, as
/// `sixteenBit` says (HasSixteenBitColors over the same points).
void ToEightBitColors(const std::uint16_t* red,
  const std::uint16_t* green,
  const std::uint16_t* blue,
  std::size_t count,
  bool sixteenBit,
  std::uint8_t* rgb);

} // namespace las
} // namespace pcurv

#endif
