/**
 * @file RankSelection.h
 * @brief The k-th smallest of a neighborhood's squared distances, exact:
 * for one rank, or for several ranks of the same values at once. Internal
 * to the normal estimation. No VTK.
 */
#ifndef RankSelection_h
#define RankSelection_h

#include <cstddef>
#include <vector>

namespace pcurv
{
namespace normals
{

/// The k-th smallest (k from 1) of values[0, count): exact whatever the
/// bounds, and quick when it lies in [low, high): the values below and
/// within are counted without branches (a sphere's distances come too
/// randomly for branch prediction) and only those within are sorted.
double KthSmallest(const double* values,
  std::size_t count,
  std::size_t k,
  double low,
  double high,
  std::vector<double>& scratch);

/// The k-th smallest (k from 1, at most count) of values[0, count), all
/// in [0, high), for each of the `n` ranks ks[] (ascending), into kth[]:
/// exact, in two passes whatever n. The values are counted into buckets of
/// equal width (squared distances within a radius spread about evenly over
/// them on a surface), and only the few that hold a wanted rank are
/// copied out and selected in.
void KthSmallestOfEach(const double* values,
  std::size_t count,
  const std::size_t* ks,
  int n,
  double high,
  double* kth,
  std::vector<double>& scratch);

} // namespace normals
} // namespace pcurv

#endif
