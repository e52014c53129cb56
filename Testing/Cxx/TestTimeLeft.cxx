// The progress text's time left (no VTK): said only when the pace is
// known, never longer than the estimate by a rounding, and "less than
// 10 s" once the estimate is that short.
#include "Common/TimeLeft.h"
#include "TestChecks.h"

#include <cmath>
#include <string>

namespace
{
using pcurv::ProgressText;

/// A 3 s run, 85 % done at 2.55 s (0.45 s left): no "about 5 s".
void TestShortRun(Checks& checks)
{
  const std::string text = ProgressText("Run", 0.85, 2.55);
  checks.True(("a 3 s run at 85 %: '" + text + "'").c_str(), text == "Run: less than 10 s left");
  checks.True("a 3 s run at 99 %: less than 10 s",
    ProgressText("Run", 0.99, 2.97) == "Run: less than 10 s left");
  checks.True(
    "9 s left: less than 10 s", ProgressText("Run", 0.5, 9.0) == "Run: less than 10 s left");
}

/// Estimates of 10 s and more, to the nearest 5 s or minute.
void TestLongRun(Checks& checks)
{
  checks.True("12 s left: about 10 s", ProgressText("Run", 0.5, 12.0) == "Run: about 10 s left");
  checks.True("33 s left: about 35 s", ProgressText("Run", 0.5, 33.0) == "Run: about 35 s left");
  checks.True("150 s left: about 3 min (2.5 rounds up)",
    ProgressText("Run", 0.25, 50.0) == "Run: about 3 min left");
  checks.True("65 min left: about 1 h 5 min",
    ProgressText("Run", 0.5, 3900.0) == "Run: about 1 h 5 min left");
}

/// The label alone: the first second, below 1 %, at the end, and for a
/// clock that says nothing.
void TestNoEstimate(Checks& checks)
{
  checks.True("first second", ProgressText("Run", 0.5, 0.5) == "Run");
  checks.True("below 1 %", ProgressText("Run", 0.005, 30.0) == "Run");
  checks.True("done", ProgressText("Run", 1.0, 30.0) == "Run");
  checks.True("no time measured", ProgressText("Run", 0.5, std::nan("")) == "Run");
}

/// A run whose first steps report nothing for 4 s, then go at a steady
/// pace to the end at 24 s: the first estimate is near the 19 s left, not
/// the 416 s (about 7 min) the pace since the start would say.
void TestSilentStart(Checks& checks)
{
  pcurv::TimeLeftClock clock;
  std::string first;
  double firstAt = 0.0;
  for (double t = 0.0; t < 24.0 && first.empty(); t += 0.1)
  {
    const double fraction = t < 4.0 ? 0.0 : (t - 4.0) / 20.0;
    const std::string text = clock.Text("Run", fraction, t);
    checks.True("no estimate while nothing moved", t >= 4.0 || text == "Run");
    if (text != "Run")
    {
      first = text;
      firstAt = t;
    }
  }
  checks.True(("the first estimate, at " + std::to_string(firstAt) + " s: '" + first + "'").c_str(),
    first == "Run: about 20 s left" || first == "Run: about 15 s left");
  checks.True("then the pace of the run: about 10 s left at 14 s",
    clock.Text("Run", 0.5, 14.0) == "Run: about 10 s left");
}

/// A clock that never saw progress says the label alone, and a clock
/// whose elapsed time is unknown does not start measuring.
void TestClockWithoutPace(Checks& checks)
{
  pcurv::TimeLeftClock clock;
  checks.True("nothing done", clock.Text("Run", 0.0, 30.0) == "Run");
  checks.True("no time measured", clock.Text("Run", 0.5, std::nan("")) == "Run");
  checks.True("done", clock.Text("Run", 1.0, 40.0) == "Run");
}

} // namespace

int main(int argc, char* argv[])
{
  return RunNamedTests(argc,
    argv,
    {
      { "ShortRun", TestShortRun },
      { "LongRun", TestLongRun },
      { "NoEstimate", TestNoEstimate },
      { "SilentStart", TestSilentStart },
      { "ClockWithoutPace", TestClockWithoutPace },
    });
}
