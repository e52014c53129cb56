#include "HalfPlaneBinning.h"

// No fused multiply-adds: with them (AVX-512 implies FMA) the kernels would
// round differently from each other and from processors without FMA.
#if defined(__clang__)
#pragma clang fp contract(off)
#elif defined(__GNUC__)
#pragma GCC optimize("fp-contract=off")
#endif

#include <cstdlib>
#include <cstring>

namespace pcurv
{
namespace binning
{
namespace
{
constexpr double TanEighthPi = 0.41421356237309503;        // tan(pi / 8)
constexpr double SinEighthPiSquared = 0.14644660940672624; // sin^2(pi / 8)
constexpr double CosEighthPi = 0.92387953251128674;        // cos(pi / 8) = sin(3 pi / 8)
constexpr double SinEighthPi = 0.38268343236508978;        // sin(pi / 8) = cos(3 pi / 8)
constexpr double CosQuarterPi = 0.70710678118654757;       // cos(pi / 4) = sin(pi / 4)

using Kernel =
  void (*)(const Frame&, const double*, const double*, const double*, std::size_t, Block&);

namespace generic
{
#define PCURV_LANES 2
#include "HalfPlaneKernel.inc"
#undef PCURV_LANES
} // namespace generic

// Wider kernels where GCC can target them per function and the processor
// is checked at run time; other compilers and processors use the generic
// one (the same results).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define PCURV_MULTIVERSION 1
#pragma GCC push_options
#pragma GCC target("avx2")
namespace avx2
{
#define PCURV_LANES 4
#include "HalfPlaneKernel.inc"
#undef PCURV_LANES
} // namespace avx2
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx512f,avx512dq,avx512vl,avx512bw")
namespace avx512
{
#define PCURV_LANES 8
#include "HalfPlaneKernel.inc"
#undef PCURV_LANES
} // namespace avx512
#pragma GCC pop_options
#endif

struct NamedKernel
{
  const char* Name;
  Kernel Function;
};

std::vector<NamedKernel> Kernels()
{
  std::vector<NamedKernel> kernels{ { "generic", &generic::ClassifyBlock } };
#ifdef PCURV_MULTIVERSION
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx2"))
  {
    kernels.push_back({ "avx2", &avx2::ClassifyBlock });
  }
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
    __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512bw"))
  {
    kernels.push_back({ "avx512", &avx512::ClassifyBlock });
  }
#endif
  return kernels;
}

/// The widest kernel, unless PCURV_KERNEL names another available one
/// (to compare them; all give the same results).
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
} // namespace

void Classify(const Frame& frame,
  const double* dx,
  const double* dy,
  const double* dz,
  std::size_t count,
  Block& block)
{
  Best().Function(frame, dx, dy, dz, count, block);
}

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

bool ClassifyWith(const std::string& kernel,
  const Frame& frame,
  const double* dx,
  const double* dy,
  const double* dz,
  std::size_t count,
  Block& block)
{
  for (const NamedKernel& candidate : Kernels())
  {
    if (kernel == candidate.Name)
    {
      candidate.Function(frame, dx, dy, dz, count, block);
      return true;
    }
  }
  return false;
}

} // namespace binning
} // namespace pcurv
