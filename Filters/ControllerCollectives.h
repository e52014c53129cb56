/**
 * @file ControllerCollectives.h
 * @brief The collectives of a parallel run over ParaView's
 * vtkMultiProcessController (private to the module).
 */
#ifndef ControllerCollectives_h
#define ControllerCollectives_h

#include "Cloud/Collectives.h"

#include <cstdint>
#include <vector>

class vtkMultiProcessController;

namespace pcurv
{

/// The global controller's processes when ParaView runs in parallel (more
/// than one process); a single process otherwise.
class ControllerCollectives : public Collectives
{
public:
  ControllerCollectives();
  bool IsDistributed() const override { return this->Controller != nullptr; }
  int GetNumberOfProcesses() const override;
  int GetLocalProcessId() const override;

  std::int64_t Sum(std::int64_t value) const override;
  void Sum(std::vector<std::int64_t>& values) const override;
  double Max(double value) const override;
  int Min(int value) const override;
  void Bounds(double lower[3], double upper[3]) const override;
  std::vector<double> Gather(const std::vector<double>& values,
    std::vector<std::int64_t>* lengths = nullptr) const override;

private:
  vtkMultiProcessController* Controller = nullptr;
};

} // namespace pcurv

#endif
