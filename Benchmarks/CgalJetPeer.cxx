#include "CgalJetPeer.h"

#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <exception>
#include <vector>

namespace pcurv
{
namespace benchmark
{
namespace
{
using Kernel = CGAL::Simple_cartesian<double>;
using Fitting = CGAL::Monge_via_jet_fitting<Kernel>;
}

struct CgalJetFitter::Implementation
{
  std::vector<Kernel::Point_3> Points;
};

CgalJetFitter::CgalJetFitter()
  : Internal(new Implementation)
{
}

CgalJetFitter::~CgalJetFitter() = default;

JetCurvatures CgalJetFitter::Fit(const double point[3],
  const double normal[3],
  const double* neighbors,
  std::size_t count)
{
  std::vector<Kernel::Point_3>& points = this->Internal->Points;
  points.clear();
  points.emplace_back(point[0], point[1], point[2]); // CGAL: the first point is the origin
  for (std::size_t k = 0; k < count; ++k)
  {
    const double* q = neighbors + 3 * k;
    if (q[0] != point[0] || q[1] != point[1] || q[2] != point[2])
    {
      points.emplace_back(q[0], q[1], q[2]);
    }
  }
  JetCurvatures result;
  constexpr int Degree = 2, MongeDegree = 2;
  if (points.size() < (Degree + 1) * (Degree + 2) / 2)
  {
    return result;
  }
  try
  {
    Fitting fitting;
    Fitting::Monge_form form = fitting(points.begin(), points.end(), Degree, MongeDegree);
    form.comply_wrt_given_normal(Kernel::Vector_3(normal[0], normal[1], normal[2]));
    // CGAL: z = (k1 x^2 + k2 y^2) / 2 + ... with z along the (now outward)
    // normal and k1 >= k2, so positive bends towards the normal; the
    // filter's sign is the opposite.
    result.Maximum = -form.principal_curvatures(1);
    result.Minimum = -form.principal_curvatures(0);
    result.Valid = std::isfinite(result.Minimum) && std::isfinite(result.Maximum);
  }
  catch (const std::exception&)
  {
    result.Valid = false; // a CGAL precondition (degenerate neighborhood)
  }
  return result;
}

} // namespace benchmark
} // namespace pcurv
