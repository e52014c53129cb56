#include "Estimation/RemoteCopies.h"

#include "Cloud/CloudPoints.h"
#include "Cloud/Collectives.h"
#include "Estimation/ResultStore.h"
#include "Outliers/SurfaceOutliers.h"

#include <algorithm>
#include <array>
#include <map>

namespace pcurv
{
namespace
{
/// A point's coordinates and normal: what makes it the point asked for.
using PointKey = std::array<double, 6>;
} // namespace

void RemoteCopies::TakeOut(CloudPoints& cloud, const SurfaceOutliers& outliers)
{
  std::vector<unsigned char> remove(outliers.RemotePoints.empty() ? 0 : cloud.NumberOfOwnPoints, 0);
  for (const std::int64_t point : outliers.RemotePoints)
  {
    remove[point] = 1;
  }
  this->Askers = RemoveOwnPoints(cloud, remove);
  this->Asked = outliers.RemoteReferences;
}

void RemoteCopies::FindAnswers(const CloudPoints& cloud, const Collectives& processes)
{
  this->Answers.clear();
  if (!processes.IsDistributed() ||
    processes.Sum(static_cast<std::int64_t>(this->Askers.size())) == 0)
  {
    return;
  }
  std::vector<std::int64_t> lengths;
  const std::vector<double> asked = processes.Gather(this->Asked, &lengths);
  this->FirstAsked = 0;
  for (int p = 0; p < processes.GetLocalProcessId(); ++p)
  {
    this->FirstAsked += lengths[p] / 6;
  }
  std::map<PointKey, std::vector<std::int64_t>> wanted;
  for (std::size_t a = 0; a < asked.size() / 6; ++a)
  {
    PointKey key;
    std::copy_n(&asked[6 * a], 6, key.begin());
    wanted[key].push_back(static_cast<std::int64_t>(a));
  }
  for (std::int64_t i = 0; i < cloud.NumberOfOwnPoints; ++i)
  {
    PointKey key;
    std::copy_n(&cloud.Coordinates[3 * i], 3, key.begin());
    std::copy_n(&cloud.Normals[3 * i], 3, key.begin() + 3);
    const auto found = wanted.find(key);
    for (std::size_t a = 0; found != wanted.end() && a < found->second.size(); ++a)
    {
      this->Answers.emplace_back(found->second[a], cloud.InputId(i));
    }
  }
}

void RemoteCopies::Deliver(const ResultStore& writer, const Collectives& processes) const
{
  for (const std::int64_t asker : this->Askers)
  {
    writer.StoreUnestimated(asker, UnestimatedReason::FitFailed);
  }
  if (!processes.IsDistributed() ||
    processes.Sum(static_cast<std::int64_t>(this->Askers.size())) == 0)
  {
    return;
  }
  constexpr std::size_t Length = ResultStore::RecordLength + 1; // the asked index first
  std::vector<double> records(Length * this->Answers.size());
  for (std::size_t a = 0; a < this->Answers.size(); ++a)
  {
    records[Length * a] = static_cast<double>(this->Answers[a].first);
    writer.Pack(this->Answers[a].second, &records[Length * a + 1]);
  }
  const std::vector<double> all = processes.Gather(records);
  const std::int64_t count = static_cast<std::int64_t>(this->Askers.size());
  for (std::size_t r = 0; r < all.size() / Length; ++r)
  {
    const std::int64_t asked = static_cast<std::int64_t>(all[Length * r]) - this->FirstAsked;
    if (asked >= 0 && asked < count)
    {
      writer.Unpack(&all[Length * r + 1], this->Askers[asked]);
    }
  }
}

} // namespace pcurv
