// libFuzzer target on the core's file parsers (text clouds, OFF meshes):
// any bytes give either an error message or a result that holds together;
// never a crash, a hang or undefined behavior. The first byte chooses the
// parser: even a text cloud (.pts rules when its second bit is set), odd an
// OFF mesh.
#include "FileFormats/MeshOrientation.h"
#include "FileFormats/OffMesh.h"
#include "FileFormats/TextPointCloud.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace
{

void Require(bool condition, const char* what)
{
  if (!condition)
  {
    std::fprintf(stderr, "invariant broken: %s\n", what);
    std::abort();
  }
}

void FuzzText(const char* data, std::size_t size, bool pts)
{
  pcurv::TextCloud cloud;
  const std::string error = pcurv::ParseTextCloud(data, size, pts, false, cloud);
  pcurv::TextCloud first;
  const std::string firstError = pcurv::ParseTextCloud(data, size, pts, true, first);
  Require(!error.empty() || firstError.empty(), "a readable file has a readable first line");
  if (!error.empty())
  {
    return;
  }
  Require(cloud.Columns >= 3, "at least x y z");
  Require(cloud.Values.size() == cloud.Rows() * cloud.Columns, "whole rows");
  Require(cloud.Rows() >= 1, "at least one point");
  const pcurv::ColumnLayout layout = pcurv::ChooseColumnLayout(cloud, pts);
  for (const auto* columns : { &layout.Position, &layout.Normal, &layout.Color })
  {
    for (std::size_t column : *columns)
    {
      Require(column < cloud.Columns, "layout columns exist");
    }
  }
  for (const auto& scalar : layout.Scalars)
  {
    Require(scalar.first < cloud.Columns && !scalar.second.empty(), "named scalar columns");
  }
  const std::vector<std::size_t> lines = pcurv::NonFinitePositionLines(cloud, layout);
  for (std::size_t i = 1; i < lines.size(); ++i)
  {
    Require(lines[i - 1] < lines[i], "non-finite lines in file order");
  }
}

void FuzzOff(const char* data, std::size_t size)
{
  pcurv::OffMesh mesh;
  if (!pcurv::ParseOffMesh(data, size, mesh).empty())
  {
    return;
  }
  const std::size_t vertices = mesh.Points.size() / 3;
  Require(mesh.Points.size() % 3 == 0, "whole vertices");
  Require(mesh.Offsets.front() == 0 &&
      mesh.Offsets.back() == static_cast<std::int64_t>(mesh.Connectivity.size()),
    "offsets span the connectivity");
  for (std::size_t f = 1; f < mesh.Offsets.size(); ++f)
  {
    Require(mesh.Offsets[f] - mesh.Offsets[f - 1] >= 3, "faces of at least 3 vertices");
  }
  for (std::int64_t index : mesh.Connectivity)
  {
    Require(index >= 0 && static_cast<std::size_t>(index) < vertices, "indices are vertices");
  }
  if (vertices > 0)
  {
    pcurv::NormalsMostlyInward(mesh.Points.data(), mesh.Points.data(), vertices);
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size)
{
  if (size == 0)
  {
    return 0;
  }
  const char* data = reinterpret_cast<const char*>(bytes + 1);
  if (bytes[0] & 1)
  {
    FuzzOff(data, size - 1);
  }
  else
  {
    FuzzText(data, size - 1, (bytes[0] & 2) != 0);
    pcurv::LooksLikePlot3d(data, size - 1);
    pcurv::LooksLikeMolecule(data, size - 1);
  }
  return 0;
}
