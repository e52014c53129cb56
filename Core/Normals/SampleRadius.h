/**
 * @file SampleRadius.h
 * @brief The cloud's typical radius for the normals' neighbors, found with
 * one pass over the cloud: internal to the normal estimation. No VTK.
 */
#ifndef SampleRadius_h
#define SampleRadius_h

namespace pcurv
{

struct CloudBoxes;
struct CloudPoints;
class WorkRunner;

namespace normals
{

/// TypicalRadius(cloud, alone, boxes, k) (CloudStatistics.cxx) without its
/// grid over the whole cloud, which took as long as a tenth of the normals:
/// the same sample (InSpacingSample), the same exact distances to the
/// (k + 1)-th nearest point, the same median; the neighbors of the ~512
/// sample points found in one parallel pass (SampleNeighborhoods). False
/// where it cannot vouch for the value (a sample point whose k nearest lie
/// beyond the cells searched, few points, a cloud far from a surface): the
/// caller then calls TypicalRadius itself.
bool QuickTypicalRadius(const CloudPoints& cloud,
  const CloudBoxes& boxes,
  int k,
  WorkRunner& runner,
  double& radius);

} // namespace normals
} // namespace pcurv

#endif
