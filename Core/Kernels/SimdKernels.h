/**
 * @file SimdKernels.h
 * @brief The innermost loops, with SIMD chosen at run time (no VTK): which
 * of the 16 half planes each neighbor of a query point falls into
 * (binning), which points of a run of grid cells lie within the radius
 * or a shell (gather), New02's summed distances to its two circles
 * (circles), and the least-squares sums of OrientedCircles' rows
 * (oriented).
 *
 * Binning is the innermost loop of the method: about 375 neighbors per point,
 * each put into its tangent frame, tested against the half planes and added
 * to its direction's sums. Done one neighbor at a time it cost about 100
 * scalar instructions and 60 % of the filter's time; here the frame
 * coordinates and the tests run on several neighbors at once (2 lanes with
 * SSE2, 4 with AVX2, 8 with AVX-512), and with AVX-512 the sums too (the
 * rare neighbors in several half planes one direction at a time).
 *
 * Every instruction set computes the same IEEE operations in the same order,
 * without fused multiply-adds (the file turns contraction off): results are
 * bit-identical whichever is used (tested). PCURV_KERNEL=generic|avx2|avx512
 * in the environment picks one (to compare them); by default the widest the
 * processor has.
 *
 * The test, for a neighbor at tangent coordinates (tx, ty) and plane
 * distance p: direction i (angle i pi / 8) holds it when t . v_i > 0 and
 * |t . (n x v_i)| < p. Farther than p / sin(pi / 4) from the normal line only
 * the four directions nearest to its angle can hold it, all with
 * t . v_i > 0: those four are tested, in coordinates mirrored into the
 * first quadrant (|tx|, |ty|), which leaves distances to the lines
 * unchanged. Nearer (2 % of the lanes at p = s / 10) all 8 lines are
 * tested, on both sides.
 */
#ifndef SimdKernels_h
#define SimdKernels_h

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pcurv
{
namespace binning
{

/// Neighbors classified per call.
constexpr std::size_t BlockSize = 64;
/// Entries written past a block's end (whole vectors): output arrays need
/// this much room beyond the block.
constexpr std::size_t Padding = 8;

/// The query: its tangent frame, the factor that takes offsets to units of
/// the neighborhood's size, and the plane distance in those units.
struct Frame
{
  double Normal[3];
  double V[3];
  double W[3];
  double InverseScale;
  double PlaneDistance;
};

/// Running sums of each direction, kept per bank: neighbor (slot) k adds
/// into bank k mod 8, so that consecutive neighbors, often in the same
/// direction, do not wait for each other's adds. A record holds, in this
/// order, the sums of h^2, h, h D, D, D^2, the count, and the largest
/// distance along the direction (the extent); record 16 of each bank takes
/// the neighbors that are in no direction (a branch-free dead end). After
/// the eight banks come 16 more records, one per direction, for the rare
/// neighbors in several half planes (or near the normal line), added in
/// slot order.
constexpr int NumberOfBanks = 8;
constexpr int RecordsPerBank = 17;
constexpr int RecordSize = 8;
constexpr int NumberOfDirections = 16;
enum Field : int
{
  SumH2 = 0,
  SumH = 1,
  SumHD = 2,
  SumD = 3,
  SumD2 = 4,
  Count = 5,
  Extent = 6
};
constexpr std::size_t RareRecordsStart =
  static_cast<std::size_t>(NumberOfBanks) * RecordsPerBank * RecordSize;
constexpr std::size_t BankDoubles =
  RareRecordsStart + static_cast<std::size_t>(NumberOfDirections) * RecordSize;

/// cos and sin of direction i's angle, i pi / 8: the one table the
/// classification and the sine fit share.
struct DirectionTable
{
  double Cos[NumberOfDirections];
  double Sin[NumberOfDirections];
};
const DirectionTable& Directions();

/// Adds one neighbor (height h, squared distance d, distance along the
/// direction) to a record; the AVX-512 kernel does the same in one vector.
inline __attribute__((always_inline)) void AddToRecord(double* r, double h, double d, double along)
{
  r[SumH2] += h * h;
  r[SumH] += h;
  r[SumHD] += h * d;
  r[SumD] += d;
  r[SumD2] += d * d;
  r[Count] += 1.0;
  r[Extent] = r[Extent] > along ? r[Extent] : along;
}

/// Adds a rare neighbor to the rare record of each direction it is in
/// (bit i of `directions`), with its distance along that direction.
inline __attribute__((always_inline)) void AddToRareRecords(double* rare,
  const DirectionTable& table,
  double h,
  double d,
  double tx,
  double ty,
  std::uint64_t directions)
{
  for (; directions; directions &= directions - 1)
  {
    const int i = __builtin_ctzll(directions);
    AddToRecord(rare + i * RecordSize, h, d, tx * table.Cos[i] + ty * table.Sin[i]);
  }
}

/// Where a block's results go. Per neighbor, at its slot: coordinates and
/// the directions it is in (bit i: direction i; none for a neighbor at the
/// query point, where the plane tests mean nothing). Every neighbor is
/// added to the sums: those in one half plane to the banks, the rare others
/// to the rare records, direction by direction.
struct Block
{
  double* H = nullptr;  ///< height above the tangent plane
  double* D = nullptr;  ///< squared distance
  double* Tx = nullptr; ///< tangent coordinates
  double* Ty = nullptr;
  std::int64_t* Mask = nullptr; ///< directions of each neighbor
  double* Banks = nullptr;      ///< BankDoubles values
  std::size_t FirstSlot = 0;    ///< slot of the block's first neighbor
  std::size_t AtQueryPoint = 0; ///< neighbors with squared distance 0
};

/// Classifies `count` (at most BlockSize) neighbors given as offsets from
/// the query point (q - x, three arrays of `count` values).
void Classify(const Frame& frame,
  const double* dx,
  const double* dy,
  const double* dz,
  std::size_t count,
  Block& block);

/// Classify with a named kernel (for tests comparing them); false when it
/// is not available.
bool ClassifyWith(const std::string& kernel,
  const Frame& frame,
  const double* dx,
  const double* dy,
  const double* dz,
  std::size_t count,
  Block& block);

/// totals[i * RecordSize + f]: field f of direction i over the eight banks
/// (added in a fixed pairwise order) and then its rare record; the extent
/// is the largest of theirs. The same operations on every instruction set.
void CombineBanks(const double* banks, double* totals);

/// CombineBanks with a named kernel (for tests); false when not available.
bool CombineBanksWith(const std::string& kernel, const double* banks, double* totals);

} // namespace binning

namespace gather
{
/// Extra entries each output array needs beyond the number of candidates:
/// whole vectors are stored.
constexpr std::size_t Padding = 8;

/// The points begin..end - 1 of coordinate arrays x, y, z (one per axis)
/// strictly closer than sqrt(radiusSquared) to `query`: their offsets
/// (x[j] - query[0], ...) appended in order from entry `kept` of dx, dy,
/// dz. Returns the new count. The distance is computed as
/// (dx^2 + dy^2) + dz^2 on every instruction set.
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
  std::size_t kept);

/// WithinRadius with a named kernel (for tests); false when not available.
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
  std::size_t& kept);

/// Candidate points: coordinate arrays and their ids.
struct Candidates
{
  const double* X;
  const double* Y;
  const double* Z;
  const std::int64_t* Ids;
};

/// Where gathered points go: offsets and ids (each with Padding entries of
/// room beyond the last candidate).
struct Output
{
  double* Dx;
  double* Dy;
  double* Dz;
  std::int64_t* Ids;
};

/// A shell about a query point: the squared distances from innerSquared
/// (included) to radiusSquared (excluded).
struct Shell
{
  const double* Query;
  double InnerSquared;
  double RadiusSquared;
};

/// The candidates begin..end - 1 in `shell` (their squared distance
/// computed as in WithinRadius): offsets and ids appended in order from
/// entry `kept` of `out`. Returns the new count.
std::size_t ShellWithin(const Candidates& in,
  std::int64_t begin,
  std::int64_t end,
  const Shell& shell,
  const Output& out,
  std::size_t kept);

/// ShellWithin with a named kernel (for tests); false when not available.
bool ShellWithinWith(const std::string& kernel,
  const Candidates& in,
  std::int64_t begin,
  std::int64_t end,
  const Shell& shell,
  const Output& out,
  std::size_t& kept);
} // namespace gather

namespace circles
{
/// sums[c] = sum over j < count of DistanceToCircle(kappa[c], h[j], d[j]),
/// c = 0, 1 (New02's choice between its two circles), added in eight
/// interleaved partial sums in a fixed order on every instruction set.
void DistanceSums(const double* h,
  const double* d,
  std::size_t count,
  const double kappa[2],
  double sums[2]);

/// DistanceSums with a named kernel (for tests); false when not available.
bool DistanceSumsWith(const std::string& kernel,
  const double* h,
  const double* d,
  std::size_t count,
  const double kappa[2],
  double sums[2]);
} // namespace circles

namespace oriented
{
/// The query point's tangent frame: unit normal and tangent axes.
struct Frame
{
  double Normal[3];
  double V[3];
  double W[3];
};

/// Where each running sum of a fit is, for a fit of the surface's terms up
/// to order 3 or 4 (order 2: the part of either without the cubic and
/// quartic terms, never summed itself). The unknowns of the positions'
/// rows: C, A, B, the two tilts, the four cubic coefficients (of u^3,
/// u^2 v, u v^2, v^3), at order 4 the five quartic ones (u^4, u^3 v,
/// u^2 v^2, u v^3, v^4), and last the query point's height; those of the
/// normals' rows: the same without the height. Entries: upper triangles
/// (row by row) and right-hand sides of both kinds of normal equations, the
/// sums of their weighted squared targets, the neighbors' counts and the
/// sums of their heights (h, h^2: those whose normal opposes the query's,
/// and the others) and of their squared distances D.
template<int Order>
struct Layout
{
  static_assert(Order >= 2 && Order <= 4, "fits of the second to the fourth order");
  static constexpr int PositionUnknowns = Order == 2 ? 6 : Order == 3 ? 10 : 15;
  static constexpr int NormalUnknowns = PositionUnknowns - 1;
  static constexpr int PositionMatrixSize = PositionUnknowns * (PositionUnknowns + 1) / 2;
  static constexpr int NormalMatrixSize = NormalUnknowns * (NormalUnknowns + 1) / 2;
  static constexpr int PositionMatrix = 0;
  static constexpr int PositionRight = PositionMatrix + PositionMatrixSize;
  static constexpr int PositionTargets = PositionRight + PositionUnknowns;
  static constexpr int NormalMatrix = PositionTargets + 1;
  static constexpr int NormalRight = NormalMatrix + NormalMatrixSize;
  static constexpr int NormalTargets = NormalRight + NormalUnknowns;
  static constexpr int Neighbors = NormalTargets + 1;
  static constexpr int NeighborsWithNormal = Neighbors + 1;
  static constexpr int Opposing = Neighbors + 2;
  static constexpr int OpposingHeights = Neighbors + 3;
  static constexpr int AgreeingHeights = Neighbors + 4;
  static constexpr int OpposingSquaredHeights = Neighbors + 5;
  static constexpr int AgreeingSquaredHeights = Neighbors + 6;
  static constexpr int SquaredDistances = Neighbors + 7;
  static constexpr int NumberOfEntries = Neighbors + 8;
};
/// Where the cubic and the quartic terms' columns begin, in both kinds of
/// rows.
constexpr int FirstCubicColumn = 5;
constexpr int FirstQuarticColumn = 9;

/// Every sum is kept in eight banks: the j-th neighbor of a call adds to
/// bank j mod 8, whatever the vector width, so that every instruction set
/// adds the same numbers in the same order (and consecutive neighbors do
/// not wait for each other's adds). Entry e of bank b: Banks[e * 8 + b].
constexpr int NumberOfBanks = 8;
template<int Order>
struct BankedSums
{
  double Banks[Layout<Order>::NumberOfEntries * NumberOfBanks];
  /// Occupied sixteenths of the turn (phi), and eighths of 2 phi.
  std::uint32_t Sectors;
  std::uint32_t HalfTurnPositions;
};
using Sums = BankedSums<3>;
using QuarticSums = BankedSums<4>;

/// Neighbors of a query: their offsets from the query point in the units
/// of the fit (Dx, Dy, Dz) and their unit normals (Nx, Ny, Nz; all three 0:
/// none), Count of each.
struct NeighborBatch
{
  const double* Dx;
  const double* Dy;
  const double* Dz;
  const double* Nx;
  const double* Ny;
  const double* Nz;
  std::size_t Count;
};

/// Adds neighbors to `sums` (zeroed before the first call). A neighbor at
/// the query point is ignored. The rows are those of OrientedCircleFit.h.
void AddNeighbors(const Frame& frame, const NeighborBatch& neighbors, Sums& sums);
void AddNeighbors(const Frame& frame, const NeighborBatch& neighbors, QuarticSums& sums);

/// AddNeighbors with a named kernel (for tests); false when not available.
bool AddNeighborsWith(const std::string& kernel,
  const Frame& frame,
  const NeighborBatch& neighbors,
  Sums& sums);
bool AddNeighborsWith(const std::string& kernel,
  const Frame& frame,
  const NeighborBatch& neighbors,
  QuarticSums& sums);

/// totals[e] for e < entries: entry e's eight banks (banks[e * 8 + b], as
/// in BankedSums) added as ((b0 + b1) + (b2 + b3)) + ((b4 + b5) + (b6 + b7)),
/// the same operations on every instruction set.
void CombineBanks(const double* banks, int entries, double* totals);

/// CombineBanks with a named kernel (for tests); false when not available.
bool CombineBanksWith(const std::string& kernel, const double* banks, int entries, double* totals);
} // namespace oriented

/// The instruction sets this build and this processor can use, widest last
/// ("generic" is always there), and the one the kernels use.
std::vector<std::string> AvailableKernels();
std::string ActiveKernel();

} // namespace pcurv

#endif
