/**
 * @file CgalJetPeer.h
 * @brief The benchmark's peer: CGAL's Monge_via_jet_fitting (degree 2, Monge
 * degree 2, CGAL::Simple_cartesian<double>) at one point from a given
 * neighborhood. Kept in its own translation unit (and library) so that
 * CGAL's compile flags (-frounding-math) do not reach the rest of the
 * benchmark. Compiled only when CMake finds CGAL.
 */
#ifndef CgalJetPeer_h
#define CgalJetPeer_h

#include <cstddef>
#include <memory>

namespace pcurv
{
namespace benchmark
{

/// Principal curvatures in the filter's sign: positive where the surface
/// bends away from the given (outward) normal.
struct JetCurvatures
{
  bool Valid = false;
  double Minimum = 0.0;
  double Maximum = 0.0;
};

class CgalJetFitter
{
public:
  CgalJetFitter();
  ~CgalJetFitter();
  CgalJetFitter(const CgalJetFitter&) = delete;
  CgalJetFitter& operator=(const CgalJetFitter&) = delete;

  /// Fits the jet at `point` (the origin of CGAL's fit: the first point of
  /// its range) to `point` and the `count` neighbors (xyz triplets; copies
  /// of `point` are skipped). `normal` only orients the result: CGAL's
  /// curvatures are relative to its own fitted normal, and are turned to
  /// the given normal's side (Monge_form::comply_wrt_given_normal) and then
  /// to the filter's sign. Fewer than 6 points (a degree-2 jet's unknowns):
  /// not valid.
  JetCurvatures Fit(const double point[3],
    const double normal[3],
    const double* neighbors,
    std::size_t count);

private:
  struct Implementation;
  std::unique_ptr<Implementation> Internal;
};

} // namespace benchmark
} // namespace pcurv

#endif
