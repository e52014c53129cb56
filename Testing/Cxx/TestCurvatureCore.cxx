// Tests of the numeric core alone (no VTK): frame, half-plane binning,
// circle fits, sine fit and the per-point estimator.
#include "AnalyticSurfaces.h"
#include "Fits/OrientedCircleFit.h"
#include "Kernels/SimdKernels.h"
#include "Fits/PrincipalCurvatureCore.h"
#include "TestChecks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace
{
using namespace pcurv;
using testing::Random;

void TestTangentFrame(Checks& checks)
{
  Random random(1);
  for (int trial = 0; trial < 1000; ++trial)
  {
    testing::Vec n{ { random.Normal(), random.Normal(), random.Normal() } };
    n = testing::Unit(n);
    const TangentFrame frame = MakeTangentFrame(n);
    checks.Near("|v0| = 1", testing::Dot(frame.V0, frame.V0), 1.0, 1e-12);
    checks.Near("|w0| = 1", testing::Dot(frame.W0, frame.W0), 1.0, 1e-12);
    checks.Near("v0 . n = 0", testing::Dot(frame.V0, n), 0.0, 1e-12);
    checks.Near("w0 . v0 = 0", testing::Dot(frame.W0, frame.V0), 0.0, 1e-12);
    const testing::Vec w = testing::Cross(n, frame.V0);
    checks.Near("w0 = n x v0", testing::Dot(w, frame.W0), 1.0, 1e-12);
  }
}

/// The definition's 16-plane test: direction i holds t when t . v_i > 0
/// and |t . (n x v_i)| < p.
std::uint32_t PlaneTestMask(double tx, double ty, double p)
{
  std::uint32_t mask = 0;
  for (int i = 0; i < NumberOfDirections; ++i)
  {
    const double theta = i * 3.14159265358979323846 / 8.0;
    const double along = tx * std::cos(theta) + ty * std::sin(theta);
    const double across = -tx * std::sin(theta) + ty * std::cos(theta);
    if (along > 0.0 && std::fabs(across) < p)
    {
      mask |= 1u << i;
    }
  }
  return mask;
}

/// The polar-angle binning must give exactly the directions of the plain
/// 16-plane test of the definition.
void TestDirectionMaskMatchesPlaneTest(Checks& checks)
{
  Random random(2);
  int mismatches = 0;
  for (int trial = 0; trial < 200000; ++trial)
  {
    const double tx = 2.0 * random.Uniform() - 1.0;
    const double ty = 2.0 * random.Uniform() - 1.0;
    const double p = 0.3 * random.Uniform() * random.Uniform();
    mismatches += PointCurvatureEstimator::DirectionMask(tx, ty, p) != PlaneTestMask(tx, ty, p);
  }
  checks.Equal("direction mask mismatches", mismatches, 0);
  // Tangent coordinates whose squares underflow to 0 (found by fuzzing):
  // not the query point, but a point in the eight half planes facing it.
  checks.Equal("point whose squared distance underflows",
    static_cast<int>(PointCurvatureEstimator::DirectionMask(1e-170, 1e-171, 1e-150)),
    static_cast<int>(PlaneTestMask(1e-170, 1e-171, 1e-150)));
  checks.Equal("point on the normal line has no direction",
    static_cast<int>(PointCurvatureEstimator::DirectionMask(0.0, 0.0, 0.1)),
    0);
  // A point on direction 0's ray, far away, belongs to direction 0 only.
  checks.Equal("far point on the ray of direction 0",
    static_cast<int>(PointCurvatureEstimator::DirectionMask(1.0, 0.0, 0.01)),
    1);
}

/// One random offset for the kernel comparison: mostly ordinary points,
/// some exactly on a direction's ray or on a slice boundary (where the
/// sector tests compare equal values), some degenerate.
void RandomOffset(Random& random, double& x, double& y, double& z)
{
  const double kind = random.Uniform();
  const double angle = 3.14159265358979323846 / 8.0 * std::floor(32.0 * random.Uniform()) / 2.0;
  const double r = 2.0 * random.Uniform();
  x = 2.0 * random.Uniform() - 1.0;
  y = 2.0 * random.Uniform() - 1.0;
  z = 0.2 * random.Uniform() - 0.1;
  if (kind < 0.2) // on a ray of a direction or half way between two
  {
    x = r * std::cos(angle);
    y = r * std::sin(angle);
  }
  else if (kind < 0.3) // |x| == |y| or |y| == tan(pi / 8) |x|
  {
    y = (random.Uniform() < 0.5 ? x : 0.41421356237309503 * x) * (random.Uniform() < 0.5 ? -1 : 1);
  }
  else if (kind < 0.35)
  {
    x = y = 0.0;
  }
  else if (kind < 0.4)
  {
    const double specials[] = { std::numeric_limits<double>::quiet_NaN(),
      std::numeric_limits<double>::infinity(),
      -std::numeric_limits<double>::infinity(),
      1e-320,
      -0.0,
      1e300 };
    x = specials[static_cast<int>(6.0 * random.Uniform()) % 6];
  }
}

/// Every instruction set's kernel gives bit for bit the generic kernel's
/// output, for every block length (whole vectors and tails).
void TestBinningKernelsAgree(Checks& checks)
{
  const std::vector<std::string> kernels = AvailableKernels();
  std::printf(
    "binning kernels: %zu available, active: %s\n", kernels.size(), ActiveKernel().c_str());
  checks.True("the generic kernel is available", kernels.front() == "generic");
  Random random(17);
  constexpr std::size_t Room = binning::BlockSize + binning::Padding;
  struct Output
  {
    binning::Block Block;
    double H[Room], D[Room], Tx[Room], Ty[Room];
    std::int64_t Mask[Room];
    std::vector<double> Banks = std::vector<double>(binning::BankDoubles, 0.0);
    explicit Output(std::size_t firstSlot)
    {
      this->Block.H = this->H;
      this->Block.D = this->D;
      this->Block.Tx = this->Tx;
      this->Block.Ty = this->Ty;
      this->Block.Mask = this->Mask;
      this->Block.Banks = this->Banks.data();
      this->Block.FirstSlot = firstSlot;
    }
    /// The banks' records of the 16 directions (not the dead end's), and
    /// the rare records.
    bool SameBanks(const Output& other) const
    {
      if (std::memcmp(this->Banks.data() + binning::RareRecordsStart,
            other.Banks.data() + binning::RareRecordsStart,
            (binning::BankDoubles - binning::RareRecordsStart) * sizeof(double)) != 0)
      {
        return false;
      }
      for (int bank = 0; bank < binning::NumberOfBanks; ++bank)
      {
        const std::size_t start =
          static_cast<std::size_t>(bank) * binning::RecordsPerBank * binning::RecordSize;
        if (std::memcmp(this->Banks.data() + start,
              other.Banks.data() + start,
              16 * binning::RecordSize * sizeof(double)) != 0)
        {
          return false;
        }
      }
      return true;
    }
  };
  long differences = 0, blocks = 0;
  for (int trial = 0; trial < 20000; ++trial)
  {
    const std::size_t count = 1 + static_cast<std::size_t>(trial % binning::BlockSize);
    // Every seventh block in the identity frame, where offsets on a ray or
    // a slice boundary stay exactly there.
    const bool identity = trial % 7 == 0;
    testing::Vec n{ { random.Normal(), random.Normal(), random.Normal() } };
    const TangentFrame t = identity
      ? TangentFrame{ { { 0.0, 0.0, 1.0 } }, { { 1.0, 0.0, 0.0 } }, { { 0.0, 1.0, 0.0 } } }
      : MakeTangentFrame(testing::Unit(n));
    const double scale = identity ? 1.0 : 0.5 + random.Uniform();
    const binning::Frame frame{ { t.Normal[0], t.Normal[1], t.Normal[2] },
      { t.V0[0], t.V0[1], t.V0[2] },
      { t.W0[0], t.W0[1], t.W0[2] },
      1.0 / scale,
      0.3 * random.Uniform() };
    double dx[binning::BlockSize], dy[binning::BlockSize], dz[binning::BlockSize];
    for (std::size_t j = 0; j < count; ++j)
    {
      RandomOffset(random, dx[j], dy[j], dz[j]);
      dz[j] = identity ? 0.0 : dz[j];
    }
    const std::size_t firstSlot = static_cast<std::size_t>(trial % 11);
    Output reference(firstSlot);
    binning::ClassifyWith("generic", frame, dx, dy, dz, count, reference.Block);
    for (const std::string& kernel : kernels)
    {
      Output out(firstSlot);
      checks.True(
        "kernel runs", binning::ClassifyWith(kernel, frame, dx, dy, dz, count, out.Block));
      ++blocks;
      const std::size_t doubles = count * sizeof(double);
      const std::size_t integers = count * sizeof(std::int64_t);
      const bool same = std::memcmp(out.H, reference.H, doubles) == 0 &&
        std::memcmp(out.D, reference.D, doubles) == 0 &&
        std::memcmp(out.Tx, reference.Tx, doubles) == 0 &&
        std::memcmp(out.Ty, reference.Ty, doubles) == 0 &&
        std::memcmp(out.Mask, reference.Mask, integers) == 0 && out.SameBanks(reference) &&
        out.Block.AtQueryPoint == reference.Block.AtQueryPoint;
      differences += same ? 0 : 1;
    }
  }
  std::printf("kernel blocks compared: %ld\n", blocks);
  checks.Equal("blocks where a kernel differs from the generic one", differences, 0L);
  Output unused(0);
  checks.True("an unknown kernel is refused",
    !binning::ClassifyWith("none", binning::Frame{}, nullptr, nullptr, nullptr, 0, unused.Block));
}

/// Combining the banks: every kernel gives the documented order's sums
/// (eight banks pairwise, then the rare record) and the largest extent.
void TestCombineKernelsAgree(Checks& checks)
{
  Random random(31);
  std::vector<double> banks(binning::BankDoubles);
  long differences = 0;
  for (int trial = 0; trial < 200; ++trial)
  {
    for (double& value : banks)
    {
      // Magnitudes far apart, so that another order of the adds rounds
      // differently.
      value = random.Normal() * std::pow(10.0, static_cast<int>(12.0 * random.Uniform()) - 6);
    }
    double expected[binning::NumberOfDirections * binning::RecordSize];
    constexpr std::size_t Stride = binning::RecordsPerBank * binning::RecordSize;
    for (int i = 0; i < binning::NumberOfDirections; ++i)
    {
      const double* r = banks.data() + i * binning::RecordSize;
      const double* rare = banks.data() + binning::RareRecordsStart + i * binning::RecordSize;
      for (int f = 0; f < binning::RecordSize; ++f)
      {
        expected[i * binning::RecordSize + f] =
          ((r[f] + r[Stride + f]) + (r[2 * Stride + f] + r[3 * Stride + f])) +
          ((r[4 * Stride + f] + r[5 * Stride + f]) + (r[6 * Stride + f] + r[7 * Stride + f])) +
          rare[f];
      }
      double extent = rare[binning::Extent];
      for (int bank = 0; bank < binning::NumberOfBanks; ++bank)
      {
        extent = std::max(extent, r[bank * Stride + binning::Extent]);
      }
      expected[i * binning::RecordSize + binning::Extent] = extent;
    }
    for (const std::string& kernel : AvailableKernels())
    {
      double totals[binning::NumberOfDirections * binning::RecordSize];
      checks.True("kernel runs", binning::CombineBanksWith(kernel, banks.data(), totals));
      differences += std::memcmp(totals, expected, sizeof totals) == 0 ? 0 : 1;
    }
  }
  checks.Equal("combined banks differing from the documented order", differences, 0L);
  // OrientedCircles' banks: every sum's eight, in the scalar tree's order
  // (lengths that leave a tail after the groups of eight).
  long orientedDifferences = 0;
  for (const int entries : { 129, 264, 7, 1 })
  {
    std::vector<double> oriented(static_cast<std::size_t>(entries) * 8);
    for (double& value : oriented)
    {
      value = random.Normal() * std::pow(10.0, static_cast<int>(12.0 * random.Uniform()) - 6);
    }
    std::vector<double> expected(entries);
    for (int e = 0; e < entries; ++e)
    {
      const double* b = &oriented[static_cast<std::size_t>(e) * 8];
      expected[e] = ((b[0] + b[1]) + (b[2] + b[3])) + ((b[4] + b[5]) + (b[6] + b[7]));
    }
    for (const std::string& kernel : AvailableKernels())
    {
      std::vector<double> totals(entries);
      checks.True(
        "kernel runs", oriented::CombineBanksWith(kernel, oriented.data(), entries, totals.data()));
      orientedDifferences +=
        std::memcmp(totals.data(), expected.data(), entries * sizeof(double)) == 0 ? 0 : 1;
    }
  }
  checks.Equal(
    "OrientedCircles' combined banks differing from the documented order", orientedDifferences, 0L);
}

/// The shell gather kernels: the same points, offsets, ids and count as
/// the generic one, for runs of every length, points exactly on either
/// sphere (the inner one's are in the shell, the outer one's are not) and
/// non-finite coordinates; and the generic one keeps exactly the points of
/// the shell.
void TestShellGatherKernelsAgree(Checks& checks)
{
  Random random(37);
  const std::size_t points = 4000;
  std::vector<double> x(points), y(points), z(points);
  std::vector<std::int64_t> ids(points);
  for (std::size_t j = 0; j < points; ++j)
  {
    x[j] = 2.0 * random.Uniform() - 1.0;
    y[j] = 2.0 * random.Uniform() - 1.0;
    z[j] = 2.0 * random.Uniform() - 1.0;
    ids[j] = static_cast<std::int64_t>(7 * j + 3);
    if (j % 97 == 0)
    {
      x[j] = j % 2 ? 0.5 : 0.25; // on the outer or the inner sphere
      y[j] = z[j] = 0.0;
    }
    if (j % 389 == 0)
    {
      z[j] = std::numeric_limits<double>::quiet_NaN();
    }
  }
  const gather::Candidates in{ x.data(), y.data(), z.data(), ids.data() };
  const double query[3] = { 0.0, 0.0, 0.0 };
  long differences = 0, wrongMembers = 0;
  constexpr std::size_t Room = 64 + gather::Padding;
  struct Gathered
  {
    std::vector<double> Dx = std::vector<double>(Room, -1.0), Dy = Dx, Dz = Dx;
    std::vector<std::int64_t> Ids = std::vector<std::int64_t>(Room, -1);
    gather::Output Out()
    {
      return { this->Dx.data(), this->Dy.data(), this->Dz.data(), this->Ids.data() };
    }
  };
  for (int trial = 0; trial < 2000; ++trial)
  {
    const std::int64_t begin = static_cast<std::int64_t>(random.Uniform() * 3900);
    const std::int64_t end = begin + trial % 40;
    const double innerSquared = trial % 3 == 0 ? 0.0625 : 0.3 * random.Uniform();
    const double radiusSquared = trial % 3 == 0 ? 0.25 : innerSquared + random.Uniform();
    Gathered reference;
    std::size_t keptReference = 3; // appended after three earlier entries
    const gather::Shell shell{ query, innerSquared, radiusSquared };
    gather::ShellWithinWith("generic", in, begin, end, shell, reference.Out(), keptReference);
    std::size_t expected = 3;
    for (std::int64_t j = begin; j < end; ++j)
    {
      const double squared = x[j] * x[j] + y[j] * y[j] + z[j] * z[j];
      if (squared >= innerSquared && squared < radiusSquared)
      {
        wrongMembers += reference.Ids[expected] == ids[j] ? 0 : 1;
        ++expected;
      }
    }
    wrongMembers += expected == keptReference ? 0 : 1;
    for (const std::string& kernel : AvailableKernels())
    {
      Gathered out;
      std::size_t kept = 3;
      checks.True("shell kernel runs",
        gather::ShellWithinWith(kernel, in, begin, end, shell, out.Out(), kept));
      const std::size_t n = (kept - 3) * sizeof(double);
      const bool same = kept == keptReference &&
        std::memcmp(out.Dx.data() + 3, reference.Dx.data() + 3, n) == 0 &&
        std::memcmp(out.Dy.data() + 3, reference.Dy.data() + 3, n) == 0 &&
        std::memcmp(out.Dz.data() + 3, reference.Dz.data() + 3, n) == 0 &&
        std::memcmp(out.Ids.data() + 3, reference.Ids.data() + 3, n) == 0;
      differences += same ? 0 : 1;
    }
  }
  checks.Equal("shell gathers where a kernel differs from the generic one", differences, 0L);
  checks.Equal("shell gathers keeping other points than the shell's", wrongMembers, 0L);
}

/// The gather kernels: the same points, offsets and count as the generic
/// one, for runs of every length (whole vectors and tails), points exactly
/// on the sphere and non-finite coordinates.
void TestGatherKernelsAgree(Checks& checks)
{
  Random random(29);
  const std::size_t points = 4000;
  std::vector<double> x(points), y(points), z(points);
  for (std::size_t j = 0; j < points; ++j)
  {
    x[j] = 2.0 * random.Uniform() - 1.0;
    y[j] = 2.0 * random.Uniform() - 1.0;
    z[j] = 2.0 * random.Uniform() - 1.0;
    if (j % 97 == 0)
    {
      x[j] = 0.5; // at distance 0.5 from the query: excluded (strictly closer)
      y[j] = z[j] = 0.0;
    }
    if (j % 389 == 0)
    {
      y[j] = std::numeric_limits<double>::quiet_NaN();
    }
  }
  const double query[3] = { 0.0, 0.0, 0.0 };
  long differences = 0;
  for (const std::string& kernel : AvailableKernels())
  {
    for (int trial = 0; trial < 2000; ++trial)
    {
      const std::int64_t begin = static_cast<std::int64_t>(random.Uniform() * 3900);
      const std::int64_t end = begin + trial % 40;
      const double radiusSquared = trial % 3 == 0 ? 0.25 : random.Uniform();
      std::vector<double> a(3 * (64 + gather::Padding), -1.0), b = a;
      std::size_t keptA = 3, keptB = 3; // appended after three earlier entries
      gather::WithinRadiusWith("generic",
        x.data(),
        y.data(),
        z.data(),
        begin,
        end,
        query,
        radiusSquared,
        a.data(),
        a.data() + 72,
        a.data() + 144,
        keptA);
      checks.True("gather kernel runs",
        gather::WithinRadiusWith(kernel,
          x.data(),
          y.data(),
          z.data(),
          begin,
          end,
          query,
          radiusSquared,
          b.data(),
          b.data() + 72,
          b.data() + 144,
          keptB));
      bool same = keptA == keptB;
      for (std::size_t k = 0; same && k < keptA; ++k)
      {
        for (int axis = 0; axis < 3; ++axis)
        {
          same = same && std::memcmp(&a[72 * axis + k], &b[72 * axis + k], sizeof(double)) == 0;
        }
      }
      differences += same ? 0 : 1;
    }
  }
  checks.Equal("gathers where a kernel differs from the generic one", differences, 0L);
}

/// New02's summed distances to its circles: every kernel gives the generic
/// one's sums bit for bit, and they equal DistanceToCircle added up.
void TestCircleDistanceKernelsAgree(Checks& checks)
{
  Random random(31);
  long differences = 0;
  double largestRelative = 0.0;
  for (int trial = 0; trial < 3000; ++trial)
  {
    const std::size_t count = static_cast<std::size_t>(trial % 70);
    std::vector<double> h(count), d(count);
    for (std::size_t j = 0; j < count; ++j)
    {
      const double along = random.Uniform();
      h[j] = 0.3 * along * along + 0.01 * random.Normal();
      d[j] = along * along + h[j] * h[j];
    }
    const double kappa[2] = { 2.0 * random.Normal(), trial % 5 == 0 ? 0.0 : 2.0 * random.Normal() };
    double reference[2];
    circles::DistanceSumsWith("generic", h.data(), d.data(), count, kappa, reference);
    for (const std::string& kernel : AvailableKernels())
    {
      double sums[2] = { -1.0, -1.0 };
      checks.True("circle kernel runs",
        circles::DistanceSumsWith(kernel, h.data(), d.data(), count, kappa, sums));
      differences += std::memcmp(sums, reference, sizeof sums) == 0 ? 0 : 1;
    }
    for (int c = 0; c < 2; ++c)
    {
      double plain = 0.0;
      for (std::size_t j = 0; j < count; ++j)
      {
        plain += DistanceToCircle(kappa[c], h[j], d[j]);
      }
      largestRelative =
        std::max(largestRelative, std::fabs(reference[c] - plain) / std::max(plain, 1e-300));
    }
  }
  checks.Equal("circle sums where a kernel differs from the generic one", differences, 0L);
  checks.Near("circle sums against DistanceToCircle (relative)", largestRelative, 0.0, 1e-13);
}

/// OrientedCircleFit.h's rows written out one neighbor at a time: the
/// positions' row (D, D cos 2 phi, D sin 2 phi, 2 u, 2 v, 2 u^3, 2 u^2 v,
/// 2 u v^2, 2 v^3, [2 u^4, 2 u^3 v, 2 u^2 v^2, 2 u v^3, 2 v^4,] 1) with target
/// 2 h; the normals' row (D, D cos 2 phi, D sin 2 phi, u, v, 3 u^3, 3 u^2 v,
/// 3 u v^2, 3 v^3[, 4 u^4, 4 u^3 v, 4 u^2 v^2, 4 u v^3, 4 v^4]) with target
/// -(n_q - n) . d (n_q turned when it opposes n) and weight 1 / D; the
/// bracketed columns at order 4.
template<int Order>
OrientedCircleSumsOf<Order> ReferenceOrientedSums(const TangentFrame& frame,
  const std::vector<std::array<double, 6>>& neighbors)
{
  constexpr int P = OrientedCircleSumsOf<Order>::PositionUnknowns;
  OrientedCircleSumsOf<Order> sums;
  auto add = [](const double* row, int n, double y, double w, double* matrix, double* right)
  {
    for (int a = 0, k = 0; a < n; ++a)
    {
      right[a] += w * row[a] * y;
      for (int b = a; b < n; ++b)
      {
        matrix[k++] += w * row[a] * row[b];
      }
    }
  };
  for (const std::array<double, 6>& q : neighbors)
  {
    const double u = testing::Dot({ { q[0], q[1], q[2] } }, frame.V0);
    const double v = testing::Dot({ { q[0], q[1], q[2] } }, frame.W0);
    const double h = testing::Dot({ { q[0], q[1], q[2] } }, frame.Normal);
    const double squared = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
    if (squared == 0.0)
    {
      continue;
    }
    const double phi = std::atan2(v, u);
    const double c = u * u + v * v > 0.0 ? std::cos(2.0 * phi) : 0.0;
    const double s = u * u + v * v > 0.0 ? std::sin(2.0 * phi) : 0.0;
    const double quartic[5] = {
      u * u * u * u, u * u * u * v, u * u * v * v, u * v * v * v, v * v * v * v
    };
    // Every order's leading columns are the fourth's, the height last.
    double full[14] = { squared,
      squared * c,
      squared * s,
      2 * u,
      2 * v,
      2 * u * u * u,
      2 * u * u * v,
      2 * u * v * v,
      2 * v * v * v };
    for (int k = 9; k < 14; ++k)
    {
      full[k] = 2 * quartic[k - 9];
    }
    double positions[P];
    std::copy_n(full, P - 1, positions);
    positions[P - 1] = 1.0;
    add(positions, P, 2.0 * h, 1.0, sums.PositionMatrix.data(), sums.PositionRight.data());
    sums.PositionTargets += 4.0 * h * h;
    ++sums.Neighbors;
    sums.SquaredDistances += squared;
    const testing::Vec normal{ { q[3], q[4], q[5] } };
    const bool opposing = testing::Dot(normal, frame.Normal) < 0.0;
    const bool hasNormal = q[3] != 0.0 || q[4] != 0.0 || q[5] != 0.0;
    (hasNormal && opposing ? sums.OpposingHeights : sums.AgreeingHeights) += h;
    (hasNormal && opposing ? sums.OpposingSquaredHeights : sums.AgreeingSquaredHeights) += h * h;
    if (!hasNormal)
    {
      continue;
    }
    const double side = opposing ? -1.0 : 1.0;
    double t = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      t -= (side * normal[k] - frame.Normal[k]) * q[k];
    }
    double normals[14] = { squared,
      squared * c,
      squared * s,
      u,
      v,
      3 * u * u * u,
      3 * u * u * v,
      3 * u * v * v,
      3 * v * v * v };
    for (int k = 9; k < 14; ++k)
    {
      normals[k] = 4 * quartic[k - 9];
    }
    add(normals, P - 1, t, 1.0 / squared, sums.NormalMatrix.data(), sums.NormalRight.data());
    sums.NormalTargets += t * t / squared;
    ++sums.NeighborsWithNormal;
    sums.Opposing += opposing;
  }
  return sums;
}

/// How far an accumulator's sums are from the rows' sums one by one
/// (relative to the largest), into `largestRelative`; counts that differ
/// into `countsWrong`.
template<int Order>
void CompareWithReference(const OrientedCircleSumsOf<Order>& sums,
  const OrientedCircleSumsOf<Order>& plain,
  double& largestRelative,
  long& countsWrong)
{
  const double size = std::max(1.0, plain.PositionMatrix[0]);
  auto compare = [&](const double* value, const double* expected, std::size_t count)
  {
    for (std::size_t k = 0; k < count; ++k)
    {
      largestRelative = std::max(largestRelative, std::fabs(value[k] - expected[k]) / size);
    }
  };
  compare(sums.PositionMatrix.data(), plain.PositionMatrix.data(), plain.PositionMatrix.size());
  compare(sums.NormalMatrix.data(), plain.NormalMatrix.data(), plain.NormalMatrix.size());
  compare(sums.PositionRight.data(), plain.PositionRight.data(), plain.PositionRight.size());
  compare(sums.NormalRight.data(), plain.NormalRight.data(), plain.NormalRight.size());
  compare(&sums.PositionTargets, &plain.PositionTargets, 1);
  compare(&sums.NormalTargets, &plain.NormalTargets, 1);
  compare(&sums.OpposingHeights, &plain.OpposingHeights, 1);
  compare(&sums.AgreeingSquaredHeights, &plain.AgreeingSquaredHeights, 1);
  compare(&sums.SquaredDistances, &plain.SquaredDistances, 1);
  countsWrong += sums.Neighbors != plain.Neighbors ||
    sums.NeighborsWithNormal != plain.NeighborsWithNormal || sums.Opposing != plain.Opposing;
}

/// The same sums, bit for bit (every entry and count).
bool SameSums(const OrientedCircleSums& a, const OrientedCircleSums& b)
{
  auto same = [](const auto& x, const auto& y)
  { return std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0; };
  return same(a.PositionMatrix, b.PositionMatrix) && same(a.PositionRight, b.PositionRight) &&
    same(a.NormalMatrix, b.NormalMatrix) && same(a.NormalRight, b.NormalRight) &&
    std::memcmp(&a.PositionTargets, &b.PositionTargets, sizeof(double)) == 0 &&
    std::memcmp(&a.NormalTargets, &b.NormalTargets, sizeof(double)) == 0 &&
    a.Neighbors == b.Neighbors && a.NeighborsWithNormal == b.NeighborsWithNormal &&
    a.Opposing == b.Opposing && a.Sectors == b.Sectors &&
    a.HalfTurnPositions == b.HalfTurnPositions &&
    std::memcmp(&a.SquaredDistances, &b.SquaredDistances, sizeof(double)) == 0 &&
    std::memcmp(&a.OpposingHeights, &b.OpposingHeights, sizeof(double)) == 0 &&
    std::memcmp(&a.AgreeingSquaredHeights, &b.AgreeingSquaredHeights, sizeof(double)) == 0;
}

/// OrientedCircleAccumulator's sums (eight lanes of oriented::AddNeighbors),
/// of the third and of the fourth order, are the rows' sums, and bit for
/// bit the same on every instruction set: neighbors with and without
/// normals, opposing ones, some at the query point or on the normal line,
/// in batches of every length. The third order's part of the fourth's sums
/// is the third order's sums, bit for bit, and the second order's part of
/// either is the second order's rows' sums.
void TestOrientedSumKernelsAgree(Checks& checks)
{
  Random random(41);
  long differences = 0, countsWrong = 0, partsDiffer = 0, groupingDiffers = 0;
  double largestRelative = 0.0;
  for (int trial = 0; trial < 400; ++trial)
  {
    testing::Vec n{ { random.Normal(), random.Normal(), random.Normal() } };
    const TangentFrame frame = MakeTangentFrame(testing::Unit(n));
    const std::size_t count = static_cast<std::size_t>(trial % 150);
    std::vector<std::array<double, 6>> neighbors(count);
    std::vector<double> columns[6];
    for (std::size_t j = 0; j < count; ++j)
    {
      std::array<double, 6>& q = neighbors[j];
      const int kind = static_cast<int>(random.Uniform() * 10.0);
      for (int k = 0; k < 3; ++k)
      {
        // At the query point, on the normal line, or anywhere.
        q[k] = kind == 0 ? 0.0 : kind == 1 ? 0.3 * frame.Normal[k] : random.Normal();
        q[3 + k] = kind == 2 ? 0.0 : frame.Normal[k] + 0.3 * random.Normal();
      }
      const double length = std::sqrt(q[3] * q[3] + q[4] * q[4] + q[5] * q[5]);
      const double flip = kind == 3 ? -1.0 : 1.0; // an opposing normal
      for (int k = 0; k < 6; ++k)
      {
        q[k] = k < 3 || length == 0.0 ? q[k] : flip * q[k] / length;
        columns[k].push_back(q[k]);
      }
    }
    const oriented::Frame f{ { frame.Normal[0], frame.Normal[1], frame.Normal[2] },
      { frame.V0[0], frame.V0[1], frame.V0[2] },
      { frame.W0[0], frame.W0[1], frame.W0[2] } };
    const oriented::NeighborBatch batch{ columns[0].data(),
      columns[1].data(),
      columns[2].data(),
      columns[3].data(),
      columns[4].data(),
      columns[5].data(),
      count };
    auto agree = [&](auto reference)
    {
      oriented::AddNeighborsWith("generic", f, batch, reference);
      for (const std::string& kernel : AvailableKernels())
      {
        decltype(reference) sums{};
        checks.True("oriented kernel runs", oriented::AddNeighborsWith(kernel, f, batch, sums));
        differences += std::memcmp(&sums, &reference, sizeof sums) == 0 ? 0 : 1;
        // Eight at a time (one group per call, where whole batches take
        // several groups per load of the sums): the same adds in the same
        // order.
        decltype(reference) byEights{};
        for (std::size_t first = 0; first < count; first += 8)
        {
          const oriented::NeighborBatch eight{ batch.Dx + first,
            batch.Dy + first,
            batch.Dz + first,
            batch.Nx + first,
            batch.Ny + first,
            batch.Nz + first,
            std::min<std::size_t>(8, count - first) };
          oriented::AddNeighborsWith(kernel, f, eight, byEights);
        }
        groupingDiffers += std::memcmp(&byEights, &reference, sizeof byEights) == 0 ? 0 : 1;
      }
    };
    agree(oriented::Sums{});
    agree(oriented::QuarticSums{});
    OrientedCircleAccumulator third;
    QuarticCircleAccumulator fourth;
    third.Begin(frame);
    fourth.Begin(frame);
    for (const std::array<double, 6>& q : neighbors)
    {
      const double* normal = q[2] == 0.0 && trial % 2 ? nullptr : q.data() + 3;
      third.Add(q.data(), normal);
      fourth.Add(q.data(), normal);
    }
    CompareWithReference(
      third.Sums(), ReferenceOrientedSums<3>(frame, neighbors), largestRelative, countsWrong);
    CompareWithReference(
      fourth.Sums(), ReferenceOrientedSums<4>(frame, neighbors), largestRelative, countsWrong);
    partsDiffer += SameSums(ThirdOrderPart(fourth.Sums()), third.Sums()) ? 0 : 1;
    // The second order's part, of either: the rows of the second order.
    const QuadraticCircleSums second = ReferenceOrientedSums<2>(frame, neighbors);
    CompareWithReference(LowerOrderPart<2>(third.Sums()), second, largestRelative, countsWrong);
    CompareWithReference(LowerOrderPart<2>(fourth.Sums()), second, largestRelative, countsWrong);
  }
  checks.Equal("oriented sums where a kernel differs from the generic one", differences, 0L);
  checks.Equal("oriented sums differing when added eight at a time", groupingDiffers, 0L);
  checks.Equal("oriented sums' neighbor counts wrong", countsWrong, 0L);
  checks.Near("oriented sums against the rows one by one (relative)", largestRelative, 0.0, 1e-12);
  checks.Equal("third order's part of the fourth's sums differs from its own", partsDiffer, 0L);
}

/// Neighbors given as coordinates or as offsets: the same estimate.
void TestOffsetsEqualCoordinates(Checks& checks)
{
  Random random(23);
  const testing::Vec x{ { 0.3, -0.2, 1.1 } };
  std::vector<double> coordinates, dx, dy, dz;
  for (int j = 0; j < 500; ++j)
  {
    const double u = 0.4 * random.Uniform() - 0.2, v = 0.4 * random.Uniform() - 0.2;
    const double q[3] = { x[0] + u, x[1] + v, x[2] + 0.7 * u * u - 0.3 * v * v };
    for (int k = 0; k < 3; ++k)
    {
      coordinates.push_back(q[k]);
    }
    dx.push_back(q[0] - x[0]);
    dy.push_back(q[1] - x[1]);
    dz.push_back(q[2] - x[2]);
  }
  PointCurvatureEstimator a, b;
  a.Begin({ { x[0], x[1], x[2] } }, { { 0.0, 0.0, 1.0 } }, 0.02, 0.2);
  b.Begin({ { x[0], x[1], x[2] } }, { { 0.0, 0.0, 1.0 } }, 0.02, 0.2);
  a.AddNeighbors(coordinates.data(), 500);
  b.AddNeighborOffsets(dx.data(), dy.data(), dz.data(), 200);
  b.AddNeighborOffsets(dx.data() + 200, dy.data() + 200, dz.data() + 200, 300);
  const PointCurvature ra = a.Estimate(FitSettings{});
  const PointCurvature rb = b.Estimate(FitSettings{});
  checks.True("estimated", ra.Valid && rb.Valid);
  checks.True("identical minimum", ra.MinimumCurvature == rb.MinimumCurvature);
  checks.True("identical maximum", ra.MaximumCurvature == rb.MaximumCurvature);
  checks.Equal("identical neighbor counts", a.GetNumberOfNeighbors(), b.GetNumberOfNeighbors());
}

/// Points of a circle through the origin with center (0, 1/kappa) in the
/// (along, h) plane; paper sign: center on the normal's side is positive.
CgaSums CirclePoints(double kappa, int count, double extent, double noise, Random& random)
{
  CgaSums sums;
  for (int j = 0; j < count; ++j)
  {
    const double along = extent * (j + 1) / count;
    double h;
    if (kappa == 0.0)
    {
      h = 0.0;
    }
    else
    {
      const double r = 1.0 / kappa;
      h = r - std::copysign(std::sqrt(r * r - along * along), r);
    }
    h += noise * random.Normal();
    sums.Add(h, along * along + h * h);
  }
  return sums;
}

void TestCircleFits(Checks& checks)
{
  Random random(3);
  for (const double kappa : { 2.0, 0.5, -0.5, -2.0, 0.01 })
  {
    const CgaSums sums = CirclePoints(kappa, 12, 0.4, 0.0, random);
    char label[64];
    std::snprintf(label, sizeof(label), "exact circle kappa=%g", kappa);
    checks.True(
      label, FitPrevious(sums).Valid && FitEquations12(sums).Valid && FitEquations23(sums).Valid);
    checks.Near(label, FitPrevious(sums).Curvature, kappa, 1e-8 * std::fabs(kappa) + 1e-10);
    checks.Near(label, FitEquations12(sums).Curvature, kappa, 1e-9 * std::fabs(kappa));
    checks.Near(label, FitEquations23(sums).Curvature, kappa, 1e-9 * std::fabs(kappa));
  }
  const CgaSums plane = CirclePoints(0.0, 10, 0.5, 0.0, random);
  checks.True("plane: Previous valid", FitPrevious(plane).Valid);
  checks.Near("plane: Previous gives 0", FitPrevious(plane).Curvature, 0.0, 1e-12);
  checks.Near("plane: kappa_23 gives 0", FitEquations23(plane).Curvature, 0.0, 1e-12);
  checks.True("plane: kappa_12 is 0/0, invalid", !FitEquations12(plane).Valid);

  CgaSums twoPoints;
  twoPoints.Add(0.1, 0.2);
  twoPoints.Add(0.1, 0.2);
  checks.True("identical points: kappa_23 invalid", !FitEquations23(twoPoints).Valid);

  // Noise in h: kappa_23 (New01) stays close; kappa_12 is biased.
  const CgaSums noisy = CirclePoints(0.5, 200, 0.5, 0.002, random);
  checks.Near("noisy circle kappa_23", FitEquations23(noisy).Curvature, 0.5, 0.05);
  checks.Near("noisy circle Previous", FitPrevious(noisy).Curvature, 0.5, 0.05);
}

/// Previous's fast eigenvector (shifted inverse iteration) against Eigen's
/// iterative eigensolver on small, random direction sets: three to 30 points
/// of a circle at random along-distances, with and without noise and
/// across-plane offsets. Three points nearly on a line once made the shifted
/// iteration converge to the middle eigenvalue (curvature 5.28 for 0.79).
void TestPreviousMatchesEigenSolver(Checks& checks)
{
  Random random(17);
  int compared = 0, differing = 0;
  double largest = 0.0;
  for (int trial = 0; trial < 200000; ++trial)
  {
    const int count = 3 + static_cast<int>(random.Uniform() * 28);
    const double kappa = 0.1 + 0.9 * random.Uniform();
    CgaSums sums;
    for (int j = 0; j < count; ++j)
    {
      const double along = 0.05 + 0.95 * random.Uniform();
      double h = (1.0 - std::sqrt(std::max(0.0, 1.0 - kappa * kappa * along * along))) / kappa;
      h += trial % 2 ? 0.0 : 0.02 * (random.Uniform() - 0.5);
      const double across = 0.05 * (random.Uniform() - 0.5);
      sums.Add(h, along * along + h * h + across * across, along);
    }
    const CircleFit fast = FitPrevious(sums);
    const CircleFit reference = FitPreviousWithEigenSolver(sums);
    if (fast.Valid != reference.Valid)
    {
      ++differing;
      continue;
    }
    if (fast.Valid)
    {
      ++compared;
      const double difference = std::fabs(fast.Curvature - reference.Curvature);
      largest = std::max(largest, difference);
      differing += difference > 1e-9 * std::max(1.0, std::fabs(reference.Curvature));
    }
  }
  std::printf("Previous vs Eigen's solver: %d fits, largest difference %g\n", compared, largest);
  checks.True("Previous compared on most direction sets", compared > 150000);
  checks.Equal("Previous = Eigen's solver (1e-9)", differing, 0);
}

void TestDistanceToCircle(Checks& checks)
{
  // Circle of curvature 1 (radius 1, center (0, 1)); the point (0, 3) lies 1
  // outside it, the point (0, 1) (the center) 1 inside; h = 0, D = 0 on it.
  checks.Near("distance outside", DistanceToCircle(1.0, 3.0, 9.0), 1.0, 1e-12);
  checks.Near("distance center", DistanceToCircle(1.0, 1.0, 1.0), 1.0, 1e-12);
  checks.Near("distance on circle", DistanceToCircle(1.0, 0.0, 0.0), 0.0, 1e-12);
  // kappa = 0 is the tangent line h = 0: distance |h|.
  checks.Near("distance to line", DistanceToCircle(0.0, 0.25, 1.0), 0.25, 1e-12);
}

void TestSineFit(Checks& checks)
{
  const double offset = 0.3, cosine = -0.2, sine = 0.15;
  std::array<double, NumberOfDirections> kappa{};
  std::array<bool, NumberOfDirections> valid{};
  for (int i = 0; i < NumberOfDirections; ++i)
  {
    const double angle = 2.0 * i * 3.14159265358979323846 / 8.0;
    kappa[i] = offset + cosine * std::cos(angle) + sine * std::sin(angle);
    valid[i] = (i % 5) != 3; // a few gaps
  }
  SineFit fit = FitSine(kappa, valid);
  checks.True("sine fit with gaps valid", fit.Valid);
  checks.Near("offset", fit.Offset, offset, 1e-12);
  checks.Near("cos amplitude", fit.CosineAmplitude, cosine, 1e-12);
  checks.Near("sin amplitude", fit.SineAmplitude, sine, 1e-12);
  checks.Near("rms", fit.RmsResidual, 0.0, 1e-12);

  // Directions 0, 1, 2 and their opposites 8, 9, 10: 2 theta covers only
  // 0..pi/2, inside a half-turn: rejected.
  valid.fill(false);
  for (int i : { 0, 1, 2, 8, 9, 10 })
  {
    valid[i] = true;
  }
  checks.True("clustered directions rejected", !FitSine(kappa, valid).Valid);
  // 2 theta at 0, pi/2, pi (a closed half-turn): rejected; adding 3pi/2: fine.
  valid.fill(false);
  valid[0] = valid[2] = valid[4] = true;
  checks.True("closed half-turn rejected", !FitSine(kappa, valid).Valid);
  valid[6] = true;
  checks.True("spread directions accepted", FitSine(kappa, valid).Valid);
  valid.fill(false);
  valid[0] = valid[8] = true;
  checks.True("two directions rejected", !FitSine(kappa, valid).Valid);
}

/// One point on a sphere, ellipsoid and saddle with exact neighbors: the
/// estimator must recover the exact values in every mode.
void TestEstimatorOnSurfaces(Checks& checks)
{
  struct Case
  {
    testing::Surface Surface;
    double Radius;
  };
  const Case cases[] = { { testing::Sphere(2.0), 0.5 },
    { testing::Ellipsoid(3.0, 2.0, 1.5), 0.4 },
    { testing::Saddle(2.0, 1.0), 0.25 },
    { testing::Torus(3.0, 1.0), 0.35 } };
  for (const Case& c : cases)
  {
    const auto samples = testing::Sample(c.Surface, 60000, 7);
    for (int mode = 0; mode < 3; ++mode)
    {
      PointCurvatureEstimator estimator;
      FitSettings settings;
      settings.Mode = static_cast<FitMode>(mode);
      double worst = 0.0;
      double worstAngle = 0.0;
      for (int q = 0; q < 50; ++q)
      {
        const testing::SurfaceSample& x = samples[q * 97];
        if (x.BoundaryDistance < 2.0 * c.Radius)
        {
          continue;
        }
        estimator.Begin(x.Point, x.Normal, 0.1 * c.Radius, c.Radius);
        for (const testing::SurfaceSample& s : samples)
        {
          const testing::Vec d = testing::Add(s.Point, testing::Scale(-1.0, x.Point));
          if (testing::Dot(d, d) < c.Radius * c.Radius)
          {
            estimator.AddNeighbor(s.Point.data());
          }
        }
        const PointCurvature r = estimator.Estimate(settings);
        checks.True("estimate valid", r.Valid);
        const double scale = std::max(std::fabs(x.MaximumCurvature), std::fabs(x.MinimumCurvature));
        worst = std::max(worst, std::fabs(r.MinimumCurvature - x.MinimumCurvature) / scale);
        worst = std::max(worst, std::fabs(r.MaximumCurvature - x.MaximumCurvature) / scale);
        checks.True("max >= min", r.MaximumCurvature >= r.MinimumCurvature);
        checks.Near("d_max . n", testing::Dot(r.MaximumDirection, x.Normal), 0.0, 1e-12);
        checks.Near(
          "d_min . d_max", testing::Dot(r.MaximumDirection, r.MinimumDirection), 0.0, 1e-12);
        if (x.MaximumCurvature - x.MinimumCurvature > 0.2 * scale)
        {
          const double cosine = std::fabs(testing::Dot(r.MaximumDirection, x.MaximumDirection));
          worstAngle = std::max(worstAngle, std::acos(std::min(1.0, cosine)) * 180.0 / testing::Pi);
        }
      }
      char label[96];
      std::snprintf(
        label, sizeof(label), "%s mode %d worst relative error", c.Surface.Name.c_str(), mode);
      std::printf("%s = %.4g\n", label, worst);
      checks.Below(label, worst, 0.05);
      std::snprintf(label,
        sizeof(label),
        "%s mode %d worst direction error (deg)",
        c.Surface.Name.c_str(),
        mode);
      std::printf("%s = %.3g\n", label, worstAngle);
      checks.Below(label, worstAngle, 5.0);
    }
  }
}

void TestDegenerateNeighborhoods(Checks& checks)
{
  PointCurvatureEstimator estimator;
  FitSettings settings;
  estimator.Begin({ { 0, 0, 0 } }, { { 0, 0, 1 } }, 0.1, 1.0);
  checks.True("no neighbors: invalid", !estimator.Estimate(settings).Valid);
  estimator.Begin({ { 0, 0, 0 } }, { { 0, 0, 1 } }, 0.1, 1.0);
  const double same[3] = { 0, 0, 0 };
  estimator.AddNeighbor(same);
  checks.Equal("coincident neighbor ignored", estimator.GetNumberOfNeighbors(), 0);
  // Points on a line: only two directions get points.
  estimator.Begin({ { 0, 0, 0 } }, { { 0, 0, 1 } }, 0.01, 1.0);
  for (int j = -20; j <= 20; ++j)
  {
    const double q[3] = { 0.05 * j, 0.0, 0.0 };
    estimator.AddNeighbor(q);
  }
  const PointCurvature line = estimator.Estimate(settings);
  checks.True("points on a line: invalid", !line.Valid);
  checks.Equal("points on a line: 2 valid directions", line.ValidDirections, 2);
}

/// Translating and scaling the neighborhood must not change the result
/// beyond the unit.
void TestInvariance(Checks& checks)
{
  const auto samples = testing::Sample(testing::Torus(3.0, 1.0), 40000, 11);
  const testing::SurfaceSample& x = samples[123];
  FitSettings settings;
  auto estimate = [&](double scale, double shift)
  {
    PointCurvatureEstimator estimator;
    const testing::Vec point{
      { scale * x.Point[0] + shift, scale * x.Point[1] + shift, scale * x.Point[2] + shift }
    };
    estimator.Begin(point, x.Normal, 0.04 * scale, 0.4 * scale);
    for (const testing::SurfaceSample& s : samples)
    {
      const testing::Vec d = testing::Add(s.Point, testing::Scale(-1.0, x.Point));
      if (testing::Dot(d, d) < 0.16)
      {
        const double q[3] = {
          scale * s.Point[0] + shift, scale * s.Point[1] + shift, scale * s.Point[2] + shift
        };
        estimator.AddNeighbor(q);
      }
    }
    return estimator.Estimate(settings);
  };
  const PointCurvature reference = estimate(1.0, 0.0);
  for (const double scale : { 1e-6, 1e6 })
  {
    const PointCurvature scaled = estimate(scale, 0.0);
    checks.Near("scaled k_max",
      scaled.MaximumCurvature * scale,
      reference.MaximumCurvature,
      1e-9 * std::fabs(reference.MaximumCurvature));
  }
  const PointCurvature shifted = estimate(1.0, 1e6);
  checks.Near("shifted by 1e6 k_max",
    shifted.MaximumCurvature,
    reference.MaximumCurvature,
    1e-4 * std::fabs(reference.MaximumCurvature));
}
} // namespace

/// OrientedCircleAccumulator files each neighbor under its sixteenth of the turn
/// (phi) and its eighth of 2 phi, by comparisons instead of atan2: the
/// same as floor((atan2 + pi) / (2 pi) * 16) and its 2 phi counterpart for
/// directions off the boundaries, in every quadrant.
void TestNeighborSectors(Checks& checks)
{
  const TangentFrame frame = MakeTangentFrame({ { 0.0, 0.0, 1.0 } });
  const double pi = 3.141592653589793;
  testing::Random random(77);
  int wrong = 0;
  for (int i = 0; i < 20000; ++i)
  {
    // Uniform angles, and the sixteenth in the middle of each as well.
    const double phi = i < 16 ? -pi + (i + 0.5) * pi / 8.0 : -pi + 2.0 * pi * random.Uniform();
    const double radius = 0.5 + random.Uniform();
    const double u = radius * std::cos(phi), v = radius * std::sin(phi);
    // The frame's own tangent axes, whatever MakeTangentFrame chose.
    double d[3];
    for (int k = 0; k < 3; ++k)
    {
      d[k] = u * frame.V0[k] + v * frame.W0[k];
    }
    OrientedCircleAccumulator accumulator;
    accumulator.Begin(frame);
    accumulator.Add(d, nullptr);
    const OrientedCircleSums& sums = accumulator.Sums();
    const double angle = std::atan2(v, u);
    const int sector = static_cast<int>(std::floor((angle + pi) / (2.0 * pi) * 16.0));
    const double twice = std::atan2(2.0 * u * v, u * u - v * v);
    const int position = static_cast<int>(std::floor((twice + pi) / (pi / 4.0)));
    const double offBoundary = std::fabs(std::remainder(angle, pi / 8.0));
    if (offBoundary > 1e-9)
    {
      wrong += sums.Sectors != (1u << std::min(sector, 15)) ||
        sums.HalfTurnPositions != (1u << std::min(position, 7));
    }
  }
  checks.Equal("oriented circles: neighbors' sectors as atan2 gives them", wrong, 0);
}

int main(int argc, char* argv[])
{
  return RunNamedTests(argc,
    argv,
    {
      { "TangentFrame", TestTangentFrame },
      { "DirectionMaskMatchesPlaneTest", TestDirectionMaskMatchesPlaneTest },
      { "BinningKernelsAgree", TestBinningKernelsAgree },
      { "CombineKernelsAgree", TestCombineKernelsAgree },
      { "GatherKernelsAgree", TestGatherKernelsAgree },
      { "ShellGatherKernelsAgree", TestShellGatherKernelsAgree },
      { "CircleDistanceKernelsAgree", TestCircleDistanceKernelsAgree },
      { "OrientedSumKernelsAgree", TestOrientedSumKernelsAgree },
      { "OffsetsEqualCoordinates", TestOffsetsEqualCoordinates },
      { "CircleFits", TestCircleFits },
      { "PreviousMatchesEigenSolver", TestPreviousMatchesEigenSolver },
      { "DistanceToCircle", TestDistanceToCircle },
      { "SineFit", TestSineFit },
      { "EstimatorOnSurfaces", TestEstimatorOnSurfaces },
      { "DegenerateNeighborhoods", TestDegenerateNeighborhoods },
      { "Invariance", TestInvariance },
      { "NeighborSectors", TestNeighborSectors },
    });
}
