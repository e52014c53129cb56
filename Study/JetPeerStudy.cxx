// A study program (not a test): CGAL's Monge_via_jet_fitting with a jet of
// degree 4 (Monge degree 2) as a peer on the workplace's shared accuracy
// suite (../shared/accuracy/README.md), beside the degree-2 jet already in
// its peers.csv (issue 22, item 3; Study/REPORT.md, "Peer: jet fitting of
// degree 4 (CGAL), at its best k").
//
// Usage: JetPeerStudy SUITE_DIR OUT.csv [--k 15,20,...] [--sizes 20000,200000]
//                     [--noise 0,0.1,0.5] [--shapes sphere,...] [--degree 4]
//                     [--eval-stride S]
//
// The runs behind Study/REPORT.md ("Peer: jet fitting of degree 4"), one
// command each:
//
//   JetPeerStudy SUITE noise0.csv --noise 0 --k 15,20,30,45,70,100,150,220,330
//   JetPeerStudy SUITE n20k.csv
//     --sizes 20000 --noise 0.1,0.5 --k 30,45,70,100,150,220,330,500,700,1000,1500,2200,3300
//   JetPeerStudy SUITE n200k.csv --sizes 200000 --noise 0.1,0.5 --k 220,500,1000,1500,2200
//   JetPeerStudy SUITE n200k_wide.csv
//     --sizes 200000 --noise 0.1,0.5 --k 2200,3300,5000,7500 --eval-stride 5
//
// For every cloud and neighbor count k (the k nearest points of the cloud,
// the evaluation point included and first, as CGAL's fitting origin), fits a
// jet to the positions only, turns its Monge normal to the side of the
// cloud's normal (exact ones, and the suite's PCA(30) ones: the same fits,
// only the orientation can differ) and measures, on the evaluation points:
// relative error = mean |k - exact| / the shape's largest |k| for k_min and
// k_max, and the median angle (as lines) between the estimated and exact
// k_max directions where the exact k_max - k_min > 0.05 x the largest |k|.
// Sign: positive where the surface bends away from the normal. One thread;
// times in seconds per million evaluation points. Writes one CSV row per
// (cloud, normals, k) with peers.csv's columns, then prints each cloud's best
// k (lowest max of the two relative errors) and the medians over the six
// shapes of the best per group. --eval-stride S measures every S-th
// evaluation point only (for the largest k on the 200k clouds; the rows
// then say so in the column n_eval).

#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Vector = Kernel::Vector_3;
using Fitting = CGAL::Monge_via_jet_fitting<Kernel>;
using SearchTraits = CGAL::Search_traits_3<Kernel>;
using Search = CGAL::Orthogonal_k_neighbor_search<SearchTraits>;
using Tree = Search::Tree;
using Clock = std::chrono::steady_clock;

constexpr int Columns = 14; // x y z, nx ny nz, k_min k_max, d1 (3), d2 (3)

struct Cloud
{
  std::vector<double> Exact; // N x 14, exact normals
  std::vector<double> Pca;   // N x 14, PCA(30) normals (same positions)
  std::vector<std::int32_t> Eval;
  std::size_t Count = 0;
};

std::vector<double> ReadDoubles(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw std::runtime_error("cannot open " + path);
  }
  in.seekg(0, std::ios::end);
  const std::streamoff bytes = in.tellg();
  in.seekg(0);
  std::vector<double> values(static_cast<std::size_t>(bytes) / sizeof(double));
  in.read(reinterpret_cast<char*>(values.data()), static_cast<std::streamsize>(bytes));
  return values;
}

std::vector<std::int32_t> ReadInts(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw std::runtime_error("cannot open " + path);
  }
  in.seekg(0, std::ios::end);
  const std::streamoff bytes = in.tellg();
  in.seekg(0);
  std::vector<std::int32_t> values(static_cast<std::size_t>(bytes) / sizeof(std::int32_t));
  in.read(reinterpret_cast<char*>(values.data()), static_cast<std::streamsize>(bytes));
  return values;
}

std::string NoiseName(double noise)
{
  std::ostringstream s;
  s << noise; // 0, 0.1, 0.5 as in the suite's file names
  return s.str();
}

double LargestCurvature(const std::string& shape)
{
  static const std::map<std::string, double> largest = { { "sphere", 0.1 },
    { "cylinder", 0.2 },
    { "torus", 1.0 / 3.0 },
    { "ellipsoid", 0.625 },
    { "saddle", 0.125 },
    { "paraboloid", 1.0 / 6.0 } };
  return largest.at(shape);
}

template<typename T>
std::vector<T> ParseList(const std::string& text)
{
  std::vector<T> values;
  std::stringstream s(text);
  std::string item;
  while (std::getline(s, item, ','))
  {
    std::stringstream v(item);
    T value;
    v >> value;
    values.push_back(value);
  }
  return values;
}

double Median(std::vector<double> values)
{
  values.erase(
    std::remove_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); }),
    values.end());
  if (values.empty())
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// One evaluation point's estimate, oriented by one kind of normal.
struct Estimate
{
  double Min = 0, Max = 0;
  Vector MaxDirection = Vector(0, 0, 0);
};

// The Monge form turned to the side of the given normal, in the project's
// sign: CGAL's z = (k1 x^2 + k2 y^2) / 2 + ... along the (turned) normal with
// k1 >= k2 is positive where the surface bends towards the normal, so the
// project's k_max is -k2, along CGAL's minimal principal direction.
Estimate Orient(Fitting::Monge_form form, const double* normal)
{
  form.comply_wrt_given_normal(Vector(normal[0], normal[1], normal[2]));
  Estimate e;
  e.Max = -form.principal_curvatures(1);
  e.Min = -form.principal_curvatures(0);
  e.MaxDirection = form.minimal_principal_direction();
  return e;
}

struct Accumulator
{
  double SumMin = 0, SumMax = 0;
  std::size_t Valid = 0, Fail = 0;
  std::vector<double> Angles;

  void Add(const Estimate& e, const double* row, double largest)
  {
    if (!std::isfinite(e.Min) || !std::isfinite(e.Max))
    {
      ++this->Fail;
      return;
    }
    ++this->Valid;
    this->SumMin += std::abs(e.Min - row[6]);
    this->SumMax += std::abs(e.Max - row[7]);
    if (row[7] - row[6] > 0.05 * largest)
    {
      const double* d = row + 11;
      const Vector& v = e.MaxDirection;
      const double dot = v.x() * d[0] + v.y() * d[1] + v.z() * d[2];
      const double norms =
        std::sqrt(v.squared_length() * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
      const double c = std::min(1.0, std::abs(dot) / norms);
      this->Angles.push_back(std::acos(c) * 180.0 / M_PI);
    }
  }
};

struct Row
{
  std::string Shape, Normals;
  int N = 0;
  double Noise = 0;
  int K = 0;
  double Radius = 0, ErrMin = 0, ErrMax = 0, Angle = 0;
  std::size_t Fail = 0;
  double TKnn = 0, TEst = 0;
  double Error() const { return std::max(this->ErrMin, this->ErrMax); }
};
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: " << argv[0]
              << " SUITE_DIR OUT.csv [--k 15,20,...] [--sizes 20000,200000] [--noise 0,0.1,0.5]"
                 " [--shapes sphere,...] [--degree 4]\n";
    return 2;
  }
  const std::string suite = argv[1];
  const std::string output = argv[2];
  std::vector<int> ks = { 15, 20, 30, 45, 70, 100, 150, 220, 330, 500, 700, 1000 };
  std::vector<int> sizes = { 20000, 200000 };
  std::vector<double> noises = { 0, 0.1, 0.5 };
  std::vector<std::string> shapes = {
    "sphere", "cylinder", "torus", "ellipsoid", "saddle", "paraboloid"
  };
  int degree = 4;
  std::size_t evalStride = 1;
  for (int i = 3; i + 1 < argc; i += 2)
  {
    const std::string option = argv[i];
    const std::string value = argv[i + 1];
    if (option == "--k")
    {
      ks = ParseList<int>(value);
    }
    else if (option == "--sizes")
    {
      sizes = ParseList<int>(value);
    }
    else if (option == "--noise")
    {
      noises = ParseList<double>(value);
    }
    else if (option == "--shapes")
    {
      shapes = ParseList<std::string>(value);
    }
    else if (option == "--eval-stride")
    {
      evalStride = static_cast<std::size_t>(std::max(1, std::atoi(value.c_str())));
    }
    else if (option == "--degree")
    {
      degree = std::atoi(value.c_str());
    }
    else
    {
      std::cerr << "unknown option " << option << "\n";
      return 2;
    }
  }
  const int mongeDegree = 2;
  const std::string method = "cgal_jet" + std::to_string(degree);
  const std::size_t minimum = static_cast<std::size_t>((degree + 1) * (degree + 2) / 2);

  std::ofstream csv(output);
  csv << "method,shape,N,noise_x_h,normals,k,mean_radius_k,rel_err_kmin,rel_err_kmax,"
         "median_angle_kmax_deg,n_fail,t_knn_s_per_1M,t_est_s_per_1M,t_total_s_per_1M,n_eval\n";
  std::vector<Row> rows;

  for (int n : sizes)
  {
    for (double noise : noises)
    {
      for (const std::string& shape : shapes)
      {
        const std::string stem =
          suite + "/" + shape + "_" + std::to_string(n) + "_n" + NoiseName(noise);
        Cloud cloud;
        try
        {
          cloud.Exact = ReadDoubles(stem + ".bin");
          cloud.Pca = ReadDoubles(stem + "_pca30.bin");
          const std::vector<std::int32_t> all =
            ReadInts(suite + "/" + shape + "_" + std::to_string(n) + ".eval");
          for (std::size_t e = 0; e < all.size(); e += evalStride)
          {
            cloud.Eval.push_back(all[e]);
          }
        }
        catch (const std::exception& e)
        {
          std::cerr << e.what() << ", skipped\n";
          continue;
        }
        cloud.Count = cloud.Exact.size() / Columns;
        const double largest = LargestCurvature(shape);

        std::vector<Point> points;
        points.reserve(cloud.Count);
        for (std::size_t i = 0; i < cloud.Count; ++i)
        {
          const double* r = cloud.Exact.data() + Columns * i;
          points.emplace_back(r[0], r[1], r[2]);
        }
        const auto built = Clock::now();
        Tree tree(points.begin(), points.end());
        tree.build();
        const double tBuild = std::chrono::duration<double>(Clock::now() - built).count();

        const std::size_t evalCount = cloud.Eval.size();
        for (int k : ks)
        {
          if (static_cast<std::size_t>(k) > cloud.Count)
          {
            continue;
          }
          // In blocks of evaluation points: their neighborhoods (timed
          // apart; the query point first), then their fits.
          constexpr std::size_t Block = 256;
          const std::size_t kk = static_cast<std::size_t>(k);
          std::vector<Point> neighborhoods(Block * kk);
          double radiusSum = 0, tKnn = 0, tEst = 0;
          Accumulator exact, pca;
          Fitting fitting;
          for (std::size_t first = 0; first < evalCount; first += Block)
          {
            const std::size_t last = std::min(evalCount, first + Block);
            const auto knnStart = Clock::now();
            for (std::size_t e = first; e < last; ++e)
            {
              const Point& query = points[static_cast<std::size_t>(cloud.Eval[e])];
              Search search(tree, query, static_cast<unsigned int>(k));
              Point* out = neighborhoods.data() + (e - first) * kk;
              std::size_t m = 0;
              out[m++] = query;
              bool skippedSelf = false;
              double farthest = 0;
              for (const auto& found : search)
              {
                farthest = std::max(farthest, found.second);
                if (!skippedSelf && found.first == query)
                {
                  skippedSelf = true; // the query point itself, already first
                  continue;
                }
                if (m < kk)
                {
                  out[m++] = found.first;
                }
              }
              radiusSum += std::sqrt(farthest);
            }
            const auto fitStart = Clock::now();
            for (std::size_t e = first; e < last; ++e)
            {
              const std::size_t index = static_cast<std::size_t>(cloud.Eval[e]);
              const double* rowExact = cloud.Exact.data() + Columns * index;
              const double* rowPca = cloud.Pca.data() + Columns * index;
              const Point* begin = neighborhoods.data() + (e - first) * kk;
              Estimate fromExact, fromPca;
              bool valid = kk >= minimum;
              if (valid)
              {
                try
                {
                  const Fitting::Monge_form form = fitting(begin,
                    begin + k,
                    static_cast<std::size_t>(degree),
                    static_cast<std::size_t>(mongeDegree));
                  fromExact = Orient(form, rowExact + 3);
                  fromPca = Orient(form, rowPca + 3);
                }
                catch (const std::exception&)
                {
                  valid = false; // a CGAL precondition (a degenerate neighborhood)
                }
              }
              if (!valid)
              {
                fromExact.Min = fromPca.Min = std::numeric_limits<double>::quiet_NaN();
              }
              exact.Add(fromExact, rowExact, largest);
              pca.Add(fromPca, rowExact, largest); // the exact curvatures are the same in both
            }
            const auto fitEnd = Clock::now();
            tKnn += std::chrono::duration<double>(fitStart - knnStart).count();
            tEst += std::chrono::duration<double>(fitEnd - fitStart).count();
          }

          for (int which = 0; which < 2; ++which)
          {
            const Accumulator& a = which == 0 ? exact : pca;
            Row row;
            row.Shape = shape;
            row.Normals = which == 0 ? "exact" : "PCA";
            row.N = n;
            row.Noise = noise;
            row.K = k;
            row.Radius = radiusSum / static_cast<double>(evalCount);
            const double valid = static_cast<double>(std::max<std::size_t>(a.Valid, 1));
            row.ErrMin = a.SumMin / valid / largest;
            row.ErrMax = a.SumMax / valid / largest;
            row.Angle = Median(a.Angles);
            row.Fail = a.Fail;
            row.TKnn = tKnn / static_cast<double>(evalCount) * 1e6;
            row.TEst = tEst / static_cast<double>(evalCount) * 1e6;
            rows.push_back(row);
            char line[512];
            std::snprintf(line,
              sizeof line,
              "%s,%s,%d,%g,%s,%d,%.6g,%.6g,%.6g,%.6g,%zu,%.5g,%.5g,%.5g,%zu",
              method.c_str(),
              shape.c_str(),
              n,
              noise,
              row.Normals.c_str(),
              k,
              row.Radius,
              row.ErrMin,
              row.ErrMax,
              row.Angle,
              row.Fail,
              row.TKnn,
              row.TEst,
              row.TKnn + row.TEst,
              evalCount);
            csv << line << "\n";
            csv.flush();
            if (which == 0)
            {
              std::printf("%s\n", line);
              std::fflush(stdout);
            }
          }
        }
        std::printf("# %s %d %g: kd-tree built in %.3f s\n", shape.c_str(), n, noise, tBuild);
      }
    }
  }

  // Each cloud's best k, then the medians over the shapes of the best.
  std::map<std::string, Row> best;
  for (const Row& row : rows)
  {
    std::ostringstream key;
    key << row.N << "|" << row.Noise << "|" << row.Normals << "|" << row.Shape;
    auto found = best.find(key.str());
    if (found == best.end() || row.Error() < found->second.Error())
    {
      best[key.str()] = row;
    }
  }
  std::printf("\nbest k per cloud (%s):\nshape,N,noise_x_h,normals,k,rel_err,median_angle_kmax_deg,"
              "t_total_s_per_1M\n",
    method.c_str());
  std::map<std::string, std::vector<const Row*>> groups;
  for (const auto& entry : best)
  {
    const Row& r = entry.second;
    std::printf("%s,%d,%g,%s,%d,%.6g,%.4g,%.4g\n",
      r.Shape.c_str(),
      r.N,
      r.Noise,
      r.Normals.c_str(),
      r.K,
      r.Error(),
      r.Angle,
      r.TKnn + r.TEst);
    std::ostringstream key;
    key << r.N << "," << r.Noise << "," << r.Normals;
    groups[key.str()].push_back(&r);
  }
  std::printf("\nmedians over the shapes of the best (%s):\nN,noise_x_h,normals,rel_err,"
              "median_angle_kmax_deg,t_total_s_per_1M\n",
    method.c_str());
  for (const auto& group : groups)
  {
    std::vector<double> errors, angles, times;
    for (const Row* r : group.second)
    {
      errors.push_back(r->Error());
      angles.push_back(r->Angle);
      times.push_back(r->TKnn + r->TEst);
    }
    std::printf(
      "%s,%.5g,%.3g,%.4g\n", group.first.c_str(), Median(errors), Median(angles), Median(times));
  }
  return 0;
}
