/**
 * @file AnalyticSurfaces.h
 * @brief Point clouds on surfaces with exact normals, principal curvatures
 * and principal directions, for tests, the demo and the benchmarks. No VTK.
 *
 * Each surface is a parametrization X(u, v) with analytic first and second
 * derivatives; the exact curvatures follow from the two fundamental forms.
 * Sign convention as the filter's output: positive where the surface bends
 * away from the normal (sphere with outward normals: +1/R).
 * Sampling is uniform in area (rejection on |X_u x X_v|) with a fixed seed
 * and a portable random generator, so clouds are identical everywhere.
 */
#ifndef AnalyticSurfaces_h
#define AnalyticSurfaces_h

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace pcurv
{
namespace testing
{
using Vec = std::array<double, 3>;

inline Vec Add(const Vec& a, const Vec& b)
{
  return { { a[0] + b[0], a[1] + b[1], a[2] + b[2] } };
}
inline Vec Scale(double s, const Vec& a)
{
  return { { s * a[0], s * a[1], s * a[2] } };
}
inline double Dot(const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vec Cross(const Vec& a, const Vec& b)
{
  return { { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] } };
}
inline Vec Unit(const Vec& a)
{
  return Scale(1.0 / std::sqrt(Dot(a, a)), a);
}

/// Portable uniform numbers in [0, 1) and standard normals from a fixed seed
/// (std distributions differ between standard libraries; these do not).
class Random
{
public:
  explicit Random(std::uint64_t seed)
    : Engine(seed)
  {
  }
  double Uniform() { return static_cast<double>(this->Engine() >> 11) * 0x1.0p-53; }
  double Normal()
  {
    const double u1 = 1.0 - this->Uniform();
    const double u2 = this->Uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * 3.14159265358979323846 * u2);
  }

private:
  std::mt19937_64 Engine;
};

/// Position and derivatives of a parametrization at (u, v).
struct Jet
{
  Vec X, Xu, Xv, Xuu, Xuv, Xvv;
};

/// One sample with its exact differential geometry.
struct SurfaceSample
{
  Vec Point;
  Vec Normal;
  double MinimumCurvature;
  double MaximumCurvature;
  Vec MaximumDirection;    // unit, tangent; meaningless where k_max == k_min
  double BoundaryDistance; // distance to the patch's edge (infinity if closed)
};

/// A parametrized surface patch [u0,u1] x [v0,v1].
struct Surface
{
  std::string Name;
  double U0, U1, V0, V1;
  std::function<Jet(double, double)> Evaluate;
  /// Distance of X(u, v) to the patch's boundary (infinity for closed surfaces).
  std::function<double(double, double)> BoundaryDistance;
  bool OutwardFlip = false; // true when X_u x X_v points inward
};

/// Exact curvatures and max direction from the fundamental forms.
inline SurfaceSample Differential(const Jet& j, bool flip)
{
  SurfaceSample s{};
  Vec n = Unit(Cross(j.Xu, j.Xv));
  if (flip)
  {
    n = Scale(-1.0, n);
  }
  const double E = Dot(j.Xu, j.Xu), F = Dot(j.Xu, j.Xv), G = Dot(j.Xv, j.Xv);
  // Output sign: bending away from n is positive, hence the minus.
  const double L = -Dot(j.Xuu, n), M = -Dot(j.Xuv, n), N = -Dot(j.Xvv, n);
  // Shape operator S = I^-1 II (2x2).
  const double det = E * G - F * F;
  const double s11 = (G * L - F * M) / det, s12 = (G * M - F * N) / det;
  const double s21 = (E * M - F * L) / det, s22 = (E * N - F * M) / det;
  const double mean = 0.5 * (s11 + s22);
  const double gauss = s11 * s22 - s12 * s21;
  const double root = std::sqrt(std::max(0.0, mean * mean - gauss));
  s.MaximumCurvature = mean + root;
  s.MinimumCurvature = mean - root;
  // Eigenvector of S for k_max, in parameter space, mapped to 3D.
  double a = s12, b = s.MaximumCurvature - s11;
  if (std::fabs(a) + std::fabs(b) < 1e-14 * (std::fabs(s11) + std::fabs(s22) + 1e-300))
  {
    a = s.MaximumCurvature - s22;
    b = s21;
  }
  if (std::fabs(a) + std::fabs(b) == 0.0)
  {
    a = 1.0;
    b = 0.0;
  }
  s.MaximumDirection = Unit(Add(Scale(a, j.Xu), Scale(b, j.Xv)));
  s.Point = j.X;
  s.Normal = n;
  return s;
}

/// `count` samples uniform in area, fixed seed.
inline std::vector<SurfaceSample> Sample(const Surface& surface, int count, std::uint64_t seed)
{
  Random random(seed);
  // Bound of the area element from a grid, with margin.
  double largestArea = 0.0;
  for (int i = 0; i <= 64; ++i)
  {
    for (int k = 0; k <= 64; ++k)
    {
      const double u = surface.U0 + (surface.U1 - surface.U0) * i / 64.0;
      const double v = surface.V0 + (surface.V1 - surface.V0) * k / 64.0;
      const Jet j = surface.Evaluate(u, v);
      largestArea = std::max(largestArea, std::sqrt(Dot(Cross(j.Xu, j.Xv), Cross(j.Xu, j.Xv))));
    }
  }
  largestArea *= 1.05;
  std::vector<SurfaceSample> samples;
  samples.reserve(count);
  while (static_cast<int>(samples.size()) < count)
  {
    const double u = surface.U0 + (surface.U1 - surface.U0) * random.Uniform();
    const double v = surface.V0 + (surface.V1 - surface.V0) * random.Uniform();
    const Jet j = surface.Evaluate(u, v);
    const double area = std::sqrt(Dot(Cross(j.Xu, j.Xv), Cross(j.Xu, j.Xv)));
    if (random.Uniform() * largestArea >= area)
    {
      continue;
    }
    SurfaceSample s = Differential(j, surface.OutwardFlip);
    s.BoundaryDistance = surface.BoundaryDistance(u, v);
    samples.push_back(s);
  }
  return samples;
}

constexpr double Pi = 3.14159265358979323846;
constexpr double Infinity = std::numeric_limits<double>::infinity();

inline double Closed(double, double)
{
  return Infinity;
}

/// Sphere of radius r; outward normals; k = 1/r.
inline Surface Sphere(double r)
{
  Surface s{ "sphere", 0.0, 2.0 * Pi, 0.0, Pi, nullptr, Closed, false };
  s.Evaluate = [r](double u, double v)
  {
    const double cu = std::cos(u), su = std::sin(u), cv = std::cos(v), sv = std::sin(v);
    Jet j;
    j.X = { { r * cu * sv, r * su * sv, r * cv } };
    j.Xu = { { -r * su * sv, r * cu * sv, 0.0 } };
    j.Xv = { { r * cu * cv, r * su * cv, -r * sv } };
    j.Xuu = { { -r * cu * sv, -r * su * sv, 0.0 } };
    j.Xuv = { { -r * su * cv, r * cu * cv, 0.0 } };
    j.Xvv = { { -r * cu * sv, -r * su * sv, -r * cv } };
    return j;
  };
  s.OutwardFlip = true; // X_u x X_v points inward for this parametrization
  return s;
}

/// Ellipsoid with semi-axes a, b, c; outward normals.
inline Surface Ellipsoid(double a, double b, double c)
{
  Surface s{ "ellipsoid", 0.0, 2.0 * Pi, 0.0, Pi, nullptr, Closed, true };
  s.Evaluate = [a, b, c](double u, double v)
  {
    const double cu = std::cos(u), su = std::sin(u), cv = std::cos(v), sv = std::sin(v);
    Jet j;
    j.X = { { a * cu * sv, b * su * sv, c * cv } };
    j.Xu = { { -a * su * sv, b * cu * sv, 0.0 } };
    j.Xv = { { a * cu * cv, b * su * cv, -c * sv } };
    j.Xuu = { { -a * cu * sv, -b * su * sv, 0.0 } };
    j.Xuv = { { -a * su * cv, b * cu * cv, 0.0 } };
    j.Xvv = { { -a * cu * sv, -b * su * sv, -c * cv } };
    return j;
  };
  return s;
}

/// Cylinder of radius r along z, z in [-h/2, h/2]; outward normals;
/// k_max = 1/r around, k_min = 0 along the axis.
inline Surface Cylinder(double r, double h)
{
  Surface s{ "cylinder", 0.0, 2.0 * Pi, -h / 2.0, h / 2.0, nullptr, nullptr, false };
  s.Evaluate = [r](double u, double v)
  {
    const double cu = std::cos(u), su = std::sin(u);
    Jet j;
    j.X = { { r * cu, r * su, v } };
    j.Xu = { { -r * su, r * cu, 0.0 } };
    j.Xv = { { 0.0, 0.0, 1.0 } };
    j.Xuu = { { -r * cu, -r * su, 0.0 } };
    j.Xuv = { { 0.0, 0.0, 0.0 } };
    j.Xvv = { { 0.0, 0.0, 0.0 } };
    return j;
  };
  s.BoundaryDistance = [h](double, double v) { return h / 2.0 - std::fabs(v); };
  return s;
}

/// Torus with major radius R and minor radius r in the xy plane; outward
/// normals; k_max = 1/r, k_min = cos(v) / (R + r cos(v)).
inline Surface Torus(double R, double r)
{
  Surface s{ "torus", 0.0, 2.0 * Pi, 0.0, 2.0 * Pi, nullptr, Closed, false };
  s.Evaluate = [R, r](double u, double v)
  {
    const double cu = std::cos(u), su = std::sin(u), cv = std::cos(v), sv = std::sin(v);
    const double w = R + r * cv;
    Jet j;
    j.X = { { w * cu, w * su, r * sv } };
    j.Xu = { { -w * su, w * cu, 0.0 } };
    j.Xv = { { -r * sv * cu, -r * sv * su, r * cv } };
    j.Xuu = { { -w * cu, -w * su, 0.0 } };
    j.Xuv = { { r * sv * su, -r * sv * cu, 0.0 } };
    j.Xvv = { { -r * cv * cu, -r * cv * su, -r * sv } };
    return j;
  };
  return s;
}

/// Height field z = f(x, y) over the square [-half, half]^2, normals up.
inline Surface HeightField(const std::string& name,
  double half,
  std::function<std::array<double, 6>(double, double)> f) // f, fx, fy, fxx, fxy, fyy
{
  Surface s{ name, -half, half, -half, half, nullptr, nullptr, false };
  s.Evaluate = [f](double x, double y)
  {
    const std::array<double, 6> d = f(x, y);
    Jet j;
    j.X = { { x, y, d[0] } };
    j.Xu = { { 1.0, 0.0, d[1] } };
    j.Xv = { { 0.0, 1.0, d[2] } };
    j.Xuu = { { 0.0, 0.0, d[3] } };
    j.Xuv = { { 0.0, 0.0, d[4] } };
    j.Xvv = { { 0.0, 0.0, d[5] } };
    return j;
  };
  s.BoundaryDistance = [half](double x, double y)
  { return half - std::max(std::fabs(x), std::fabs(y)); };
  return s;
}

/// Plane z = 0 over [-half, half]^2: k = 0.
inline Surface Plane(double half)
{
  return HeightField("plane",
    half,
    [](double, double) {
      return std::array<double, 6>{ { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 } };
    });
}

/// Saddle z = (x^2 - y^2) / (2 a): principal curvatures +-1/a at the origin.
inline Surface Saddle(double half, double a)
{
  return HeightField("saddle",
    half,
    [a](double x, double y)
    {
      return std::array<double, 6>{
        { (x * x - y * y) / (2.0 * a), x / a, -y / a, 1.0 / a, 0.0, -1.0 / a }
      };
    });
}

/// Paraboloid z = (x^2 + y^2) / (2 a) (a bowl opening toward the normal).
inline Surface Paraboloid(double half, double a)
{
  return HeightField("paraboloid",
    half,
    [a](double x, double y)
    {
      return std::array<double, 6>{
        { (x * x + y * y) / (2.0 * a), x / a, y / a, 1.0 / a, 0.0, 1.0 / a }
      };
    });
}

/// Wavy height field z = amp sin(x / w) cos(y / w).
inline Surface Wave(double half, double amp, double w)
{
  return HeightField("wave",
    half,
    [amp, w](double x, double y)
    {
      const double sx = std::sin(x / w), cx = std::cos(x / w), sy = std::sin(y / w),
                   cy = std::cos(y / w);
      const double w2 = w * w;
      return std::array<double, 6>{ { amp * sx * cy,
        amp * cx * cy / w,
        -amp * sx * sy / w,
        -amp * sx * cy / w2,
        -amp * cx * sy / w2,
        -amp * sx * cy / w2 } };
    });
}

/// A box with rounded edges: the points at distance `radius` from the box
/// [-half, half] (flat faces, quarter cylinders along the edges, sphere
/// octants at the corners), sampled uniformly by area; outward normals.
/// On the faces both curvatures are 0, across an edge 1/radius (along it
/// 0), at a corner 1/radius.
inline std::vector<SurfaceSample> SampleRoundedBox(const Vec& half,
  double radius,
  int count,
  std::uint64_t seed)
{
  Random random(seed);
  double faces[3], edges[3];
  for (int k = 0; k < 3; ++k)
  {
    const double a = half[(k + 1) % 3], b = half[(k + 2) % 3];
    faces[k] = 2.0 * 4.0 * a * b;                       // the two faces across axis k
    edges[k] = 4.0 * 0.5 * Pi * radius * 2.0 * half[k]; // the four edges along axis k
  }
  const double corners = 4.0 * Pi * radius * radius;
  const double total = faces[0] + faces[1] + faces[2] + edges[0] + edges[1] + edges[2] + corners;
  std::vector<SurfaceSample> samples;
  samples.reserve(count);
  auto sign = [&random]() { return random.Uniform() < 0.5 ? -1.0 : 1.0; };
  while (static_cast<int>(samples.size()) < count)
  {
    double pick = random.Uniform() * total;
    SurfaceSample s{};
    s.BoundaryDistance = Infinity;
    int axis = 0;
    while (axis < 3 && pick >= faces[axis])
    {
      pick -= faces[axis++];
    }
    Vec offset{ { 0.0, 0.0, 0.0 } }; // the unit normal, away from the box
    Vec core{ { 0.0, 0.0, 0.0 } };   // the nearest point of the box
    if (axis < 3)
    {
      for (int k = 0; k < 3; ++k)
      {
        core[k] = (2.0 * random.Uniform() - 1.0) * half[k];
      }
      offset[axis] = sign();
      core[axis] = offset[axis] * half[axis];
      s.MaximumDirection[(axis + 1) % 3] = 1.0;
    }
    else
    {
      axis = 0;
      while (axis < 3 && pick >= edges[axis])
      {
        pick -= edges[axis++];
      }
      if (axis < 3)
      {
        const int a = (axis + 1) % 3, b = (axis + 2) % 3;
        const double angle = 0.5 * Pi * random.Uniform();
        const double sa = sign(), sb = sign();
        offset[a] = sa * std::cos(angle);
        offset[b] = sb * std::sin(angle);
        core[axis] = (2.0 * random.Uniform() - 1.0) * half[axis];
        core[a] = sa * half[a];
        core[b] = sb * half[b];
        s.MaximumCurvature = 1.0 / radius;
        s.MaximumDirection = Unit(Cross(
          offset, Vec{ { axis == 0 ? 1.0 : 0.0, axis == 1 ? 1.0 : 0.0, axis == 2 ? 1.0 : 0.0 } }));
      }
      else
      {
        offset = Unit(Vec{ { random.Normal(), random.Normal(), random.Normal() } });
        for (int k = 0; k < 3; ++k)
        {
          core[k] = (offset[k] < 0.0 ? -1.0 : 1.0) * half[k];
        }
        s.MaximumCurvature = s.MinimumCurvature = 1.0 / radius;
        s.MaximumDirection = Unit(Cross(offset, Vec{ { 0.0, 0.0, 1.0 } }));
      }
    }
    s.Point = Add(core, Scale(radius, offset));
    s.Normal = offset;
    samples.push_back(s);
  }
  return samples;
}

/// Adds isotropic Gaussian noise of standard deviation sigma to the points
/// (normals and exact values stay those of the noise-free surface).
inline void AddPositionNoise(std::vector<SurfaceSample>& samples, double sigma, std::uint64_t seed)
{
  Random random(seed);
  for (SurfaceSample& s : samples)
  {
    for (int k = 0; k < 3; ++k)
    {
      s.Point[k] += sigma * random.Normal();
    }
  }
}

/// Moves a share of the points (each with that chance) by isotropic
/// Gaussian noise of standard deviation sigma, as stray returns are; their
/// normals and exact values stay those of the point they came from.
/// Returns which were moved.
inline std::vector<bool> AddOutliers(std::vector<SurfaceSample>& samples,
  double share,
  double sigma,
  std::uint64_t seed)
{
  Random random(seed);
  std::vector<bool> moved(samples.size(), false);
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    moved[i] = random.Uniform() < share;
    for (int k = 0; k < 3 && moved[i]; ++k)
    {
      samples[i].Point[k] += sigma * random.Normal();
    }
  }
  return moved;
}

/// Turns every normal by a random tangential vector (Gaussian, standard
/// deviation `angle` radians along each tangent axis), as estimated
/// normals are off: normals that no longer follow the surface as exact
/// ones do (the automatic scale's fourth order stays off for them).
inline void TiltNormals(std::vector<SurfaceSample>& samples, double angle, std::uint64_t seed)
{
  Random random(seed);
  for (SurfaceSample& s : samples)
  {
    Vec tilt{ { angle * random.Normal(), angle * random.Normal(), angle * random.Normal() } };
    tilt = Add(tilt, Scale(-Dot(tilt, s.Normal), s.Normal));
    s.Normal = Unit(Add(s.Normal, tilt));
  }
}

/// Rounds every coordinate to a multiple of `step` (a grid of that
/// spacing), then shifts it by `offset` (as LAS files store positions: an
/// offset plus integers times a scale).
inline void RoundPositions(std::vector<SurfaceSample>& samples, double step, double offset = 0.0)
{
  for (SurfaceSample& s : samples)
  {
    for (double& x : s.Point)
    {
      x = offset + std::nearbyint(x / step) * step;
    }
  }
}

} // namespace testing
} // namespace pcurv

#endif
