#include "PrincipalCurvatureCloud.h"

#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pcurv
{
namespace
{
constexpr int PointRecordSize = 6; // x y z nx ny nz

/// Squared distance from x to the box [lower, upper] (0 inside).
double SquaredDistanceToBox(const double* x, const double lower[3], const double upper[3])
{
  double squared = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const double outside = std::max({ lower[k] - x[k], 0.0, x[k] - upper[k] });
    squared += outside * outside;
  }
  return squared;
}

std::uint64_t Mix(std::uint64_t z)
{
  // splitmix64's finaliser: every input bit affects every output bit.
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}
/// n scaled to unit length, or zero when it has no direction (zero, NaN or
/// Inf components). Divided by its largest component first, so that the
/// squares neither overflow (length 1e170) nor underflow (length 1e-170).
void UnitNormal(double n[3])
{
  const double largest = std::max({ std::fabs(n[0]), std::fabs(n[1]), std::fabs(n[2]) });
  if (!(largest > 0.0 && std::isfinite(largest + n[0] + n[1] + n[2])))
  {
    n[0] = n[1] = n[2] = 0.0;
    return;
  }
  for (int k = 0; k < 3; ++k)
  {
    n[k] /= largest;
  }
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (int k = 0; k < 3; ++k)
  {
    n[k] /= length;
  }
}
} // namespace

void CloudPoints::Read(vtkPointSet* input, vtkDataArray* normals)
{
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  this->Coordinates.clear();
  this->Normals.clear();
  this->InputIds.clear();
  this->FiniteInput.assign(numberOfPoints, 0);
  this->Coordinates.reserve(3 * numberOfPoints);
  this->Normals.reserve(3 * numberOfPoints);
  this->InputIds.reserve(numberOfPoints);
  vtkDataArray* points = numberOfPoints > 0 ? input->GetPoints()->GetData() : nullptr;
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    double x[3], n[3];
    points->GetTuple(i, x);
    if (!(std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2])))
    {
      continue;
    }
    normals->GetTuple(i, n);
    UnitNormal(n);
    this->FiniteInput[i] = 1;
    this->Coordinates.insert(this->Coordinates.end(), x, x + 3);
    this->Normals.insert(this->Normals.end(), n, n + 3);
    this->InputIds.push_back(i);
  }
  this->NumberOfOwnPoints = static_cast<vtkIdType>(this->InputIds.size());
}

void CloudPoints::OwnBounds(double lower[3], double upper[3]) const
{
  for (int k = 0; k < 3; ++k)
  {
    lower[k] = std::numeric_limits<double>::infinity();
    upper[k] = -std::numeric_limits<double>::infinity();
  }
  for (vtkIdType i = 0; i < this->NumberOfOwnPoints; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      lower[k] = std::min(lower[k], this->Coordinates[3 * i + k]);
      upper[k] = std::max(upper[k], this->Coordinates[3 * i + k]);
    }
  }
}

void CloudPoints::ScaleCoordinates(double factor)
{
  for (double& coordinate : this->Coordinates)
  {
    coordinate *= factor;
  }
}

ProcessGroup::ProcessGroup()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    this->Controller = controller;
  }
}

int ProcessGroup::GetNumberOfProcesses() const
{
  return this->Controller ? this->Controller->GetNumberOfProcesses() : 1;
}

std::int64_t ProcessGroup::Sum(std::int64_t value) const
{
  if (!this->Controller)
  {
    return value;
  }
  vtkTypeInt64 local = value, global = 0;
  this->Controller->AllReduce(&local, &global, 1, vtkCommunicator::SUM_OP);
  return global;
}

void ProcessGroup::Sum(std::vector<std::int64_t>& values) const
{
  if (!this->Controller || values.empty())
  {
    return;
  }
  std::vector<vtkTypeInt64> local(values.begin(), values.end()), global(values.size());
  this->Controller->AllReduce(
    local.data(), global.data(), static_cast<vtkIdType>(local.size()), vtkCommunicator::SUM_OP);
  std::copy(global.begin(), global.end(), values.begin());
}

double ProcessGroup::Max(double value) const
{
  if (!this->Controller)
  {
    return value;
  }
  double global = value;
  this->Controller->AllReduce(&value, &global, 1, vtkCommunicator::MAX_OP);
  return global;
}

int ProcessGroup::Min(int value) const
{
  if (!this->Controller)
  {
    return value;
  }
  int global = value;
  this->Controller->AllReduce(&value, &global, 1, vtkCommunicator::MIN_OP);
  return global;
}

void ProcessGroup::Bounds(double lower[3], double upper[3]) const
{
  if (!this->Controller)
  {
    return;
  }
  double localLower[3], localUpper[3];
  std::copy(lower, lower + 3, localLower);
  std::copy(upper, upper + 3, localUpper);
  this->Controller->AllReduce(localLower, lower, 3, vtkCommunicator::MIN_OP);
  this->Controller->AllReduce(localUpper, upper, 3, vtkCommunicator::MAX_OP);
}

std::vector<double> ProcessGroup::Gather(const std::vector<double>& values,
  std::vector<vtkIdType>* lengthsOut) const
{
  if (!this->Controller)
  {
    if (lengthsOut)
    {
      lengthsOut->assign(1, static_cast<vtkIdType>(values.size()));
    }
    return values;
  }
  const int processes = this->Controller->GetNumberOfProcesses();
  vtkIdType length = static_cast<vtkIdType>(values.size());
  std::vector<vtkIdType> lengths(processes), offsets(processes);
  this->Controller->AllGather(&length, lengths.data(), 1);
  vtkIdType total = 0;
  for (int p = 0; p < processes; ++p)
  {
    offsets[p] = total;
    total += lengths[p];
  }
  std::vector<double> all(std::max<vtkIdType>(total, 1));
  const double dummy = 0.0;
  this->Controller->AllGatherV(
    values.empty() ? &dummy : values.data(), all.data(), length, lengths.data(), offsets.data());
  all.resize(total);
  if (lengthsOut)
  {
    *lengthsOut = lengths;
  }
  return all;
}

void ProcessGroup::ExchangeHalo(CloudPoints& cloud, double reach) const
{
  cloud.Coordinates.resize(3 * cloud.NumberOfOwnPoints);
  cloud.Normals.resize(3 * cloud.NumberOfOwnPoints);
  if (!this->Controller)
  {
    return;
  }
  const int processes = this->Controller->GetNumberOfProcesses();
  const int me = this->Controller->GetLocalProcessId();
  double lower[3], upper[3];
  cloud.OwnBounds(lower, upper);
  std::vector<double> boxes(6 * processes);
  double box[6] = { lower[0], lower[1], lower[2], upper[0], upper[1], upper[2] };
  this->Controller->AllGather(box, boxes.data(), 6);

  // Own points within reach of another process's box, as records.
  const double reachSquared = reach * reach;
  std::vector<double> outgoing;
  for (vtkIdType i = 0; i < cloud.NumberOfOwnPoints; ++i)
  {
    const double* x = &cloud.Coordinates[3 * i];
    for (int p = 0; p < processes; ++p)
    {
      if (p != me && SquaredDistanceToBox(x, &boxes[6 * p], &boxes[6 * p + 3]) <= reachSquared)
      {
        outgoing.insert(outgoing.end(), x, x + 3);
        outgoing.insert(outgoing.end(), &cloud.Normals[3 * i], &cloud.Normals[3 * i] + 3);
        break;
      }
    }
  }
  // Every process's records reach every process, which keeps those within
  // reach of its own box. Simple and deadlock free; the records are only
  // the points near the boundaries between the pieces.
  std::vector<vtkIdType> lengths;
  const std::vector<double> records = this->Gather(outgoing, &lengths);
  vtkIdType offset = 0;
  for (int p = 0; p < processes; ++p)
  {
    if (p != me && cloud.NumberOfOwnPoints > 0)
    {
      for (vtkIdType r = offset; r < offset + lengths[p]; r += PointRecordSize)
      {
        const double* record = &records[r];
        if (SquaredDistanceToBox(record, lower, upper) <= reachSquared)
        {
          cloud.Coordinates.insert(cloud.Coordinates.end(), record, record + 3);
          cloud.Normals.insert(cloud.Normals.end(), record + 3, record + 6);
        }
      }
    }
    offset += lengths[p];
  }
}

double WorkingLengthScale(const CloudPoints& cloud, const ProcessGroup& processes)
{
  double largest = 0.0;
  for (vtkIdType i = 0; i < 3 * cloud.NumberOfOwnPoints; ++i)
  {
    largest = std::max(largest, std::fabs(cloud.Coordinates[i]));
  }
  largest = processes.Max(largest);
  if (!(largest > 0.0) || (largest >= std::ldexp(1.0, -400) && largest <= std::ldexp(1.0, 400)))
  {
    return 1.0;
  }
  int exponent = 0;
  std::frexp(largest, &exponent); // largest = m 2^exponent, m in [0.5, 1)
  return std::ldexp(1.0, 1 - exponent);
}

void SamplingBox(const CloudPoints& cloud,
  const ProcessGroup& processes,
  double lower[3],
  double upper[3])
{
  const std::int64_t total = processes.Sum(cloud.NumberOfOwnPoints);
  // 0-based ranks, in coordinate order, of the points at 1 % and 99 %.
  const std::int64_t firstRank = total / 100;
  const std::int64_t lastRank = total - 1 - total / 100;
  constexpr int Bins = 1024;
  constexpr int EnoughBins = 64; // the central points span 64 of 1024 bins: no zoom
  for (int axis = 0; axis < 3; ++axis)
  {
    std::int64_t below = 0; // points below lower[axis]
    for (int level = 0; level < 8 && upper[axis] > lower[axis]; ++level)
    {
      const double low = lower[axis];
      const double width = (upper[axis] - low) / Bins;
      std::vector<std::int64_t> counts(Bins, 0);
      for (vtkIdType i = 0; i < cloud.NumberOfOwnPoints; ++i)
      {
        const double x = cloud.Coordinates[3 * i + axis];
        if (x >= low && x <= upper[axis])
        {
          const double bin = std::floor((x - low) / width);
          ++counts[static_cast<int>(std::min(std::max(bin, 0.0), Bins - 1.0))];
        }
      }
      processes.Sum(counts);
      int firstBin = -1, lastBin = -1;
      std::int64_t cumulative = below;
      for (int b = 0; b < Bins && lastBin < 0; ++b)
      {
        if (firstBin < 0 && cumulative + counts[b] > firstRank)
        {
          firstBin = b;
          below = cumulative;
        }
        if (cumulative + counts[b] > lastRank)
        {
          lastBin = b;
        }
        cumulative += counts[b];
      }
      if (firstBin < 0 || lastBin < 0 || lastBin - firstBin >= EnoughBins)
      {
        break;
      }
      const double newUpper = lastBin + 1 < Bins ? low + (lastBin + 1) * width : upper[axis];
      lower[axis] = low + firstBin * width;
      upper[axis] = newUpper;
    }
  }
}

bool InSpacingSample(const double x[3],
  const double lower[3],
  const double upper[3],
  std::int64_t stride)
{
  std::uint64_t hash = 0;
  for (int k = 0; k < 3; ++k)
  {
    const double extent = upper[k] - lower[k];
    // Points outside the box (far outliers) share the steps -1 and 2^20.
    const double step = extent > 0.0
      ? std::min(std::max(std::floor((x[k] - lower[k]) / extent * 1048576.0), -1.0), 1048576.0)
      : 0.0;
    hash = Mix(hash ^ static_cast<std::uint64_t>(static_cast<std::int64_t>(step)));
  }
  return hash % static_cast<std::uint64_t>(std::max<std::int64_t>(stride, 1)) == 0;
}

void GridBox(const CloudPoints& cloud,
  const ProcessGroup& processes,
  double lower[3],
  double upper[3],
  double sampleLower[3],
  double sampleUpper[3])
{
  double fullLower[3], fullUpper[3];
  cloud.OwnBounds(fullLower, fullUpper);
  processes.Bounds(fullLower, fullUpper);
  std::copy_n(fullLower, 3, sampleLower);
  std::copy_n(fullUpper, 3, sampleUpper);
  SamplingBox(cloud, processes, sampleLower, sampleUpper);
  for (int k = 0; k < 3; ++k)
  {
    const double margin = 0.5 * sampleUpper[k] - 0.5 * sampleLower[k];
    lower[k] = std::max(fullLower[k], sampleLower[k] - margin);
    upper[k] = std::min(fullUpper[k], sampleUpper[k] + margin);
  }
}

GridLattice GlobalLattice(const CloudPoints& cloud, const ProcessGroup& processes, double radius)
{
  double lower[3], upper[3], sampleLower[3], sampleUpper[3];
  GridBox(cloud, processes, lower, upper, sampleLower, sampleUpper);
  for (int k = 0; k < 3; ++k)
  {
    if (!(lower[k] <= upper[k]))
    {
      lower[k] = upper[k] = 0.0; // no point anywhere
    }
  }
  const std::int64_t count = processes.Sum(cloud.NumberOfOwnPoints);
  return GridLattice::Make(lower, upper, count, 0.5 * radius);
}

double TypicalRadius(CloudPoints& cloud, const ProcessGroup& processes, int k)
{
  const std::int64_t globalCount = processes.Sum(cloud.NumberOfOwnPoints);
  if (globalCount < 2)
  {
    return 0.0;
  }
  // About 512 sample points whatever the size of the cloud.
  const std::int64_t stride = std::max<std::int64_t>(1, globalCount / 512);
  double lower[3], upper[3], sampleLower[3], sampleUpper[3];
  GridBox(cloud, processes, lower, upper, sampleLower, sampleUpper);
  const double diagonal = std::sqrt(vtkMath::Distance2BetweenPoints(sampleLower, sampleUpper));
  // Cells for a first guess: the points spread over a square as wide as
  // the (sampling) box's diagonal.
  const double guess = diagonal * std::sqrt(k / (vtkMath::Pi() * globalCount));
  const GridLattice lattice = GridLattice::Make(lower, upper, globalCount, 0.5 * guess);

  std::vector<vtkIdType> sample;
  for (vtkIdType i = 0; i < cloud.NumberOfOwnPoints; ++i)
  {
    if (InSpacingSample(&cloud.Coordinates[3 * i], sampleLower, sampleUpper, stride))
    {
      sample.push_back(i);
    }
  }
  PointGrid grid;
  std::vector<double> scratch;
  auto sampleRadii = [&]()
  {
    grid.Build(cloud.Coordinates.data(), cloud.GetNumberOfPoints(), lattice);
    std::vector<double> radii;
    for (const vtkIdType i : sample)
    {
      // k + 1: the sample point itself is among the points found.
      radii.push_back(
        std::sqrt(grid.SquaredDistanceToKth(&cloud.Coordinates[3 * i], k + 1, scratch)));
    }
    return radii;
  };
  if (processes.IsDistributed())
  {
    // Radii from this process's points alone can only be too large: reach
    // that far into the other pieces, then measure again.
    cloud.Coordinates.resize(3 * cloud.NumberOfOwnPoints);
    cloud.Normals.resize(3 * cloud.NumberOfOwnPoints);
    const std::vector<double> bounds = sampleRadii();
    const double reach =
      processes.Max(bounds.empty() ? 0.0 : *std::max_element(bounds.begin(), bounds.end()));
    processes.ExchangeHalo(cloud, reach);
  }
  std::vector<double> radii = processes.Gather(sampleRadii());
  if (radii.empty())
  {
    return 0.0;
  }
  std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
  return radii[radii.size() / 2];
}

} // namespace pcurv
