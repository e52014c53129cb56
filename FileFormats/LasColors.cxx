#include "FileFormats/LasColors.h"

namespace pcurv
{
namespace las
{

bool HasSixteenBitColors(const std::uint16_t* red,
  const std::uint16_t* green,
  const std::uint16_t* blue,
  std::size_t count)
{
  for (std::size_t i = 0; i < count; ++i)
  {
    if (red[i] > 255 || green[i] > 255 || blue[i] > 255)
    {
      return true;
    }
  }
  return false;
}

void ToEightBitColors(const std::uint16_t* red,
  const std::uint16_t* green,
  const std::uint16_t* blue,
  std::size_t count,
  bool sixteenBit,
  std::uint8_t* rgb)
{
  // 65535 / 255 = 257 exactly: v / 257, rounded, maps 0-65535 onto 0-255.
  auto eightBit = [sixteenBit](std::uint16_t value)
  { return static_cast<std::uint8_t>(sixteenBit ? (value + 128u) / 257u : value); };
  for (std::size_t i = 0; i < count; ++i)
  {
    rgb[3 * i] = eightBit(red[i]);
    rgb[3 * i + 1] = eightBit(green[i]);
    rgb[3 * i + 2] = eightBit(blue[i]);
  }
}

} // namespace las
} // namespace pcurv
