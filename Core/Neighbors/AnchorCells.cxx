#include "Neighbors/AnchorCells.h"

#include <cmath>
#include <unordered_set>

namespace pcurv
{

std::size_t AnchorCells::CellHash::operator()(const CellKey& key) const
{
  std::uint64_t h = static_cast<std::uint64_t>(key.I) * 0x9E3779B97F4A7C15ull;
  h ^= static_cast<std::uint64_t>(key.J) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
  h ^= static_cast<std::uint64_t>(key.K) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
  return static_cast<std::size_t>(h);
}

void AnchorCells::Begin(const double origin[3],
  double cellSide,
  const double* coordinates,
  const double* normals)
{
  std::copy_n(origin, 3, this->Origin);
  this->CellSide = cellSide;
  this->Coordinates = coordinates;
  this->Normals = normals;
  this->Anchors.clear();
}

AnchorCells::CellKey AnchorCells::KeyOf(const double x[3]) const
{
  constexpr double Limit = 9.0e18; // below 2^63
  std::int64_t index[3];
  for (int k = 0; k < 3; ++k)
  {
    const double cells = std::floor((x[k] - this->Origin[k]) / this->CellSide);
    index[k] =
      cells == cells ? static_cast<std::int64_t>(std::min(std::max(cells, -Limit), Limit)) : 0;
  }
  return CellKey{ index[0], index[1], index[2] };
}

bool AnchorCells::Precedes(std::int64_t a, std::int64_t b, const CellKey& cell) const
{
  const double* xa = this->Coordinates + 3 * a;
  const double* xb = this->Coordinates + 3 * b;
  const std::int64_t index[3] = { cell.I, cell.J, cell.K };
  double da = 0.0, db = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const double center = this->Origin[k] + (static_cast<double>(index[k]) + 0.5) * this->CellSide;
    da += (xa[k] - center) * (xa[k] - center);
    db += (xb[k] - center) * (xb[k] - center);
  }
  if (da != db)
  {
    return da < db;
  }
  const double* na = this->Normals + 3 * a;
  const double* nb = this->Normals + 3 * b;
  return std::lexicographical_compare(xa, xa + 3, xb, xb + 3) ||
    (std::equal(xa, xa + 3, xb) && std::lexicographical_compare(na, na + 3, nb, nb + 3));
}

void AnchorCells::Offer(const CellKey& cell, std::int64_t point)
{
  const auto [slot, added] = this->Anchors.try_emplace(cell, point);
  if (!added && this->Precedes(point, slot->second, cell))
  {
    slot->second = point;
  }
}

bool AnchorCells::AnchorsAround(const double x[3], Around& around) const
{
  const CellKey center = this->KeyOf(x);
  if (around.Known && around.Cell == center)
  {
    return false;
  }
  around.Known = true;
  around.Cell = center;
  around.Anchors.clear();
  for (std::int64_t dk = -1; dk <= 1; ++dk)
  {
    for (std::int64_t dj = -1; dj <= 1; ++dj)
    {
      for (std::int64_t di = -1; di <= 1; ++di)
      {
        const auto found =
          this->Anchors.find(CellKey{ center.I + di, center.J + dj, center.K + dk });
        if (found != this->Anchors.end() && found->second >= 0)
        {
          around.Anchors.push_back(found->second);
        }
      }
    }
  }
  return true;
}

void AnchorCells::NumberAnchors(const std::vector<std::int64_t>& kept)
{
  for (auto& cell : this->Anchors)
  {
    cell.second = -1;
  }
  for (std::size_t position = 0; position < kept.size(); ++position)
  {
    // An anchor is the one of the cell that holds it.
    this->Anchors[this->KeyOf(this->Coordinates + 3 * kept[position])] =
      static_cast<std::int64_t>(position);
  }
}

bool AnchorCells::MarkAnchorsAround(std::int64_t count,
  const std::function<std::int64_t(std::int64_t)>& pointAt,
  std::vector<unsigned char>& marks,
  const std::function<bool()>& keepGoing) const
{
  std::unordered_set<CellKey, CellHash> visited;
  Around around;
  for (std::int64_t j = 0; j < count; ++j)
  {
    if (j % CheckInterval == 0 && !keepGoing())
    {
      return false;
    }
    const double* x = this->Coordinates + 3 * pointAt(j);
    const CellKey cell = this->KeyOf(x);
    if ((!around.Known || !(around.Cell == cell)) && visited.insert(cell).second)
    {
      this->AnchorsAround(x, around);
      for (const std::int64_t anchor : around.Anchors)
      {
        marks[static_cast<std::size_t>(anchor)] = 1;
      }
    }
  }
  return true;
}

} // namespace pcurv
