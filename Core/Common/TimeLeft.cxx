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

/// ProgressText with the pace measured from `firstFraction` done at
/// `firstSeconds`.
std::string TextSince(const std::string& label,
  double fraction,
  double elapsedSeconds,
  double firstFraction,
  double firstSeconds)
{
  const double seconds = elapsedSeconds - firstSeconds;
  const double done = fraction - firstFraction;
  // Before a second has passed or 1 % is done, the pace says little (the
  // first stages are not the slowest).
  if (!(seconds >= 1.0) || !(done >= 0.01) || fraction >= 1.0)
  {
    return label;
  }
  const double secondsLeft = seconds * (1.0 - fraction) / done;
  if (secondsLeft < ShortestEstimate)
  {
    return label + ": less than " + std::to_string(ShortestEstimate) + " s left";
  }
  return label + ": about " + RoughDuration(secondsLeft) + " left";
}
} // namespace

std::string ProgressText(const std::string& label, double fraction, double elapsedSeconds)
{
  return TextSince(label, std::min(std::max(fraction, 0.0), 1.0), elapsedSeconds, 0.0, 0.0);
}

std::string TimeLeftClock::Text(const std::string& label, double fraction, double elapsedSeconds)
{
  fraction = std::min(std::max(fraction, 0.0), 1.0);
  if (!this->Moved && fraction > 0.0 && std::isfinite(elapsedSeconds))
  {
    this->Moved = true;
    this->FirstFraction = fraction;
    this->FirstSeconds = elapsedSeconds;
  }
  return this->Moved
    ? TextSince(label, fraction, elapsedSeconds, this->FirstFraction, this->FirstSeconds)
    : label;
}

} // namespace pcurv
