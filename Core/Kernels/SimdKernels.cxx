#include "Kernels/SimdKernels.h"

// No fused multiply-adds: with them (AVX-512 implies FMA) the kernels would
// round differently from each other and from processors without FMA.
#if defined(__clang__)
#pragma clang fp contract(off)
#elif defined(__GNUC__)
#pragma GCC optimize("fp-contract=off")
#endif

#include <cmath>
#include <cstdlib>
#include <cstring>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
// Wider kernels where GCC can target them per function and the processor
// is checked at run time; other compilers and processors use the generic
// ones (the same results).
#define PCURV_MULTIVERSION 1
#include <immintrin.h>
#endif

namespace pcurv
{
namespace
{
constexpr double TanEighthPi = 0.41421356237309503;  // tan(pi / 8)
constexpr double CosEighthPi = 0.92387953251128674;  // cos(pi / 8) = sin(3 pi / 8)
constexpr double SinEighthPi = 0.38268343236508978;  // sin(pi / 8) = cos(3 pi / 8)
constexpr double CosQuarterPi = 0.70710678118654757; // cos(pi / 4) = sin(pi / 4)

using namespace binning;
using ClassifyKernel =
  void (*)(const Frame&, const double*, const double*, const double*, std::size_t, Block&);
using CombineKernel = void (*)(const double*, double*);
using OrientedCombineKernel = void (*)(const double*, int, double*);
using CircleKernel = void (*)(const double*, const double*, std::size_t, const double*, double*);
using OrientedKernel = void (*)(const oriented::Frame&,
  const oriented::NeighborBatch&,
  oriented::Sums&);
using QuarticKernel = void (*)(const oriented::Frame&,
  const oriented::NeighborBatch&,
  oriented::QuarticSums&);
using GatherKernel = std::size_t (*)(const double*,
  const double*,
  const double*,
  std::int64_t,
  std::int64_t,
  const double*,
  double,
  double*,
  double*,
  double*,
  std::size_t);

/// The gather, one candidate at a time: branch-free (about half the
/// candidates are rejected, too randomly for branch prediction), a
/// rejected candidate's offsets are overwritten by the next one.
std::size_t GatherScalar(const double* x,
  const double* y,
  const double* z,
  std::int64_t begin,
  std::int64_t end,
  const double* query,
  double radiusSquared,
  double* dx,
  double* dy,
  double* dz,
  std::size_t kept)
{
  for (std::int64_t j = begin; j < end; ++j)
  {
    const double ox = x[j] - query[0], oy = y[j] - query[1], oz = z[j] - query[2];
    dx[kept] = ox;
    dy[kept] = oy;
    dz[kept] = oz;
    kept += (ox * ox + oy * oy + oz * oz < radiusSquared) ? 1 : 0;
  }
  return kept;
}

namespace generic
{
#define PCURV_LANES 2
#include "SimdKernels.inc"
#undef PCURV_LANES
#undef PCURV_CLASSIFY_LANES
} // namespace generic

#ifdef PCURV_MULTIVERSION
#pragma GCC push_options
#pragma GCC target("avx2")
namespace avx2
{
#define PCURV_LANES 4
#include "SimdKernels.inc"
#undef PCURV_LANES
#undef PCURV_CLASSIFY_LANES
} // namespace avx2
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx512f,avx512dq,avx512vl,avx512bw")
namespace avx512
{
#include "Avx512Kernels.inc"
} // namespace avx512
#pragma GCC pop_options
#endif

using ShellKernel = std::size_t (*)(const gather::Candidates&,
  std::int64_t,
  std::int64_t,
  const gather::Shell&,
  const gather::Output&,
  std::size_t);

/// The shell's gather one candidate at a time, branch-free as GatherScalar.
std::size_t GatherShellScalar(const gather::Candidates& in,
  std::int64_t begin,
  std::int64_t end,
  const gather::Shell& shell,
  const gather::Output& out,
  std::size_t kept)
{
  const double* query = shell.Query;
  for (std::int64_t j = begin; j < end; ++j)
  {
    const double ox = in.X[j] - query[0], oy = in.Y[j] - query[1], oz = in.Z[j] - query[2];
    const double squared = ox * ox + oy * oy + oz * oz;
    out.Dx[kept] = ox;
    out.Dy[kept] = oy;
    out.Dz[kept] = oz;
    out.Ids[kept] = in.Ids[j];
    kept += (squared >= shell.InnerSquared) & (squared < shell.RadiusSquared);
  }
  return kept;
}

struct NamedKernel
{
  const char* Name;
  ClassifyKernel Classify;
  CombineKernel Combine;
  GatherKernel Gather;
  ShellKernel Shell;
  CircleKernel Circles;
  OrientedKernel Oriented;
  QuarticKernel Quartic;
  OrientedCombineKernel OrientedCombine;
};

std::vector<NamedKernel> Kernels()
{
  std::vector<NamedKernel> kernels{ { "generic",
    &generic::ClassifyBlock,
    &generic::CombineBanks,
    &GatherScalar,
    &GatherShellScalar,
    &generic::CircleDistanceSums,
    &generic::AddOrientedNeighbors<3>,
    &generic::AddOrientedNeighbors<4>,
    &generic::CombineOrientedBanks } };
#ifdef PCURV_MULTIVERSION
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx2"))
  {
    kernels.push_back({ "avx2",
      &avx2::ClassifyBlock,
      &avx2::CombineBanks,
      &GatherScalar,
      &GatherShellScalar,
      &avx2::CircleDistanceSums,
      &avx2::AddOrientedNeighbors<3>,
      &avx2::AddOrientedNeighbors<4>,
      &avx2::CombineOrientedBanks });
  }
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
    __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512bw"))
  {
    kernels.push_back({ "avx512",
      &avx512::ClassifyBlock,
      &avx512::CombineBanks,
      &avx512::Gather,
      &avx512::GatherShell,
      &avx512::CircleDistanceSums,
      &avx512::AddOrientedNeighbors<3>,
      &avx512::AddOrientedNeighbors<4>,
      &avx512::CombineOrientedBanks });
  }
#endif
  return kernels;
}

/// The widest kernel, unless PCURV_KERNEL names another available one.
NamedKernel ChooseKernel()
{
  const std::vector<NamedKernel> kernels = Kernels();
  if (const char* wanted = std::getenv("PCURV_KERNEL"))
  {
    for (const NamedKernel& kernel : kernels)
    {
      if (std::strcmp(kernel.Name, wanted) == 0)
      {
        return kernel;
      }
    }
  }
  return kernels.back();
}

const NamedKernel& Best()
{
  static const NamedKernel best = ChooseKernel();
  return best;
}

const NamedKernel* Named(const std::string& name)
{
  static const std::vector<NamedKernel> kernels = Kernels();
  for (const NamedKernel& kernel : kernels)
  {
    if (name == kernel.Name)
    {
      return &kernel;
    }
  }
  return nullptr;
}
} // namespace

namespace binning
{
const DirectionTable& Directions()
{
  static const DirectionTable table = []
  {
    constexpr double Pi = 3.14159265358979323846;
    constexpr double DirectionStep = Pi / 8.0;
    DirectionTable t;
    for (int i = 0; i < NumberOfDirections; ++i)
    {
      t.Cos[i] = std::cos(i * DirectionStep);
      t.Sin[i] = std::sin(i * DirectionStep);
    }
    return t;
  }();
  return table;
}

void CombineBanks(const double* banks, double* totals)
{
  Best().Combine(banks, totals);
}

bool CombineBanksWith(const std::string& kernel, const double* banks, double* totals)
{
  const NamedKernel* named = Named(kernel);
  if (named)
  {
    named->Combine(banks, totals);
  }
  return named != nullptr;
}

void Classify(const Frame& frame,
  const double* dx,
  const double* dy,
  const double* dz,
  std::size_t count,
  Block& block)
{
  Best().Classify(frame, dx, dy, dz, count, block);
}

bool ClassifyWith(const std::string& kernel,
  const Frame& frame,
  const double* dx,
  const double* dy,
  const double* dz,
  std::size_t count,
  Block& block)
{
  const NamedKernel* named = Named(kernel);
  if (named)
  {
    named->Classify(frame, dx, dy, dz, count, block);
  }
  return named != nullptr;
}
} // namespace binning

namespace gather
{
std::size_t WithinRadius(const double* x,
  const double* y,
  const double* z,
  std::int64_t begin,
  std::int64_t end,
  const double query[3],
  double radiusSquared,
  double* dx,
  double* dy,
  double* dz,
  std::size_t kept)
{
  return Best().Gather(x, y, z, begin, end, query, radiusSquared, dx, dy, dz, kept);
}

bool WithinRadiusWith(const std::string& kernel,
  const double* x,
  const double* y,
  const double* z,
  std::int64_t begin,
  std::int64_t end,
  const double query[3],
  double radiusSquared,
  double* dx,
  double* dy,
  double* dz,
  std::size_t& kept)
{
  const NamedKernel* named = Named(kernel);
  if (named)
  {
    kept = named->Gather(x, y, z, begin, end, query, radiusSquared, dx, dy, dz, kept);
  }
  return named != nullptr;
}

std::size_t ShellWithin(const Candidates& in,
  std::int64_t begin,
  std::int64_t end,
  const Shell& shell,
  const Output& out,
  std::size_t kept)
{
  return Best().Shell(in, begin, end, shell, out, kept);
}

bool ShellWithinWith(const std::string& kernel,
  const Candidates& in,
  std::int64_t begin,
  std::int64_t end,
  const Shell& shell,
  const Output& out,
  std::size_t& kept)
{
  const NamedKernel* named = Named(kernel);
  if (named)
  {
    kept = named->Shell(in, begin, end, shell, out, kept);
  }
  return named != nullptr;
}
} // namespace gather

namespace circles
{
void DistanceSums(const double* h,
  const double* d,
  std::size_t count,
  const double kappa[2],
  double sums[2])
{
  Best().Circles(h, d, count, kappa, sums);
}

bool DistanceSumsWith(const std::string& kernel,
  const double* h,
  const double* d,
  std::size_t count,
  const double kappa[2],
  double sums[2])
{
  const NamedKernel* named = Named(kernel);
  if (named)
  {
    named->Circles(h, d, count, kappa, sums);
  }
  return named != nullptr;
}
} // namespace circles

namespace oriented
{
void AddNeighbors(const Frame& frame, const NeighborBatch& neighbors, Sums& sums)
{
  Best().Oriented(frame, neighbors, sums);
}

void AddNeighbors(const Frame& frame, const NeighborBatch& neighbors, QuarticSums& sums)
{
  Best().Quartic(frame, neighbors, sums);
}

bool AddNeighborsWith(const std::string& kernel,
  const Frame& frame,
  const NeighborBatch& neighbors,
  Sums& sums)
{
  const NamedKernel* named = Named(kernel);
  if (named)
  {
    named->Oriented(frame, neighbors, sums);
  }
  return named != nullptr;
}

bool AddNeighborsWith(const std::string& kernel,
  const Frame& frame,
  const NeighborBatch& neighbors,
  QuarticSums& sums)
{
  const NamedKernel* named = Named(kernel);
  if (named)
  {
    named->Quartic(frame, neighbors, sums);
  }
  return named != nullptr;
}

void CombineBanks(const double* banks, int entries, double* totals)
{
  Best().OrientedCombine(banks, entries, totals);
}

bool CombineBanksWith(const std::string& kernel, const double* banks, int entries, double* totals)
{
  const NamedKernel* named = Named(kernel);
  if (named)
  {
    named->OrientedCombine(banks, entries, totals);
  }
  return named != nullptr;
}
} // namespace oriented

std::vector<std::string> AvailableKernels()
{
  std::vector<std::string> names;
  for (const NamedKernel& kernel : Kernels())
  {
    names.emplace_back(kernel.Name);
  }
  return names;
}

std::string ActiveKernel()
{
  return Best().Name;
}

} // namespace pcurv
