#include "ControllerCollectives.h"

#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <future>
#include <string>
#include <utility>

namespace pcurv
{

ControllerCollectives::ControllerCollectives()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    this->Controller = controller;
  }
}

int ControllerCollectives::GetNumberOfProcesses() const
{
  return this->Controller ? this->Controller->GetNumberOfProcesses() : 1;
}

int ControllerCollectives::GetLocalProcessId() const
{
  return this->Controller ? this->Controller->GetLocalProcessId() : 0;
}

std::int64_t ControllerCollectives::Sum(std::int64_t value) const
{
  if (!this->Controller)
  {
    return value;
  }
  vtkTypeInt64 local = value, global = 0;
  this->Controller->AllReduce(&local, &global, 1, vtkCommunicator::SUM_OP);
  return global;
}

void ControllerCollectives::Sum(std::vector<std::int64_t>& values) const
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

double ControllerCollectives::Max(double value) const
{
  if (!this->Controller)
  {
    return value;
  }
  double global = value;
  this->Controller->AllReduce(&value, &global, 1, vtkCommunicator::MAX_OP);
  return global;
}

int ControllerCollectives::Min(int value) const
{
  if (!this->Controller)
  {
    return value;
  }
  int global = value;
  this->Controller->AllReduce(&value, &global, 1, vtkCommunicator::MIN_OP);
  return global;
}

void ControllerCollectives::Bounds(double lower[3], double upper[3]) const
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

std::vector<double> ControllerCollectives::Gather(const std::vector<double>& values,
  std::vector<std::int64_t>* lengthsOut) const
{
  if (!this->Controller)
  {
    if (lengthsOut)
    {
      lengthsOut->assign(1, static_cast<std::int64_t>(values.size()));
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
    lengthsOut->assign(lengths.begin(), lengths.end());
  }
  return all;
}

} // namespace pcurv
