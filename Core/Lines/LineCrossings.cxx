#include "Lines/LineCrossings.h"

#include <algorithm>
#include <cmath>

namespace pcurv
{
namespace
{
using Vec3 = std::array<double, 3>;

double Dot(const Vec3& a, const Vec3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// The kind of an extremum of k_max (ofMaximum) or k_min whose bend
/// (second derivative along its direction) is `bend`, where the
/// curvatures are kMax and kMin.
LineKind KindOf(bool ofMaximum, double bend, double kMax, double kMin)
{
  if (ofMaximum)
  {
    if (bend > 0.0)
    {
      return LineKind::MinimumOfMaximum;
    }
    return kMax > std::fabs(kMin) ? LineKind::Ridge : LineKind::MaximumOfMaximum;
  }
  if (bend < 0.0)
  {
    return LineKind::MaximumOfMinimum;
  }
  return kMin < -std::fabs(kMax) ? LineKind::Valley : LineKind::MinimumOfMinimum;
}

class EdgeCrossings
{
public:
  EdgeCrossings(const LineInput& input,
    const LineSettings& settings,
    std::vector<LineCrossing>& out)
    : Input(input)
    , Settings(settings)
    , Out(out)
  {
  }

  /// The crossing of one curvature's derivative on the edge p-q, if any.
  void Cross(std::int64_t p,
    std::int64_t q,
    const Extremality& a,
    const Extremality& b,
    bool ofMaximum)
  {
    if (!a.Significant || !b.Significant || (a.Bend > 0.0) != (b.Bend > 0.0))
    {
      return;
    }
    // Directions are defined up to sign, and the derivative along one
    // flips with it: compare both along p's direction.
    const double aligned = Dot(a.Direction, b.Direction) >= 0.0 ? 1.0 : -1.0;
    const double ea = a.Slope, eb = aligned * b.Slope;
    if (!(ea * eb < 0.0))
    {
      return;
    }
    Vec3 edge;
    for (int k = 0; k < 3; ++k)
    {
      edge[k] = this->Input.Points[3 * q + k] - this->Input.Points[3 * p + k];
    }
    // Through a maximum the derivative falls along the direction: a sign
    // change the other way round is noise, not this extremum. The change
    // across the edge, not the fits' second derivatives, decides whether
    // the extremum is significant: a fit over the tangent plane also sees
    // the curvature change across a curved line of curvature (a torus's
    // parallels), where it is constant along the line itself.
    const double along = 0.5 * (Dot(edge, a.Direction) + aligned * Dot(edge, b.Direction));
    const double bendAcross = (eb - ea) / along;
    const double slopeError = std::sqrt(a.SlopeError * a.SlopeError + b.SlopeError * b.SlopeError);
    if (!(bendAcross * a.Bend > 0.0) ||
      !(std::fabs(eb - ea) > this->Settings.Significance * slopeError) ||
      !(std::fabs(bendAcross) >= std::max(a.BendFloor, b.BendFloor)))
    {
      return;
    }
    const double t = ea / (ea - eb);
    const double kMax =
      (1.0 - t) * this->Input.MaximumCurvature[p] + t * this->Input.MaximumCurvature[q];
    const double kMin =
      (1.0 - t) * this->Input.MinimumCurvature[p] + t * this->Input.MinimumCurvature[q];
    const double bend = (1.0 - t) * a.Bend + t * b.Bend;
    const LineKind kind = KindOf(ofMaximum, bend, kMax, kMin);
    if (!(this->Settings.Kinds & KindBit(kind)))
    {
      return;
    }
    LineCrossing c;
    const double tangentSign = Dot(a.Tangent, b.Tangent) >= 0.0 ? 1.0 : -1.0;
    double norm = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      c.Position[k] = this->Input.Points[3 * p + k] + t * edge[k];
      c.Tangent[k] = a.Tangent[k] + tangentSign * b.Tangent[k];
      norm += c.Tangent[k] * c.Tangent[k];
    }
    norm = std::sqrt(norm);
    for (int k = 0; k < 3; ++k)
    {
      c.Tangent[k] = norm > 0.0 ? c.Tangent[k] / norm : a.Tangent[k];
    }
    c.Curvature = ofMaximum ? kMax : kMin;
    c.EdgeLength = std::sqrt(Dot(edge, edge));
    c.Kind = kind;
    this->Out.push_back(c);
  }

private:
  const LineInput& Input;
  const LineSettings& Settings;
  std::vector<LineCrossing>& Out;
};

/// Whether `p` is among the graph neighbors of `q`.
bool InRow(const PointDerivatives& d, std::int64_t q, std::int64_t p)
{
  const std::int64_t* row = &d.Graph[q * d.GraphWidth];
  for (int k = 0; k < d.GraphWidth; ++k)
  {
    if (row[k] == p)
    {
      return true;
    }
  }
  return false;
}

} // namespace

std::vector<LineCrossing> FindCrossings(const LineInput& input,
  const LineSettings& settings,
  const PointDerivatives& derivatives,
  const std::int64_t* order,
  WorkRunner* runner)
{
  const bool maxima = settings.Kinds &
    (KindBit(LineKind::Ridge) | KindBit(LineKind::MaximumOfMaximum) |
      KindBit(LineKind::MinimumOfMaximum));
  const bool minima = settings.Kinds &
    (KindBit(LineKind::Valley) | KindBit(LineKind::MinimumOfMinimum) |
      KindBit(LineKind::MaximumOfMinimum));
  // Fixed blocks of the order, each with its own list, joined in order:
  // the same crossings in the same order on any number of threads.
  constexpr std::int64_t Block = 4096;
  const std::int64_t blocks = (input.Count + Block - 1) / Block;
  std::vector<std::vector<LineCrossing>> found(static_cast<std::size_t>(blocks));
  RunRanges(runner,
    blocks,
    1,
    [&](std::int64_t firstBlock, std::int64_t endBlock)
    {
      for (std::int64_t b = firstBlock; b < endBlock; ++b)
      {
        EdgeCrossings edges(input, settings, found[b]);
        for (std::int64_t j = b * Block; j < std::min(input.Count, (b + 1) * Block); ++j)
        {
          const std::int64_t p = order[j];
          if (!derivatives.Fitted[p] || (input.Owned && !input.Owned[p]))
          {
            continue;
          }
          const std::int64_t* row = &derivatives.Graph[p * derivatives.GraphWidth];
          for (int k = 0; k < derivatives.GraphWidth; ++k)
          {
            const std::int64_t q = row[k];
            // Each undirected edge once: from its lower end when both
            // list it.
            if (q < 0 || !derivatives.Fitted[q] || (q < p && InRow(derivatives, q, p)))
            {
              continue;
            }
            if (maxima)
            {
              edges.Cross(p, q, derivatives.Maximum[p], derivatives.Maximum[q], true);
            }
            if (minima)
            {
              edges.Cross(p, q, derivatives.Minimum[p], derivatives.Minimum[q], false);
            }
          }
        }
      }
    });
  std::vector<LineCrossing> crossings;
  for (const std::vector<LineCrossing>& block : found)
  {
    crossings.insert(crossings.end(), block.begin(), block.end());
  }
  return crossings;
}

} // namespace pcurv
