/**
 * @file PrincipalCurvatureCloud.h
 * @brief The VTK side of the core's cloud (private to the module): reading a
 * vtkPointSet and its normals into pcurv::CloudPoints, and the collectives
 * of a parallel run implemented with vtkMultiProcessController.
 */
#ifndef PrincipalCurvatureCloud_h
#define PrincipalCurvatureCloud_h

#include "CloudStatistics.h"

class vtkDataArray;
class vtkMultiProcessController;
class vtkPointSet;

namespace pcurv
{

/// The input's points and normals (non-unit normals normalised; zero or
/// non-finite ones become zero: such points are not estimated).
CloudPoints ReadCloud(vtkPointSet* input, vtkDataArray* normals);

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
