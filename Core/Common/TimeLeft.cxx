#include "Common/TimeLeft.h"

#include <algorithm>
#include <cmath>

namespace pcurv
{
namespace
{
/// Below this many seconds the estimate is only said to be short.
constexpr int ShortestEstimate = 10;

/// "35 s", "2 min", "1 h 5 min": coarse enough not to flicker, to the
/// nearest 5 s below a minute, to the nearest minute above.
std::string RoughDuration(double seconds)
{
  if (seconds < 57.5)
  {
    return std::to_string(5 * std::max(2L, std::lround(seconds / 5.0))) + " s";
  }
  const long minutes = std::lround(seconds / 60.0);
  if (minutes < 60)
  {
    return std::to_string(minutes) + " min";
  }
  return std::to_string(minutes / 60) + " h " + std::to_string(minutes % 60) + " min";
}
} // namespace

std::string ProgressText(const std::string& label, double fraction, double elapsedSeconds)
{
  fraction = std::min(std::max(fraction, 0.0), 1.0);
  // Before a second has passed or 1 % is done, the pace says little (the
  // first stages are not the slowest).
  if (!(elapsedSeconds >= 1.0) || fraction < 0.01 || fraction >= 1.0)
  {
    return label;
  }
  const double secondsLeft = elapsedSeconds * (1.0 - fraction) / fraction;
  if (secondsLeft < ShortestEstimate)
  {
    return label + ": less than " + std::to_string(ShortestEstimate) + " s left";
  }
  return label + ": about " + RoughDuration(secondsLeft) + " left";
}

} // namespace pcurv
