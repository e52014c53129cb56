/**
 * @file Collectives.h
 * @brief The collective operations of a parallel run, behind an interface
 * that the VTK glue implements with vtkMultiProcessController and which, as
 * given here, is a single process. No VTK.
 */
#ifndef Collectives_h
#define Collectives_h

#include <cstdint>
#include <vector>

namespace pcurv
{

/**
 * Collective operations over the processes of a parallel run. This base
 * class is a single process: every reduction returns the local value. The
 * VTK glue overrides it for ParaView's MPI runs.
 */
class Collectives
{
public:
  virtual ~Collectives() = default;
  virtual bool IsDistributed() const { return false; }
  virtual int GetNumberOfProcesses() const { return 1; }
  virtual int GetLocalProcessId() const { return 0; }

  virtual std::int64_t Sum(std::int64_t value) const { return value; }
  /// Element-wise global sums, in place.
  virtual void Sum(std::vector<std::int64_t>&) const {}
  virtual double Max(double value) const { return value; }
  virtual int Min(int value) const { return value; }
  /// Global bounds from local ones (empty local boxes ignored), in place.
  virtual void Bounds(double[3], double[3]) const {}
  /// All processes' values, concatenated in process order; `lengths`, when
  /// given, receives how many values each process gave.
  virtual std::vector<double> Gather(const std::vector<double>& values,
    std::vector<std::int64_t>* lengths = nullptr) const;
};

} // namespace pcurv

#endif
