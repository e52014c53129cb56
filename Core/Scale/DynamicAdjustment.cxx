#include "Scale/DynamicAdjustment.h"

#include <algorithm>
#include <cmath>

namespace pcurv
{

AdjustmentSettings BandedLadder(double firstCount, double planeDistance)
{
  AdjustmentSettings ladder;
  ladder.TargetNeighborCounts = { { firstCount, 2.0 * firstCount, 4.0 * firstCount } };
  ladder.TargetPlaneDistances = { { planeDistance, planeDistance, planeDistance } };
  ladder.SwitchLengths = BandedLadderSwitchLengths;
  return ladder;
}

AdjustmentSettings AdjustmentConstants(AdjustmentPreset preset)
{
  switch (preset)
  {
    case AdjustmentPreset::Ladder:
      return BandedLadder(375.0, 0.2);
    case AdjustmentPreset::NoisyLadder:
      return BandedLadder(1000.0, 0.6);
    case AdjustmentPreset::Paper:
      break;
  }
  return AdjustmentSettings{};
}

DynamicAdjustment::DynamicAdjustment(const AdjustmentSettings& settings)
  : Settings(settings)
{
  this->Restart();
}

void DynamicAdjustment::Restart()
{
  this->Surroundings = this->Settings.InitialSurroundingsThreshold * this->Settings.LengthUnit;
  this->Level = 0;
}

double DynamicAdjustment::Adjust(int neighborCount)
{
  const AdjustmentSettings& c = this->Settings;
  const double target = c.TargetNeighborCounts[this->Level];
  // No neighbor at all: the formulas divide by zero; grow s by the largest
  // factor one neighbor would give instead (the paper is silent here).
  const double found = std::max(1, neighborCount);
  const double planeDistance = c.TargetPlaneDistances[this->Level] * c.LengthUnit * target / found;

  this->Surroundings = std::min(
    this->Surroundings * std::sqrt(target / found), c.MaximumSurroundingsThreshold * c.LengthUnit);
  const double s = this->Surroundings / c.LengthUnit;
  if (this->Level == 0 && s < c.SwitchLengths[0])
  {
    this->Level = 1;
  }
  if (this->Level == 1 && s < c.SwitchLengths[1])
  {
    this->Level = 2;
  }
  else if (this->Level > 0 && s > c.SwitchLengths[2])
  {
    --this->Level;
  }
  return planeDistance;
}

} // namespace pcurv
