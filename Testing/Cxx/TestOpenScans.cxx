// Normals of scans seen from one side (no VTK): a generated airborne tile,
// terrain with tree crowns, buildings and a closed object beside them, with
// its normals estimated and oriented by default.
#include "CloudTestSupport.h"

namespace
{
using namespace pcurv;
using namespace cloudtest;

/// What a point of the tile belongs to.
enum class Part : int
{
  Ground,
  Crown,   // the outer shell of a tree crown
  Foliage, // returns from inside a crown: no surface, no normal to check
  Roof,
  Wall,
  Sphere // a closed object beside the tile
};

struct Tile
{
  std::vector<testing::SurfaceSample> Samples;
  std::vector<Part> Parts;
  /// The crown (or -1) of each point, and the crowns' centers.
  std::vector<int> Crowns;
  std::vector<testing::Vec> CrownCenters;

  void Add(const testing::Vec& x, const testing::Vec& normal, Part part, int crown = -1)
  {
    testing::SurfaceSample sample{};
    sample.Point = x;
    sample.Normal = normal;
    this->Samples.push_back(sample);
    this->Parts.push_back(part);
    this->Crowns.push_back(crown);
  }
};

constexpr double Spacing = 0.5;

double GroundHeight(double x, double y)
{
  return 0.4 * std::sin(x / 6.0) * std::cos(y / 7.0);
}

void AddGround(Tile& tile, testing::Random& random)
{
  for (double x = 0.0; x < 40.0; x += Spacing)
  {
    for (double y = 0.0; y < 40.0; y += Spacing)
    {
      const double px = x + 0.4 * Spacing * (random.Uniform() - 0.5),
                   py = y + 0.4 * Spacing * (random.Uniform() - 0.5);
      const double dx = 0.4 / 6.0 * std::cos(px / 6.0) * std::cos(py / 7.0);
      const double dy = -0.4 / 7.0 * std::sin(px / 6.0) * std::sin(py / 7.0);
      tile.Add(
        { { px, py, GroundHeight(px, py) } }, testing::Unit({ { -dx, -dy, 1.0 } }), Part::Ground);
    }
  }
}

/// A crown as an airborne scanner sees it: the shell of an ellipsoid down
/// to 10 degrees below its equator (a scanner looking at most 10 to 20
/// degrees away from straight down sees no lower), its surface rough at the scale of the
/// leaves, and returns from inside it; a trunk joins it to the ground.
void AddCrown(Tile& tile, const testing::Vec& center, testing::Random& random)
{
  const int crown = static_cast<int>(tile.CrownCenters.size());
  tile.CrownCenters.push_back(center);
  const double a = 2.5, c = 2.0;
  const auto unit = [&random](testing::Random&) { return random.Uniform(); };
  const auto noise = [&random](testing::Random&) { return 0.1 * random.Normal(); };
  const double lowest = std::sin(-10.0 * 3.141592653589793 / 180.0);
  const int shell = static_cast<int>(4.0 * 3.14159 * a * a * 0.7 / (Spacing * Spacing));
  for (int i = 0; i < shell; ++i)
  {
    const double w = lowest + (1.0 - lowest) * unit(random); // sin(latitude)
    const double phi = 2.0 * 3.141592653589793 * unit(random);
    const double r = std::sqrt(1.0 - w * w);
    const double rough = 1.0 + 0.08 * (unit(random) - 0.5);
    const testing::Vec x{ { center[0] + rough * a * r * std::cos(phi) + noise(random),
      center[1] + rough * a * r * std::sin(phi) + noise(random),
      center[2] + rough * c * w + noise(random) } };
    const testing::Vec normal =
      testing::Unit({ { r * std::cos(phi) / a, r * std::sin(phi) / a, w / c } });
    tile.Add(x, normal, Part::Crown, crown);
  }
  for (int i = 0; i < shell / 6; ++i)
  {
    const double s = 0.75 * std::cbrt(unit(random));
    const double w = 2.0 * unit(random) - 1.0, phi = 2.0 * 3.141592653589793 * unit(random);
    const double r = std::sqrt(1.0 - w * w);
    tile.Add({ { center[0] + s * a * r * std::cos(phi),
               center[1] + s * a * r * std::sin(phi),
               center[2] + s * c * w } },
      { { 0.0, 0.0, 1.0 } },
      Part::Foliage,
      crown);
  }
  const double ground = GroundHeight(center[0], center[1]);
  for (double z = ground; z < center[2] - 0.8 * c; z += 0.5 * Spacing)
  {
    tile.Add({ { center[0] + 0.1 * (unit(random) - 0.5), center[1], z } },
      { { 0.0, 0.0, 1.0 } },
      Part::Foliage);
  }
}

/// A flat-roofed building block: its roof and four walls.
void AddBuilding(Tile& tile, double x0, double y0, double width, double depth, double height)
{
  const double ground = GroundHeight(x0, y0);
  for (double x = x0; x <= x0 + width + 1e-9; x += Spacing)
  {
    for (double y = y0; y <= y0 + depth + 1e-9; y += Spacing)
    {
      tile.Add({ { x, y, ground + height } }, { { 0.0, 0.0, 1.0 } }, Part::Roof);
    }
  }
  for (double z = ground + Spacing; z < ground + height - 0.5 * Spacing; z += Spacing)
  {
    for (double x = x0 + Spacing; x < x0 + width - 0.5 * Spacing; x += Spacing)
    {
      tile.Add({ { x, y0 - 0.05, z } }, { { 0.0, -1.0, 0.0 } }, Part::Wall);
      tile.Add({ { x, y0 + depth + 0.05, z } }, { { 0.0, 1.0, 0.0 } }, Part::Wall);
    }
    for (double y = y0 + Spacing; y < y0 + depth - 0.5 * Spacing; y += Spacing)
    {
      tile.Add({ { x0 - 0.05, y, z } }, { { -1.0, 0.0, 0.0 } }, Part::Wall);
      tile.Add({ { x0 + width + 0.05, y, z } }, { { 1.0, 0.0, 0.0 } }, Part::Wall);
    }
  }
}

Tile AirborneTile()
{
  Tile tile;
  testing::Random random(2026);
  AddGround(tile, random);
  for (const auto& center : { testing::Vec{ { 6.0, 6.0, 7.0 } },
         testing::Vec{ { 12.0, 30.0, 6.5 } },
         testing::Vec{ { 20.0, 8.0, 8.0 } },
         testing::Vec{ { 33.0, 33.0, 7.0 } },
         testing::Vec{ { 28.0, 20.0, 6.0 } },
         testing::Vec{ { 7.0, 20.0, 7.5 } } })
  {
    AddCrown(tile, center, random);
  }
  AddBuilding(tile, 14.0, 15.0, 8.0, 6.0, 5.0);
  AddBuilding(tile, 30.0, 4.0, 6.0, 9.0, 7.0);
  const auto sphere = testing::Sample(testing::Sphere(3.0), 600, 7);
  for (const auto& s : sphere)
  {
    tile.Add({ { s.Point[0] - 8.0, s.Point[1] + 20.0, s.Point[2] + 4.0 } }, s.Normal, Part::Sphere);
  }
  return tile;
}

/// The share of a part's points (of one crown, or any) whose estimated
/// normal agrees with the exact one in sign.
double AgreeingShare(const Tile& tile, const std::vector<double>& normals, Part part, int crown)
{
  int agree = 0, count = 0;
  for (std::size_t i = 0; i < tile.Samples.size(); ++i)
  {
    if (tile.Parts[i] == part && (crown < 0 || tile.Crowns[i] == crown))
    {
      const testing::Vec n{ { normals[3 * i], normals[3 * i + 1], normals[3 * i + 2] } };
      agree += testing::Dot(n, tile.Samples[i].Normal) > 0.0;
      ++count;
    }
  }
  return count ? static_cast<double>(agree) / count : 0.0;
}

/// The scene is recognized as seen from above: ground and roofs up, every
/// crown outward (up and away from its middle), the closed sphere beside
/// the tile outward, and the normals of the crowns' and roofs' points that
/// face up hardly ever down.
void TestAirborneTileNormals(Checks& checks)
{
  const Tile tile = AirborneTile();
  SerialRunner serial;
  std::vector<double> normals(3 * tile.Samples.size());
  const NormalSummary summary = EstimateCloudNormals(
    MakeCloud(tile.Samples), NormalSettings{}, Collectives{}, serial, normals.data());
  checks.True("the tile is seen from above", summary.SeenFromAbove);
  checks.AtLeast("ground up", AgreeingShare(tile, normals, Part::Ground, -1), 0.995);
  checks.AtLeast("roofs up", AgreeingShare(tile, normals, Part::Roof, -1), 0.99);
  checks.AtLeast("sphere outward", AgreeingShare(tile, normals, Part::Sphere, -1), 0.99);
  for (int crown = 0; crown < static_cast<int>(tile.CrownCenters.size()); ++crown)
  {
    const std::string name = "crown " + std::to_string(crown) + " outward";
    checks.AtLeast(name.c_str(), AgreeingShare(tile, normals, Part::Crown, crown), 0.9);
  }
  int down = 0, above = 0;
  for (std::size_t i = 0; i < tile.Samples.size(); ++i)
  {
    if ((tile.Parts[i] == Part::Crown || tile.Parts[i] == Part::Roof) &&
      tile.Samples[i].Normal[2] > 0.2)
    {
      down += normals[3 * i + 2] < 0.0;
      ++above;
    }
  }
  checks.Below("crown and roof normals down where the surface faces up",
    static_cast<double>(down) / above,
    0.02);

  ThreadRunner threads(3);
  std::vector<double> threaded(normals.size());
  EstimateCloudNormals(
    MakeCloud(tile.Samples), NormalSettings{}, Collectives{}, threads, threaded.data());
  checks.True("3 threads bit-identical to 1", threaded == normals);
}

/// Closed objects keep their outward normals; a closed object is never
/// taken for a scan from above, even lying flat.
void TestClosedObjectsNotFromAbove(Checks& checks)
{
  for (const auto& [name, surface] : { std::pair{ "sphere", testing::Sphere(2.0) },
         std::pair{ "flat torus", testing::Torus(3.0, 0.5) } })
  {
    const auto samples = testing::Sample(surface, 20000, 23);
    SerialRunner serial;
    std::vector<double> normals(3 * samples.size());
    const NormalSummary summary = EstimateCloudNormals(
      MakeCloud(samples), NormalSettings{}, Collectives{}, serial, normals.data());
    checks.True((std::string(name) + ": not seen from above").c_str(), !summary.SeenFromAbove);
  }
}

/// The estimated crowns come out convex: the mean curvature of their
/// shells is positive, as the ground's is about zero.
void TestAirborneTileCurvature(Checks& checks)
{
  const Tile tile = AirborneTile();
  EstimationSettings settings;
  settings.EstimateNormals = true;
  Results results(tile.Samples.size(), false);
  SerialRunner serial;
  Estimate(tile.Samples, settings, results, serial);
  for (int crown = 0; crown < static_cast<int>(tile.CrownCenters.size()); ++crown)
  {
    int convex = 0, count = 0;
    for (std::size_t i = 0; i < tile.Samples.size(); ++i)
    {
      if (tile.Parts[i] == Part::Crown && tile.Crowns[i] == crown && results.Valid[i])
      {
        convex += results.Mean[i] > 0.0;
        ++count;
      }
    }
    const std::string name = "crown " + std::to_string(crown) + ": H > 0";
    checks.AtLeast(name.c_str(), count ? static_cast<double>(convex) / count : 0.0, 0.8);
  }
}

} // namespace

int main(int argc, char* argv[])
{
  return RunNamedTests(argc,
    argv,
    {
      { "AirborneTileNormals", TestAirborneTileNormals },
      { "ClosedObjectsNotFromAbove", TestClosedObjectsNotFromAbove },
      { "AirborneTileCurvature", TestAirborneTileCurvature },
    });
}
