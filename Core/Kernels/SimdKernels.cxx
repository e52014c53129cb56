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
/// The classification of SimdKernels.inc in AVX-512 intrinsics: the same
/// operations in the same order (bit-identical, tested), with comparisons
/// kept in mask registers (the vector extensions turned each into a vector
/// and back, and took twice the time).
inline __attribute__((always_inline)) __m512i AllDirectionsAvx512(__m512d tx, __m512d ty, double p)
{
  static constexpr double Cos[8] = {
    1.0, CosEighthPi, CosQuarterPi, SinEighthPi, 0.0, -SinEighthPi, -CosQuarterPi, -CosEighthPi
  };
  static constexpr double Sin[8] = {
    0.0, SinEighthPi, CosQuarterPi, CosEighthPi, 1.0, CosEighthPi, CosQuarterPi, SinEighthPi
  };
  const __m512d limit = _mm512_set1_pd(p);
  __m512i mask = _mm512_setzero_si512();
  for (int m = 0; m < 8; ++m)
  {
    const __m512d c = _mm512_set1_pd(Cos[m]), s = _mm512_set1_pd(Sin[m]);
    const __mmask8 in = _mm512_cmp_pd_mask(
      _mm512_abs_pd(_mm512_sub_pd(_mm512_mul_pd(ty, c), _mm512_mul_pd(tx, s))), limit, _CMP_LT_OQ);
    const __m512d along = _mm512_add_pd(_mm512_mul_pd(tx, c), _mm512_mul_pd(ty, s));
    const __mmask8 positive = _mm512_cmp_pd_mask(along, _mm512_setzero_pd(), _CMP_GT_OQ);
    const __mmask8 negative = _mm512_cmp_pd_mask(along, _mm512_setzero_pd(), _CMP_LT_OQ);
    mask = _mm512_or_si512(mask,
      _mm512_or_si512(_mm512_maskz_set1_epi64(in & positive, std::int64_t{ 1 } << m),
        _mm512_maskz_set1_epi64(in & negative, std::int64_t{ 1 } << (m + 8))));
  }
  return mask;
}

/// lane[j][f] = field[f][j]: eight vectors of eight transposed in three
/// rounds of two-source permutes.
inline __attribute__((always_inline)) void Transpose(const __m512d field[8], __m512d lane[8])
{
  __m512d a[8], b[8];
  for (int k = 0; k < 4; ++k)
  {
    a[2 * k] = _mm512_unpacklo_pd(field[2 * k], field[2 * k + 1]);
    a[2 * k + 1] = _mm512_unpackhi_pd(field[2 * k], field[2 * k + 1]);
  }
  const __m512i low = _mm512_set_epi64(13, 12, 5, 4, 9, 8, 1, 0);
  const __m512i high = _mm512_set_epi64(15, 14, 7, 6, 11, 10, 3, 2);
  // b[0]: fields 0-3 of lanes 0 and 4; b[1]: of lanes 2 and 6; b[2]: 1
  // and 5; b[3]: 3 and 7; b[4..7] the same for fields 4-7.
  for (int k = 0; k < 2; ++k)
  {
    b[4 * k] = _mm512_permutex2var_pd(a[4 * k], low, a[4 * k + 2]);
    b[4 * k + 1] = _mm512_permutex2var_pd(a[4 * k], high, a[4 * k + 2]);
    b[4 * k + 2] = _mm512_permutex2var_pd(a[4 * k + 1], low, a[4 * k + 3]);
    b[4 * k + 3] = _mm512_permutex2var_pd(a[4 * k + 1], high, a[4 * k + 3]);
  }
  const __m512i first = _mm512_set_epi64(11, 10, 9, 8, 3, 2, 1, 0);
  const __m512i second = _mm512_set_epi64(15, 14, 13, 12, 7, 6, 5, 4);
  static constexpr int LaneOf[4] = { 0, 2, 1, 3 };
  for (int k = 0; k < 4; ++k)
  {
    lane[LaneOf[k]] = _mm512_permutex2var_pd(b[k], first, b[k + 4]);
    lane[LaneOf[k] + 4] = _mm512_permutex2var_pd(b[k], second, b[k + 4]);
  }
}

/// One neighbour's record (h^2, h, h D, D, D^2, 1, along, -) added to a
/// record of sums, the extent by a max: AddToRecord in one vector.
inline __attribute__((always_inline)) void AddLaneToRecord(double* r, __m512d value)
{
  __m512d sums = _mm512_loadu_pd(r);
  sums = _mm512_mask_add_pd(sums, 0x3f, sums, value);
  sums = _mm512_mask_max_pd(sums, 0x40, sums, value);
  _mm512_storeu_pd(r, sums);
}

inline __attribute__((always_inline)) __m512i ClassifyLanesAvx512(const Frame& f,
  const DirectionTable& table,
  const double* dx,
  const double* dy,
  const double* dz,
  std::size_t at,
  Block& block)
{
  const __m512d scale = _mm512_set1_pd(f.InverseScale);
  const __m512d x = _mm512_mul_pd(_mm512_loadu_pd(dx), scale);
  const __m512d y = _mm512_mul_pd(_mm512_loadu_pd(dy), scale);
  const __m512d z = _mm512_mul_pd(_mm512_loadu_pd(dz), scale);
  auto dot = [&](const double* axis)
  {
    return _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(x, _mm512_set1_pd(axis[0])),
                           _mm512_mul_pd(y, _mm512_set1_pd(axis[1]))),
      _mm512_mul_pd(z, _mm512_set1_pd(axis[2])));
  };
  const __m512d h = dot(f.Normal);
  const __m512d tx = dot(f.V);
  const __m512d ty = dot(f.W);
  const __m512d d =
    _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(x, x), _mm512_mul_pd(y, y)), _mm512_mul_pd(z, z));
  _mm512_storeu_pd(block.H + at, h);
  _mm512_storeu_pd(block.D + at, d);
  _mm512_storeu_pd(block.Tx + at, tx);
  _mm512_storeu_pd(block.Ty + at, ty);

  const double p = f.PlaneDistance;
  const __m512d limit = _mm512_set1_pd(p);
  const __mmask8 near = _mm512_cmp_pd_mask(
    _mm512_mul_pd(_mm512_add_pd(_mm512_mul_pd(tx, tx), _mm512_mul_pd(ty, ty)), _mm512_set1_pd(0.5)),
    _mm512_set1_pd(p * p),
    _CMP_LT_OQ);
  const __m512d ax = _mm512_abs_pd(tx);
  const __m512d ay = _mm512_abs_pd(ty);
  const __m512d tan = _mm512_set1_pd(TanEighthPi);
  const __mmask8 c1 = _mm512_cmp_pd_mask(ay, _mm512_mul_pd(tan, ax), _CMP_GE_OQ);
  const __mmask8 c2 = _mm512_cmp_pd_mask(ay, ax, _CMP_GE_OQ);
  const __mmask8 c3 = _mm512_cmp_pd_mask(_mm512_mul_pd(tan, ay), ax, _CMP_GT_OQ);
  const __m512i one = _mm512_set1_epi64(1);
  const __m512i slice = _mm512_add_epi64(
    _mm512_add_epi64(_mm512_maskz_mov_epi64(c1, one), _mm512_maskz_mov_epi64(c2, one)),
    _mm512_maskz_mov_epi64(c3, one));
  auto pick = [&](double v0, double v1, double v2, double v3)
  {
    __m512d v = _mm512_mask_blend_pd(c1, _mm512_set1_pd(v0), _mm512_set1_pd(v1));
    v = _mm512_mask_blend_pd(c2, v, _mm512_set1_pd(v2));
    return _mm512_mask_blend_pd(c3, v, _mm512_set1_pd(v3));
  };
  const __m512d cosine = pick(1.0, CosEighthPi, CosQuarterPi, SinEighthPi);
  const __m512d sine = pick(0.0, SinEighthPi, CosQuarterPi, CosEighthPi);
  const __m512d u = _mm512_add_pd(_mm512_mul_pd(ax, cosine), _mm512_mul_pd(ay, sine));
  const __m512d w = _mm512_sub_pd(_mm512_mul_pd(ay, cosine), _mm512_mul_pd(ax, sine));
  const __m512d wc = _mm512_mul_pd(w, _mm512_set1_pd(CosEighthPi));
  const __m512d us = _mm512_mul_pd(u, _mm512_set1_pd(SinEighthPi));
  auto inside = [&](__m512d across)
  { return _mm512_cmp_pd_mask(_mm512_abs_pd(across), limit, _CMP_LT_OQ); };
  const __mmask8 in0 = inside(_mm512_add_pd(wc, us));
  const __mmask8 in1 = inside(w);
  const __mmask8 in2 = inside(_mm512_sub_pd(wc, us));
  const __mmask8 in3 = inside(_mm512_mul_pd(_mm512_sub_pd(w, u), _mm512_set1_pd(CosQuarterPi)));
  const __mmask8 any = in0 | in1 | in2 | in3;
  const __mmask8 several = (in0 & (in1 | in2 | in3)) | (in1 & (in2 | in3)) | (in2 & in3);
  const __mmask8 single = any & ~several;

  const __mmask8 negativeX = _mm512_cmp_pd_mask(tx, _mm512_setzero_pd(), _CMP_LT_OQ);
  const __mmask8 negativeY = _mm512_cmp_pd_mask(ty, _mm512_setzero_pd(), _CMP_LT_OQ);
  const __m512i base = _mm512_add_epi64(
    _mm512_maskz_set1_epi64(negativeX, 8), _mm512_maskz_set1_epi64(negativeY & ~negativeX, 16));
  const __mmask8 flip = negativeX ^ negativeY;
  const __m512i fifteen = _mm512_set1_epi64(15);
  auto line = [&](std::int64_t offset)
  {
    const __m512i k = _mm512_add_epi64(slice, _mm512_set1_epi64(offset));
    const __m512i signedK = _mm512_mask_sub_epi64(k, flip, _mm512_setzero_si512(), k);
    return _mm512_and_si512(_mm512_add_epi64(base, signedK), fifteen);
  };
  const __m512i line0 = line(-1), line1 = line(0), line2 = line(1), line3 = line(2);
  const __m512i list = _mm512_or_si512(
    _mm512_or_si512(_mm512_maskz_mov_epi64(in0, line0), _mm512_maskz_mov_epi64(in1, line1)),
    _mm512_or_si512(_mm512_maskz_mov_epi64(in2, line2), _mm512_maskz_mov_epi64(in3, line3)));
  const __m512d c8 = _mm512_set1_pd(CosEighthPi), s8 = _mm512_set1_pd(SinEighthPi);
  const __m512d along0 = _mm512_sub_pd(_mm512_mul_pd(u, c8), _mm512_mul_pd(w, s8));
  const __m512d along2 = _mm512_add_pd(_mm512_mul_pd(u, c8), _mm512_mul_pd(w, s8));
  const __m512d along3 = _mm512_mul_pd(_mm512_add_pd(u, w), _mm512_set1_pd(CosQuarterPi));
  // in0 ? along0 : in1 ? u : in2 ? along2 : along3
  __m512d along = _mm512_mask_blend_pd(in2, along3, along2);
  along = _mm512_mask_blend_pd(in1, along, u);
  along = _mm512_mask_blend_pd(in0, along, along0);
  const __mmask8 keep = single & ~near;
  const __m512i record = _mm512_mask_mov_epi64(_mm512_set1_epi64(RecordsPerBank - 1), keep, list);

  __m512i mask = _mm512_or_si512(_mm512_or_si512(_mm512_maskz_sllv_epi64(in0, one, line0),
                                   _mm512_maskz_sllv_epi64(in1, one, line1)),
    _mm512_or_si512(
      _mm512_maskz_sllv_epi64(in2, one, line2), _mm512_maskz_sllv_epi64(in3, one, line3)));
  if (near)
  {
    mask = _mm512_mask_mov_epi64(mask, near, AllDirectionsAvx512(tx, ty, p));
  }
  const __mmask8 atQueryPoint = _mm512_cmp_pd_mask(d, _mm512_setzero_pd(), _CMP_EQ_OQ);
  const __mmask8 rare = (near | several) & ~atQueryPoint;
  _mm512_storeu_si512(block.Mask + at, _mm512_maskz_mov_epi64(rare | keep, mask));

  // The single-plane lanes into their banks: the eight records (h^2, h,
  // h D, D, D^2, 1, along, -) transposed to one vector per lane, each added
  // to its bank's record with one vector add (and a max for the extent).
  __m512d field[8] = { _mm512_mul_pd(h, h),
    h,
    _mm512_mul_pd(h, d),
    d,
    _mm512_mul_pd(d, d),
    _mm512_set1_pd(1.0),
    along,
    _mm512_setzero_pd() };
  __m512d lane[8];
  Transpose(field, lane);
  alignas(64) std::int64_t records[8];
  _mm512_store_si512(records, record);
  for (int j = 0; j < 8; ++j)
  {
    const std::size_t bank = (block.FirstSlot + at + j) % NumberOfBanks;
    AddLaneToRecord(block.Banks + (bank * RecordsPerBank + records[j]) * RecordSize, lane[j]);
  }
  // The rare lanes, direction by direction, with the distance along each.
  for (unsigned rest = rare; rest; rest &= rest - 1)
  {
    const int j = __builtin_ctz(rest);
    const double tx = block.Tx[at + j], ty = block.Ty[at + j];
    for (std::uint64_t directions = static_cast<std::uint64_t>(block.Mask[at + j]); directions;
         directions &= directions - 1)
    {
      const int i = __builtin_ctzll(directions);
      const double along = tx * table.Cos[i] + ty * table.Sin[i];
      AddLaneToRecord(block.Banks + RareRecordsStart + i * RecordSize,
        _mm512_mask_mov_pd(lane[j], 0x40, _mm512_set1_pd(along)));
    }
  }
  return _mm512_maskz_mov_epi64(atQueryPoint, one);
}
#define PCURV_CLASSIFY_LANES ClassifyLanesAvx512

#define PCURV_LANES 8
#include "SimdKernels.inc"
#undef PCURV_LANES

/// Eight candidates at a time: the points inside are packed to the front
/// of each vector (compress) and stored whole, the count advancing by
/// their number. The same operations as GatherScalar.
std::size_t Gather(const double* x,
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
  const __m512d qx = _mm512_set1_pd(query[0]);
  const __m512d qy = _mm512_set1_pd(query[1]);
  const __m512d qz = _mm512_set1_pd(query[2]);
  const __m512d limit = _mm512_set1_pd(radiusSquared);
  for (std::int64_t j = begin; j < end; j += 8)
  {
    const __mmask8 valid =
      end - j >= 8 ? __mmask8(0xff) : static_cast<__mmask8>((1u << (end - j)) - 1u);
    const __m512d ox = _mm512_sub_pd(_mm512_maskz_loadu_pd(valid, x + j), qx);
    const __m512d oy = _mm512_sub_pd(_mm512_maskz_loadu_pd(valid, y + j), qy);
    const __m512d oz = _mm512_sub_pd(_mm512_maskz_loadu_pd(valid, z + j), qz);
    const __m512d squared = _mm512_add_pd(
      _mm512_add_pd(_mm512_mul_pd(ox, ox), _mm512_mul_pd(oy, oy)), _mm512_mul_pd(oz, oz));
    const __mmask8 inside = _mm512_mask_cmp_pd_mask(valid, squared, limit, _CMP_LT_OQ);
    _mm512_storeu_pd(dx + kept, _mm512_maskz_compress_pd(inside, ox));
    _mm512_storeu_pd(dy + kept, _mm512_maskz_compress_pd(inside, oy));
    _mm512_storeu_pd(dz + kept, _mm512_maskz_compress_pd(inside, oz));
    kept += static_cast<std::size_t>(__builtin_popcount(inside));
  }
  return kept;
}

/// The shell's gather eight candidates at a time, ids packed with the
/// offsets. The same operations as GatherShellScalar.
std::size_t GatherShell(const gather::Candidates& in,
  std::int64_t begin,
  std::int64_t end,
  const gather::Shell& shell,
  const gather::Output& out,
  std::size_t kept)
{
  const __m512d qx = _mm512_set1_pd(shell.Query[0]);
  const __m512d qy = _mm512_set1_pd(shell.Query[1]);
  const __m512d qz = _mm512_set1_pd(shell.Query[2]);
  const __m512d lower = _mm512_set1_pd(shell.InnerSquared);
  const __m512d limit = _mm512_set1_pd(shell.RadiusSquared);
  for (std::int64_t j = begin; j < end; j += 8)
  {
    const __mmask8 valid =
      end - j >= 8 ? __mmask8(0xff) : static_cast<__mmask8>((1u << (end - j)) - 1u);
    const __m512d ox = _mm512_sub_pd(_mm512_maskz_loadu_pd(valid, in.X + j), qx);
    const __m512d oy = _mm512_sub_pd(_mm512_maskz_loadu_pd(valid, in.Y + j), qy);
    const __m512d oz = _mm512_sub_pd(_mm512_maskz_loadu_pd(valid, in.Z + j), qz);
    const __m512d squared = _mm512_add_pd(
      _mm512_add_pd(_mm512_mul_pd(ox, ox), _mm512_mul_pd(oy, oy)), _mm512_mul_pd(oz, oz));
    const __mmask8 inside = _mm512_mask_cmp_pd_mask(valid, squared, lower, _CMP_GE_OQ) &
      _mm512_cmp_pd_mask(squared, limit, _CMP_LT_OQ);
    _mm512_storeu_pd(out.Dx + kept, _mm512_maskz_compress_pd(inside, ox));
    _mm512_storeu_pd(out.Dy + kept, _mm512_maskz_compress_pd(inside, oy));
    _mm512_storeu_pd(out.Dz + kept, _mm512_maskz_compress_pd(inside, oz));
    _mm512_storeu_si512(out.Ids + kept,
      _mm512_maskz_compress_epi64(inside, _mm512_maskz_loadu_epi64(valid, in.Ids + j)));
    kept += static_cast<std::size_t>(__builtin_popcount(inside));
  }
  return kept;
}
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
