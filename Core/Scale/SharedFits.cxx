#include "Scale/SharedFits.h"
#include "Fits/OrientedCircleFit.h"
#include "Fits/PrincipalCurvatureCore.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace pcurv
{
namespace
{
using Vector3d = Eigen::Vector3d;

Vector3d ToEigen(const Vector3& v)
{
  return Vector3d(v[0], v[1], v[2]);
}

Vector3 FromEigen(const Vector3d& v)
{
  return Vector3{ { v[0], v[1], v[2] } };
}

/// The fitted surface's height, slope and second derivatives at (u, v).
struct SurfaceJet
{
  double Height, Fu, Fv, Fuu, Fuv, Fvv;
};

/// The fit's surface is not the polynomial `jet` (P) but the one whose
/// circles it fits: the positions' rows fit 2 h = kappa(phi) |d|^2 + ...,
/// |d| the distance in space, which a circle tangent to the frame's plane
/// meets exactly (a polynomial of the same coefficients leaves a sphere's
/// fourth order out, and off the anchor its curvature falls short). With
/// the circles through the fitted point (height e): h = P + kappa(phi) w^2
/// / 2, w = h - e, kappa(phi) = C + (A (u^2 - v^2) + 2 B u v) / rho^2. Its
/// height and derivatives at (u, v) by implicit differentiation of h = R(u,
/// v, h); (u, v) != (0, 0).
void CompleteCircles(const std::array<double, 15>& x, double u, double v, SurfaceJet& jet)
{
  const double a = x[1], b = x[2];
  const double rho2 = u * u + v * v;
  // g = T / rho^2 and its derivatives, T = A (u^2 - v^2) + 2 B u v.
  const double t = a * (u * u - v * v) + 2.0 * b * u * v;
  const double tu = 2.0 * (a * u + b * v), tv = 2.0 * (b * u - a * v);
  const double g = t / rho2;
  const double gu = (tu - g * 2.0 * u) / rho2, gv = (tv - g * 2.0 * v) / rho2;
  const double guu = (2.0 * a - 4.0 * gu * u - 2.0 * g) / rho2;
  const double gvv = (-2.0 * a - 4.0 * gv * v - 2.0 * g) / rho2;
  const double guv = (2.0 * b - 2.0 * gu * v - 2.0 * gv * u) / rho2;
  const double k = x[0] + g; // kappa(phi)
  const double e = 0.5 * x[9];
  double h = jet.Height;
  for (int i = 0; i < 4; ++i)
  {
    h = jet.Height + 0.5 * k * (h - e) * (h - e);
  }
  const double w = h - e, w2 = w * w;
  const double denominator = 1.0 - k * w; // 1 - R_h
  const double hu = (jet.Fu + 0.5 * gu * w2) / denominator;
  const double hv = (jet.Fv + 0.5 * gv * w2) / denominator;
  // R_uh = kappa_u w, R_hh = kappa.
  const double ruh = gu * w, rvh = gv * w;
  jet.Height = h;
  jet.Fu = hu;
  jet.Fv = hv;
  jet.Fuu = (jet.Fuu + 0.5 * guu * w2 + 2.0 * ruh * hu + k * hu * hu) / denominator;
  jet.Fvv = (jet.Fvv + 0.5 * gvv * w2 + 2.0 * rvh * hv + k * hv * hv) / denominator;
  jet.Fuv = (jet.Fuv + 0.5 * guv * w2 + ruh * hv + rvh * hu + k * hu * hv) / denominator;
}

SurfaceJet JetAt(const FittedSurface& surface, double u, double v)
{
  const auto& x = surface.Coefficients;
  const double c = x[0], a = x[1], b = x[2];
  SurfaceJet jet;
  jet.Height = 0.5 * x[9] + x[3] * u + x[4] * v +
    0.5 * ((c + a) * u * u + 2.0 * b * u * v + (c - a) * v * v) + x[5] * u * u * u +
    x[6] * u * u * v + x[7] * u * v * v + x[8] * v * v * v;
  jet.Fu = x[3] + (c + a) * u + b * v + 3.0 * x[5] * u * u + 2.0 * x[6] * u * v + x[7] * v * v;
  jet.Fv = x[4] + b * u + (c - a) * v + x[6] * u * u + 2.0 * x[7] * u * v + 3.0 * x[8] * v * v;
  jet.Fuu = c + a + 6.0 * x[5] * u + 2.0 * x[6] * v;
  jet.Fuv = b + 2.0 * x[6] * u + 2.0 * x[7] * v;
  jet.Fvv = c - a + 2.0 * x[7] * u + 6.0 * x[8] * v;
  // A third-order surface skips these: adding zeros could still turn a
  // -0 into +0, and its numbers stay as they were.
  const double* q = x.data() + FittedSurface::FirstQuarticCoefficient;
  if (q[0] != 0.0 || q[1] != 0.0 || q[2] != 0.0 || q[3] != 0.0 || q[4] != 0.0)
  {
    const double uu = u * u, uv = u * v, vv = v * v;
    jet.Height +=
      q[0] * uu * uu + q[1] * uu * uv + q[2] * uu * vv + q[3] * uv * vv + q[4] * vv * vv;
    jet.Fu += 4.0 * q[0] * uu * u + 3.0 * q[1] * uu * v + 2.0 * q[2] * uv * v + q[3] * vv * v;
    jet.Fv += q[1] * uu * u + 2.0 * q[2] * uu * v + 3.0 * q[3] * uv * v + 4.0 * q[4] * vv * v;
    jet.Fuu += 12.0 * q[0] * uu + 6.0 * q[1] * uv + 2.0 * q[2] * vv;
    jet.Fuv += 3.0 * q[1] * uu + 4.0 * q[2] * uv + 3.0 * q[3] * vv;
    jet.Fvv += 2.0 * q[2] * uu + 6.0 * q[3] * uv + 12.0 * q[4] * vv;
  }
  if (surface.Circles && (u != 0.0 || v != 0.0))
  {
    CompleteCircles(x, u, v, jet);
  }
  return jet;
}

/// The second fundamental form of the graph h(u, v) (paper sign: positive
/// where the surface bends towards the frame's normal) in the orthonormal
/// tangent basis e1 = X_u / |X_u|, e2 = N x e1, as the sine's offset and
/// amplitudes; `unitNormal` and `e1` receive N and e1.
SineFit SineOfJet(const SurfaceJet& jet,
  const TangentFrame& frame,
  Vector3d& unitNormal,
  Vector3d& e1)
{
  const Vector3d n = ToEigen(frame.Normal), v0 = ToEigen(frame.V0), w0 = ToEigen(frame.W0);
  const Vector3d xu = v0 + jet.Fu * n, xv = w0 + jet.Fv * n;
  const double metric = std::sqrt(1.0 + jet.Fu * jet.Fu + jet.Fv * jet.Fv);
  unitNormal = (n - jet.Fu * v0 - jet.Fv * w0) / metric;
  e1 = xu.normalized();
  const Vector3d e2 = unitNormal.cross(e1);
  // e1, e2 in the parameters' basis: the first fundamental form solves it.
  Eigen::Matrix2d first;
  first << xu.dot(xu), xu.dot(xv), xv.dot(xu), xv.dot(xv);
  Eigen::Matrix2d tangents; // columns: e1, e2 as (du, dv)
  const Eigen::LDLT<Eigen::Matrix2d> metricTensor(first);
  tangents.col(0) = metricTensor.solve(Eigen::Vector2d(e1.dot(xu), e1.dot(xv)));
  tangents.col(1) = metricTensor.solve(Eigen::Vector2d(e2.dot(xu), e2.dot(xv)));
  Eigen::Matrix2d second;
  second << jet.Fuu, jet.Fuv, jet.Fuv, jet.Fvv;
  const Eigen::Matrix2d form = tangents.transpose() * (second / metric) * tangents;
  SineFit sine;
  sine.Valid = form.allFinite();
  sine.Offset = 0.5 * (form(0, 0) + form(1, 1));
  sine.CosineAmplitude = 0.5 * (form(0, 0) - form(1, 1));
  sine.SineAmplitude = form(0, 1);
  return sine;
}

/// The normal the directions are tangent to: the point's own, turned
/// towards the fitted surface's by the share of their difference that the
/// point's displacement along the surface does not explain (as at the
/// anchor itself: OrientedCircleFit's fitted frame). In units of the scale.
Vector3d DirectionsNormal(const Vector3d& own,
  const Vector3d& fitted,
  const SineFit& sine,
  double noiseVariance)
{
  const double cosine = own.dot(fitted);
  const Vector3d tangential = own - cosine * fitted;
  const double tilt = tangential.squaredNorm() / (cosine * cosine);
  const double amplitude = std::hypot(sine.CosineAmplitude, sine.SineAmplitude);
  const double k1 = sine.Offset + amplitude, k2 = sine.Offset - amplitude;
  const double share = TiltShare(tilt, noiseVariance * (k1 * k1 + k2 * k2));
  const Vector3d turned = ((1.0 - share) * own + share * fitted).normalized();
  return turned.allFinite() ? turned : own;
}

/// One anchor's fitted surface at the point: its shape tensor (output
/// sign, 1/length, in the fitted tangent plane), the fitted normal and the
/// normal the directions are tangent to.
struct SurfaceAtPoint
{
  bool Valid = false;
  Eigen::Matrix3d Shape = Eigen::Matrix3d::Zero();
  Vector3d Normal = Vector3d::Zero();
  Vector3d DirectionsNormal = Vector3d::Zero();
};

SurfaceAtPoint EvaluateAt(const AnchorEstimate& anchor,
  const Vector3d& x,
  const Vector3d& own,
  const SharingRule& rule)
{
  SurfaceAtPoint at;
  const FittedSurface& surface = anchor.Fit->Surface;
  const Vector3d d = (x - Vector3d(anchor.Position[0], anchor.Position[1], anchor.Position[2])) *
    surface.InverseScale;
  const double u = d.dot(ToEigen(anchor.Frame.V0));
  const double v = d.dot(ToEigen(anchor.Frame.W0));
  const double h = d.dot(ToEigen(anchor.Frame.Normal));
  const SurfaceJet jet = JetAt(surface, u, v);
  const double allowedHeight = std::max(rule.HeightDeviations * std::sqrt(surface.NoiseVariance),
    0.01 * anchor.Fit->Radius * surface.InverseScale);
  if (!(std::fabs(h - jet.Height) <= allowedHeight))
  {
    return at;
  }
  Vector3d e1;
  const SineFit sine = SineOfJet(jet, anchor.Frame, at.Normal, e1);
  if (!sine.Valid || !(own.dot(at.Normal) >= rule.MinimumNormalCosine))
  {
    return at;
  }
  at.DirectionsNormal = DirectionsNormal(own, at.Normal, sine, surface.NoiseVariance);
  // Paper sign in the basis e1, e2: the output's is the opposite.
  const Vector3d e2 = at.Normal.cross(e1);
  const double l11 = sine.Offset + sine.CosineAmplitude, l22 = sine.Offset - sine.CosineAmplitude;
  const double l12 = sine.SineAmplitude;
  at.Shape = -surface.InverseScale *
    (l11 * e1 * e1.transpose() + l12 * (e1 * e2.transpose() + e2 * e1.transpose()) +
      l22 * e2 * e2.transpose());
  at.Valid = at.Shape.allFinite() && at.DirectionsNormal.allFinite();
  return at;
}

/// The principal curvatures and directions of a shape tensor in the plane
/// of `normal`, the directions given in the plane of `directionsNormal`.
PointCurvature CurvaturesOfShape(const Eigen::Matrix3d& shape,
  const Vector3d& normal,
  const Vector3d& directionsNormal)
{
  const TangentFrame plane = MakeTangentFrame(FromEigen(normal));
  const Vector3d e1 = ToEigen(plane.V0), e2 = ToEigen(plane.W0);
  const double l11 = e1.dot(shape * e1), l22 = e2.dot(shape * e2), l12 = e1.dot(shape * e2);
  SineFit sine; // paper sign
  sine.Valid = true;
  sine.Offset = -0.5 * (l11 + l22);
  sine.CosineAmplitude = -0.5 * (l11 - l22);
  sine.SineAmplitude = -l12;
  const Vector3d v0 = (e1 - e1.dot(directionsNormal) * directionsNormal).normalized();
  TangentFrame frame;
  frame.Normal = FromEigen(directionsNormal);
  frame.V0 = FromEigen(v0);
  frame.W0 = FromEigen(directionsNormal.cross(v0));
  PointCurvature out;
  PrincipalCurvaturesFromSine(sine, frame, out);
  out.FittedNormal = frame.Normal;
  return out;
}
} // namespace

SharedEstimate EstimateFromAnchors(const std::vector<AnchorEstimate>& anchors,
  const double x[3],
  const double normal[3],
  const SharingRule& rule)
{
  SharedEstimate estimate;
  const Vector3d point(x[0], x[1], x[2]), own(normal[0], normal[1], normal[2]);
  double weights = 0.0, heaviest = 0.0, errors = 0.0, radius = 0.0, neighbors = 0.0, rms = 0.0;
  Eigen::Matrix3d shape = Eigen::Matrix3d::Zero();
  Vector3d fitted = Vector3d::Zero(), directionsNormal = Vector3d::Zero();
  int validDirections = 0;
  // At most the 27 cells' anchors (AnchorCells::AnchorsAround): no
  // allocation per point.
  constexpr std::size_t MostAnchors = 27;
  std::array<std::pair<double, Eigen::Matrix3d>, MostAnchors> shapes;
  std::size_t used = 0;
  for (const AnchorEstimate& anchor : anchors)
  {
    const AnchorFit& fit = *anchor.Fit;
    const double reach = rule.OffsetFraction * fit.Radius;
    const Vector3d offset =
      point - Vector3d(anchor.Position[0], anchor.Position[1], anchor.Position[2]);
    const double closeness = 1.0 - offset.squaredNorm() / (reach * reach);
    if (!fit.Valid || !(closeness > 0.0) || !(fit.Radius >= rule.MinimumRadius) ||
      !(fit.Surface.InverseScale > 0.0))
    {
      continue;
    }
    const SurfaceAtPoint at =
      used < MostAnchors ? EvaluateAt(anchor, point, own, rule) : SurfaceAtPoint{};
    if (!at.Valid)
    {
      continue;
    }
    const double w = closeness * closeness;
    weights += w;
    shape += w * at.Shape;
    shapes[used++] = { w, at.Shape };
    fitted += w * at.Normal;
    directionsNormal += w * at.DirectionsNormal;
    errors += w * fit.Error * fit.Error;
    radius += w * fit.Radius;
    neighbors += w * fit.NeighborCount;
    rms += w * fit.SineFitRms;
    if (w > heaviest)
    {
      heaviest = w;
      validDirections = fit.ValidDirections;
    }
  }
  if (!(weights > 0.0))
  {
    return estimate;
  }
  const Eigen::Matrix3d mean = shape / weights;
  PointCurvature& out = estimate.Curvature;
  out = CurvaturesOfShape(mean, fitted.normalized(), directionsNormal.normalized());
  if (!out.Valid)
  {
    return estimate;
  }
  // How far the anchors' surfaces disagree at the point (the weighted RMS
  // of their shape tensors about the blend, which bounds the principal
  // curvatures' differences): the extrapolations' error, which no anchor's
  // own error covers.
  double spread = 0.0;
  for (std::size_t i = 0; i < used; ++i)
  {
    spread += shapes[i].first * (shapes[i].second - mean).squaredNorm();
  }
  const double shift = std::sqrt(spread / weights);
  out.NeighborCount = static_cast<int>(std::lround(neighbors / weights));
  out.ValidDirections = validDirections;
  out.SineFitRms = rms / weights;
  estimate.Radius = radius / weights;
  estimate.Error = std::hypot(std::sqrt(errors / weights), ReportedErrorFactor * shift);
  return estimate;
}

SharedEstimate AnchorTable::EstimateAt(const CloudPoints& cloud,
  std::int64_t point,
  const SharingRule& rule,
  SharedFitScratch& scratch) const
{
  const AnchorTable& anchors = *this;
  const double* x = &cloud.Coordinates[3 * point];
  std::vector<AnchorEstimate>& nearby = scratch.NearbyAnchors;
  // Points in the grid's order mostly share their cell with the one
  // before: the anchors around it, with their frames, are made once.
  if (anchors.Cells.AnchorsAround(x, scratch.Anchors))
  {
    nearby.clear();
    for (const std::int64_t position : scratch.Anchors.Anchors)
    {
      const std::int64_t anchor = anchors.Points[position];
      const double* n = &cloud.Normals[3 * anchor];
      nearby.push_back(AnchorEstimate{ &anchors.Fits[position],
        &cloud.Coordinates[3 * anchor],
        MakeTangentFrame({ { n[0], n[1], n[2] } }) });
    }
  }
  return EstimateFromAnchors(nearby, x, &cloud.Normals[3 * point], rule);
}

} // namespace pcurv
