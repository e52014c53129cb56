// libFuzzer target on the numeric core (no VTK): random and degenerate
// neighbourhoods, extreme magnitudes, random sine-fit inputs, grid queries
// and the dynamic adjustment. Aborts when an invariant breaks:
// - a valid estimate has finite curvatures, max >= min, unit principal
//   directions orthogonal to the normal and to each other;
// - the grid finds exactly the points a brute-force scan finds;
// - the adjustment keeps s and p finite and positive.
#include "DynamicAdjustment.h"
#include "PointGrid.h"
#include "PrincipalCurvatureCore.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace
{
/// Reads values from the fuzzer's bytes; zeros once they run out.
class Bytes
{
public:
  Bytes(const std::uint8_t* data, std::size_t size)
    : Data(data)
    , Size(size)
  {
  }
  std::uint8_t Byte() { return this->Position < this->Size ? this->Data[this->Position++] : 0; }
  /// A finite double of any magnitude the core's contract allows (the VTK
  /// class drops non-finite coordinates before the core sees them).
  double Finite()
  {
    double value = 0.0;
    if (this->Position + sizeof value <= this->Size)
    {
      std::memcpy(&value, this->Data + this->Position, sizeof value);
      this->Position += sizeof value;
    }
    if (!std::isfinite(value) || std::fabs(value) > 1e100)
    {
      value = 0.0;
    }
    return value;
  }
  /// A small integer-valued coordinate, to make coincidences likely.
  double Small() { return static_cast<int>(this->Byte()) - 128; }
  bool Empty() const { return this->Position >= this->Size; }

private:
  const std::uint8_t* Data;
  std::size_t Size;
  std::size_t Position = 0;
};

void Require(bool condition, const char* what)
{
  if (!condition)
  {
    std::fprintf(stderr, "invariant broken: %s\n", what);
    std::abort();
  }
}

void CheckEstimate(Bytes& in)
{
  const int shape = in.Byte() % 5;
  const double scale = std::ldexp(1.0, static_cast<int>(in.Byte() % 80) - 40); // 1e-12 .. 1e12
  pcurv::Vector3 x{ { in.Finite(), in.Finite(), in.Finite() } };
  pcurv::Vector3 n{ { in.Small(), in.Small(), in.Small() } };
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (!(length > 0.0))
  {
    n = { { 0.0, 0.0, 1.0 } };
  }
  else
  {
    n = { { n[0] / length, n[1] / length, n[2] / length } };
  }
  const double s = scale * (1 + in.Byte());
  const double p = s * (1 + in.Byte()) / 256.0;
  const int count = in.Byte() * 4;
  std::vector<double> neighbors;
  for (int j = 0; j < count && !in.Empty(); ++j)
  {
    double d[3] = { scale * in.Small(), scale * in.Small(), scale * in.Small() };
    switch (shape)
    {
      case 1: // coplanar with the tangent plane
        d[2] = 0.0;
        break;
      case 2: // collinear
        d[1] = d[2] = 0.0;
        break;
      case 3: // duplicates of the query point
        d[0] = d[1] = d[2] = 0.0;
        break;
      case 4: // a real curved patch: z = (a x^2 + b y^2) / 2 in the normal's frame
      {
        const double a = in.Small() / (64.0 * scale), b = in.Small() / (64.0 * scale);
        d[2] = 0.5 * (a * d[0] * d[0] + b * d[1] * d[1]);
        break;
      }
      default:
        break;
    }
    for (int k = 0; k < 3; ++k)
    {
      neighbors.push_back(x[k] + d[k]);
    }
  }
  pcurv::PointCurvatureEstimator estimator;
  pcurv::FitSettings settings;
  settings.Mode = static_cast<pcurv::FitMode>(in.Byte() % 3);
  estimator.Begin(x, n, p, s);
  estimator.AddNeighbors(neighbors.data(), neighbors.size() / 3);
  const pcurv::PointCurvature r = estimator.Estimate(settings);
  if (!r.Valid)
  {
    return;
  }
  Require(
    std::isfinite(r.MinimumCurvature) && std::isfinite(r.MaximumCurvature), "finite curvatures");
  Require(r.MaximumCurvature >= r.MinimumCurvature, "max >= min");
  auto dot = [](const pcurv::Vector3& a, const pcurv::Vector3& b)
  { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  Require(std::fabs(dot(r.MinimumDirection, r.MinimumDirection) - 1.0) < 1e-9, "unit d_min");
  Require(std::fabs(dot(r.MaximumDirection, r.MaximumDirection) - 1.0) < 1e-9, "unit d_max");
  Require(std::fabs(dot(r.MaximumDirection, r.MinimumDirection)) < 1e-9, "d_min . d_max = 0");
  Require(std::fabs(dot(r.MaximumDirection, n)) < 1e-9, "d_max . n = 0");
  Require(r.ValidDirections >= 3 && r.ValidDirections <= 16, "valid direction count");
}

void CheckSineFit(Bytes& in)
{
  std::array<double, pcurv::NumberOfDirections> kappa{};
  std::array<bool, pcurv::NumberOfDirections> valid{};
  for (int i = 0; i < pcurv::NumberOfDirections; ++i)
  {
    kappa[i] = in.Finite();
    valid[i] = in.Byte() & 1;
  }
  const pcurv::SineFit fit = pcurv::FitSine(kappa, valid);
  if (fit.Valid)
  {
    Require(std::isfinite(fit.Offset) && std::isfinite(fit.RmsResidual), "finite sine fit");
  }
}

void CheckGrid(Bytes& in)
{
  const int count = 1 + in.Byte();
  std::vector<double> points;
  for (int i = 0; i < 3 * count; ++i)
  {
    points.push_back(in.Small() * 0.25);
  }
  double lower[3] = { 1e300, 1e300, 1e300 }, upper[3] = { -1e300, -1e300, -1e300 };
  for (int i = 0; i < count; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      lower[k] = std::min(lower[k], points[3 * i + k]);
      upper[k] = std::max(upper[k], points[3 * i + k]);
    }
  }
  const double cell = 0.05 * (1 + in.Byte());
  pcurv::PointGrid grid;
  grid.Build(points.data(), count, pcurv::GridLattice::Make(lower, upper, count, cell));
  const double x[3] = { in.Small() * 0.25, in.Small() * 0.25, in.Small() * 0.25 };
  const double radius = 0.1 * in.Byte();
  std::vector<double> found;
  grid.GatherWithinRadius(x, radius, found);
  std::size_t expected = 0;
  for (int i = 0; i < count; ++i)
  {
    const double dx = points[3 * i] - x[0], dy = points[3 * i + 1] - x[1],
                 dz = points[3 * i + 2] - x[2];
    expected += dx * dx + dy * dy + dz * dz < radius * radius;
  }
  Require(found.size() == 3 * expected, "grid finds what a scan finds");
}

void CheckAdjustment(Bytes& in)
{
  pcurv::AdjustmentSettings settings;
  settings.LengthUnit = std::ldexp(1.0, static_cast<int>(in.Byte() % 60) - 30);
  pcurv::DynamicAdjustment adjustment(settings);
  for (int step = 0; step < 64 && !in.Empty(); ++step)
  {
    const double p = adjustment.Adjust(in.Byte() * in.Byte());
    Require(std::isfinite(p) && p > 0.0, "p finite, positive");
    const double s = adjustment.GetSurroundingsThreshold();
    Require(
      std::isfinite(s) && s > 0.0 && s <= 16.0 * settings.LengthUnit * (1 + 1e-12), "s bounded");
    Require(adjustment.GetLevel() >= 0 && adjustment.GetLevel() <= 2, "level in range");
  }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  Bytes in(data, size);
  switch (in.Byte() % 4)
  {
    case 0:
      CheckEstimate(in);
      break;
    case 1:
      CheckSineFit(in);
      break;
    case 2:
      CheckGrid(in);
      break;
    default:
      CheckAdjustment(in);
      break;
  }
  return 0;
}
