/**
 * @file RemoteCopies.h
 * @brief Distributed runs: the outliers whose surface point lies in another
 * process's part (SurfaceOutliers::RemotePoints). They leave the working
 * cloud, as an outlier moved onto an own point does as its repeat, and get
 * that point's results from its process once they are in: the numbers of a
 * serial run, for any split. No VTK.
 */
#ifndef RemoteCopies_h
#define RemoteCopies_h

#include <cstdint>
#include <utility>
#include <vector>

namespace pcurv
{

struct CloudPoints;
class Collectives;
class ResultStore;
struct SurfaceOutliers;

class RemoteCopies
{
public:
  /// Takes the outliers of `outliers.RemotePoints` out of the own points of
  /// `cloud` (no halo yet), keeping their input ids and surface points.
  void TakeOut(CloudPoints& cloud, const SurfaceOutliers& outliers);
  /// Which surface points asked for, by any process, are own points of
  /// `cloud` (after its repeats are removed). Collective.
  void FindAnswers(const CloudPoints& cloud, const Collectives& processes);
  /// Once the results are stored: each asking outlier gets its surface
  /// point's (unestimated, FitFailed, should none answer). Collective.
  void Deliver(const ResultStore& writer, const Collectives& processes) const;

private:
  std::vector<std::int64_t> Askers; // input ids of the own outliers taken out
  std::vector<double> Asked;        // their surface points, coordinates and normal
  std::int64_t FirstAsked = 0;      // the first of them among every process's
  std::vector<std::pair<std::int64_t, std::int64_t>> Answers; // (asked, own input id)
};

} // namespace pcurv

#endif
