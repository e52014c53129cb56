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

} // namespace

int main(int argc, char* argv[])
{
  return RunNamedTests(argc,
    argv,
    {
      { "ShortRun", TestShortRun },
      { "LongRun", TestLongRun },
      { "NoEstimate", TestNoEstimate },
    });
}
