// Writes a point cloud sampled on an analytic surface, with exact normals
// and exact principal curvatures, as a .vtp file:
//   GenerateAnalyticCloud <torus|sphere|cylinder|saddle|ellipsoid|plane|paraboloid|wave>
//                         <number of points> <output.vtp|output.xyz> [seed] [noise, in spacings]
#include "AnalyticClouds.h"

#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

namespace
{
bool MakeSurface(const std::string& name, pcurv::testing::Surface& surface)
{
  using namespace pcurv::testing;
  if (name == "torus")
    surface = Torus(3.0, 1.0);
  else if (name == "sphere")
    surface = Sphere(1.0);
  else if (name == "cylinder")
    surface = Cylinder(1.0, 6.0);
  else if (name == "saddle")
    surface = Saddle(1.0, 1.0);
  else if (name == "ellipsoid")
    surface = Ellipsoid(3.0, 2.0, 1.5);
  else if (name == "plane")
    surface = Plane(1.0);
  else if (name == "paraboloid")
    surface = Paraboloid(1.0, 1.0);
  else if (name == "wave")
    surface = Wave(3.0, 0.3, 0.5);
  else
    return false;
  return true;
}
} // namespace

int main(int argc, char* argv[])
{
  pcurv::testing::Surface surface;
  if (argc < 4 || !MakeSurface(argv[1], surface))
  {
    std::fprintf(stderr,
      "usage: %s <torus|sphere|cylinder|saddle|ellipsoid|plane|paraboloid|wave> <points> "
      "<output.vtp|output.xyz> [seed] [noise in spacings] [--points-only] [--rounded] "
      "[--tilted-normals] [--outliers]\n"
      "  (--points-only: a .xyz of x y z alone, as most scans come; --rounded: the\n"
      "  positions rounded to a grid of that many spacings instead of the noise;\n"
      "  --tilted-normals: each normal turned by about 0.05 rad at random, as\n"
      "  estimated normals are off; --outliers: 5 %% of the points also moved by\n"
      "  Gaussian noise of 10 spacings, as stray returns are)\n",
      argv[0]);
    return EXIT_FAILURE;
  }
  bool pointsOnly = false, rounded = false, tilted = false, outliers = false;
  int numbers = argc; // the optional numbers come before the flags
  for (int a = 4; a < argc; ++a)
  {
    const std::string flag = argv[a];
    pointsOnly = pointsOnly || flag == "--points-only";
    rounded = rounded || flag == "--rounded";
    tilted = tilted || flag == "--tilted-normals";
    outliers = outliers || flag == "--outliers";
    if (flag.rfind("--", 0) == 0)
    {
      numbers = std::min(numbers, a);
    }
  }
  argc = numbers;
  const int count = std::atoi(argv[2]);
  const unsigned long long seed = argc > 4 ? std::strtoull(argv[4], nullptr, 10) : 1;
  const double noise = argc > 5 ? std::atof(argv[5]) : 0.0;
  auto samples = pcurv::testing::Sample(surface, count, seed);
  if (noise > 0.0 || outliers)
  {
    // Spacing: sqrt(area per point), with the area estimated by sampling.
    double area = 0.0;
    pcurv::testing::Random random(seed + 1);
    const int trials = 100000;
    for (int t = 0; t < trials; ++t)
    {
      const double u = surface.U0 + (surface.U1 - surface.U0) * random.Uniform();
      const double v = surface.V0 + (surface.V1 - surface.V0) * random.Uniform();
      const pcurv::testing::Jet j = surface.Evaluate(u, v);
      const pcurv::testing::Vec c = pcurv::testing::Cross(j.Xu, j.Xv);
      area += std::sqrt(pcurv::testing::Dot(c, c));
    }
    area *= (surface.U1 - surface.U0) * (surface.V1 - surface.V0) / trials;
    const double spacing = std::sqrt(area / count);
    if (rounded)
    {
      // Rounding makes some points coincide: the first of each position
      // is kept (a cloud's points are told apart by their coordinates).
      pcurv::testing::RoundPositions(samples, noise * spacing);
      std::set<std::array<double, 3>> seen;
      std::vector<pcurv::testing::SurfaceSample> kept;
      for (const auto& s : samples)
      {
        if (seen.insert(s.Point).second)
        {
          kept.push_back(s);
        }
      }
      samples.swap(kept);
    }
    else
    {
      pcurv::testing::AddPositionNoise(samples, noise * spacing, seed + 2);
    }
    if (outliers)
    {
      pcurv::testing::AddOutliers(samples, 0.05, 10.0 * spacing, seed + 4);
    }
  }
  if (tilted)
  {
    pcurv::testing::TiltNormals(samples, 0.05, seed + 3);
  }
  const std::string output = argv[3];
  if (output.size() > 4 && output.substr(output.size() - 4) == ".xyz")
  {
    // Text: x y z nx ny nz per line, as scanners and CGAL's data sets have.
    std::FILE* file = std::fopen(argv[3], "w");
    if (!file)
    {
      std::fprintf(stderr, "could not write %s\n", argv[3]);
      return EXIT_FAILURE;
    }
    for (const auto& s : samples)
    {
      if (pointsOnly)
      {
        std::fprintf(file, "%.17g %.17g %.17g\n", s.Point[0], s.Point[1], s.Point[2]);
        continue;
      }
      std::fprintf(file,
        "%.17g %.17g %.17g %.17g %.17g %.17g\n",
        s.Point[0],
        s.Point[1],
        s.Point[2],
        s.Normal[0],
        s.Normal[1],
        s.Normal[2]);
    }
    std::fclose(file);
    std::printf("wrote %zu points on a %s to %s\n", samples.size(), argv[1], argv[3]);
    return EXIT_SUCCESS;
  }
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(pcurv::testing::MakeCloud(samples));
  writer->SetFileName(argv[3]);
  // Inline binary, not appended: ParaView 5.11 on a current Debian 12
  // (libexpat 2.5.0-1+deb12u2 and later) cannot read appended data.
  writer->SetDataModeToBinary();
  if (!writer->Write())
  {
    std::fprintf(stderr, "could not write %s\n", argv[3]);
    return EXIT_FAILURE;
  }
  std::printf("wrote %zu points on a %s to %s\n", samples.size(), argv[1], argv[3]);
  return EXIT_SUCCESS;
}
