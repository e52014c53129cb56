/**
 * @file PrincipalCurvatureCloud.h
 * @brief The VTK side of the core's cloud (private to the module): reading a
 * vtkPointSet and its normals into pcurv::CloudPoints, the collectives of a
 * parallel run implemented with vtkMultiProcessController, and the core's
 * work run on vtkSMPTools threads.
 */
#ifndef PrincipalCurvatureCloud_h
#define PrincipalCurvatureCloud_h

#include "Cloud/Collectives.h"
#include "Common/Progress.h"
#include "Common/WorkRunner.h"
#include "Cloud/CloudPoints.h"

#include <atomic>
#include <chrono>
#include <future>
#include <string>
#include <utility>

class vtkAlgorithm;
class vtkDataArray;
class vtkMultiProcessController;
class vtkPointSet;
class vtkPolyData;

namespace pcurv
{

/// The input's points and normals (non-unit normals normalized; zero or
/// non-finite ones become zero: such points are not estimated). Without
/// normals (null) every normal is zero, for the core to estimate.
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

/// The output's geometry: the input's points, its point data and, for a
/// vtkPolyData with cells, its cells; otherwise one vertex cell per point,
/// so that a cloud shows in a render view.
void CopyGeometry(vtkPointSet* input, vtkPolyData* output);

/// What the curvature arrays are measured in, as ParaView shows it (the
/// Information panel lists field data): the string array Curvature_Unit,
/// "1/length unit of the input coordinates".
void AddCurvatureUnit(vtkPolyData* output);

/**
 * The range that VTK reports for `array` (and ParaView colors a new
 * display over), set to [-clip, clip]: symmetric about zero, so that a
 * diverging color map's middle (white in Cool to Warm) is zero even where
 * only one tail was clipped (a torus's mean curvature is positive
 * everywhere, and its clipped array's own range put white at +0.31). VTK
 * keeps the range in the array's information and forgets it when the array
 * is modified. Nothing is set for a clip that is zero or not finite.
 */
void SetSymmetricRange(vtkDataArray* array, double clip);

/// "Principal curvatures: about 2 min left": `label` and the time left if
/// the rest goes at the pace so far (`elapsedSeconds` since the start, the
/// part `fraction` done); `label` alone while the pace is not yet known
/// (the first second, or less than 1 % done) and at the end. ParaView's
/// progress bar adds the percentage.
std::string ProgressText(const std::string& label, double fraction, double elapsedSeconds);

/// Progress from the core's threads, passed to a filter on the thread that
/// runs the filter: ParaView shows progress, and honors Abort, only from
/// there. The filter's abort flag travels back the same way. The filter's
/// progress text (what ParaView's progress bar shows) says the time left.
class AlgorithmProgress : public ProgressMonitor
{
public:
  AlgorithmProgress(vtkAlgorithm* algorithm, std::string label);
  /// From any thread: keeps the fraction; false once Pass saw an abort.
  bool Continue(double fraction) override;
  /// From the filter's thread: reports the newest fraction and the time
  /// left to the filter (a progress event even when the fraction has not
  /// moved, so that a GUI listening to them stays responsive), and reads
  /// its abort flag.
  void Pass();

private:
  vtkAlgorithm* Algorithm;
  std::string Label;
  std::chrono::steady_clock::time_point Start;
  std::atomic<double> Fraction{ 0.0 };
  std::atomic<bool> AbortRequested{ false };
};

/// `estimate()` (a whole estimation: its serial stages too, which take
/// seconds on millions of points) on a thread of its own, while the calling
/// thread, the filter's, passes `progress` on ten times a second: ParaView
/// then shows progress and honors Abort all along. For one process only:
/// a distributed run's collectives stay on the calling thread (MPI is
/// initialized for one thread), and it passes progress in the parallel
/// stages alone (SMPToolsRunner).
template<typename Estimate>
auto RunPassingProgress(AlgorithmProgress& progress, Estimate&& estimate)
{
  auto done = std::async(std::launch::async, std::forward<Estimate>(estimate));
  while (done.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready)
  {
    progress.Pass();
  }
  progress.Pass();
  return done.get();
}

/// The core's work items on vtkSMPTools threads:
/// all cores unless the user chose otherwise (ParaView's bundled VTK
/// defaults to the sequential backend; STDThread is used then, unless a
/// backend was requested through the environment). With `progress`, the
/// calling thread only waits and passes the progress on, ten times a second
/// (null when the whole estimation runs in RunPassingProgress).
class SMPToolsRunner : public WorkRunner
{
public:
  explicit SMPToolsRunner(int maximumThreads, AlgorithmProgress* progress = nullptr)
    : MaximumThreads(maximumThreads)
    , Progress(progress)
  {
  }
  void For(std::int64_t count, std::int64_t grain, const RangeWork& work) override;

private:
  void RunParallel(std::int64_t count, std::int64_t grain, const RangeWork& work);

  int MaximumThreads;
  AlgorithmProgress* Progress;
};

} // namespace pcurv

#endif
