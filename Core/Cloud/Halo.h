/**
 * @file Halo.h
 * @brief The halo of a distributed run: each process sees every point its own
 * points' neighborhoods can reach, so that a split cloud gives the numbers
 * of a serial run. No VTK.
 */
#ifndef Halo_h
#define Halo_h

#include <cstdint>
#include <functional>
#include <vector>

namespace pcurv
{

struct CloudPoints;
class Collectives;

/// Writes the record of a process's point i: `width` doubles, the point's
/// coordinates first.
using HaloRecord = std::function<void(std::int64_t i, double* record)>;

/// The records of other processes' points within `reach` of the bounding
/// box of this process's `count` points, in process order, then in each
/// process's order. Collective; empty when not distributed.
std::vector<double> ExchangeHaloRecords(std::int64_t count,
  int width,
  const HaloRecord& recordOf,
  const Collectives& processes,
  double reach);

/// Replaces the halo of `cloud` by the points of other processes within
/// `reach` of this process's own bounding box (drops it when not
/// distributed).
void ExchangeHalo(CloudPoints& cloud, const Collectives& processes, double reach);

} // namespace pcurv

#endif
