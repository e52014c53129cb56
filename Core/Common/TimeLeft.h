/**
 * @file TimeLeft.h
 * @brief The progress text a long run shows: its label and, when the pace
 * says something, the time left. No VTK.
 */
#ifndef TimeLeft_h
#define TimeLeft_h

#include <string>

namespace pcurv
{

/// "Principal curvatures: about 2 min left": `label` and the time left if
/// the rest goes at the pace so far (`elapsedSeconds` since the start, the
/// part `fraction` done). `label` alone while the pace is not yet known
/// (the first second, or less than 1 % done) and at the end; "less than
/// 10 s left" once the estimate is that short: a countdown in seconds is
/// not worth reading there, and the stages do not all go at one pace.
/// ParaView's progress bar adds the percentage.
std::string ProgressText(const std::string& label, double fraction, double elapsedSeconds);

/// The progress text of a run whose first steps may report no progress at
/// all (the serial steps before the first counted stage take seconds on
/// millions of points): the pace is measured from the first time the
/// fraction was seen to move, so that the time those steps took is not
/// charged to every percent still to go.
class TimeLeftClock
{
public:
  /// ProgressText over the part of the run since the fraction first moved.
  std::string Text(const std::string& label, double fraction, double elapsedSeconds);

private:
  bool Moved = false;
  double FirstFraction = 0.0;
  double FirstSeconds = 0.0;
};

} // namespace pcurv

#endif
