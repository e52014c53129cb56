/**
 * @file Halo.h
 * @brief The halo of a distributed run: each process sees every point its own
 * points' neighborhoods can reach, so that a split cloud gives the numbers
 * of a serial run. No VTK.
 */
#ifndef Halo_h
#define Halo_h

namespace pcurv
{

struct CloudPoints;
class Collectives;

/// Replaces the halo of `cloud` by the points of other processes within
/// `reach` of this process's own bounding box (drops it when not
/// distributed).
void ExchangeHalo(CloudPoints& cloud, const Collectives& processes, double reach);

} // namespace pcurv

#endif
