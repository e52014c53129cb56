// Times vtkLASPointCloudReader on a large LAS file and reports the peak
// memory, to show that the points are read once, in chunks, straight into
// the output arrays:
//   LasReadBenchmark write FILE.las [points=10000000] [format=3]
//   LasReadBenchmark read FILE.las
// "write" makes a LAS 1.2 file of points on a slanted grid (streamed, a
// chunk at a time); "read" reads it and prints the seconds and the
// process's peak resident size (getrusage), with the size of the output's
// arrays beside it. Run the two in separate processes, so that the reading
// one's peak is the reader's. See BENCHMARK.md, "Reading a LAS file".
#include "vtkLASPointCloudReader.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <sys/resource.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace
{

template<typename T>
void Put(std::vector<unsigned char>& bytes, std::size_t at, T value)
{
  std::memcpy(bytes.data() + at, &value, sizeof(T)); // little-endian hosts
}

int Write(const char* path, std::uint64_t count, int format)
{
  const int lengths[] = { 20, 28, 26, 34 };
  const std::uint16_t length = static_cast<std::uint16_t>(lengths[format]);
  std::vector<unsigned char> header(227, 0);
  std::memcpy(header.data(), "LASF", 4);
  header[24] = 1;
  header[25] = 2;
  Put<std::uint16_t>(header, 94, 227);
  Put<std::uint32_t>(header, 96, 227);
  header[104] = static_cast<unsigned char>(format);
  Put<std::uint16_t>(header, 105, length);
  Put<std::uint32_t>(header, 107, static_cast<std::uint32_t>(count));
  const double scale[3] = { 0.001, 0.001, 0.001 }, offset[3] = { 596000, 243000, 0 };
  std::memcpy(header.data() + 131, scale, sizeof scale);
  std::memcpy(header.data() + 155, offset, sizeof offset);
  std::FILE* file = std::fopen(path, "wb");
  if (!file || std::fwrite(header.data(), 1, header.size(), file) != header.size())
  {
    std::perror(path);
    return EXIT_FAILURE;
  }
  const std::uint64_t chunk = 1 << 16;
  std::vector<unsigned char> records(chunk * length, 0);
  const std::uint64_t side = 3163; // a square grid of about 10M points
  for (std::uint64_t first = 0; first < count; first += chunk)
  {
    const std::uint64_t n = std::min(chunk, count - first);
    for (std::uint64_t k = 0; k < n; ++k)
    {
      const std::uint64_t i = first + k;
      const std::size_t at = k * length;
      Put<std::int32_t>(records, at, static_cast<std::int32_t>(i % side * 250));
      Put<std::int32_t>(records, at + 4, static_cast<std::int32_t>(i / side * 250));
      Put<std::int32_t>(records, at + 8, static_cast<std::int32_t>((i % side + i / side) * 10));
      Put<std::uint16_t>(records, at + 12, static_cast<std::uint16_t>(i));
      records[at + 14] = 1 | (1 << 3);
      records[at + 15] = 2;
      if (format == 1 || format == 3)
        Put<double>(records, at + 20, i * 1e-3);
    }
    if (std::fwrite(records.data(), length, n, file) != n)
    {
      std::perror(path);
      return EXIT_FAILURE;
    }
  }
  std::fclose(file);
  std::printf("wrote %s: %llu points, format %d, %llu bytes\n",
    path,
    static_cast<unsigned long long>(count),
    format,
    static_cast<unsigned long long>(227 + count * length));
  return EXIT_SUCCESS;
}

double PeakMegabytes()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0; // kilobytes on Linux
}

int Read(const char* path)
{
  const double before = PeakMegabytes();
  vtkNew<vtkLASPointCloudReader> reader;
  reader->SetFileName(path);
  const auto start = std::chrono::steady_clock::now();
  reader->Update();
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  vtkPolyData* cloud = reader->GetOutput();
  const double arrays =
    (cloud->GetActualMemorySize() - cloud->GetVerts()->GetActualMemorySize()) / 1024.0;
  const double cells = cloud->GetVerts()->GetActualMemorySize() / 1024.0;
  std::printf("read %lld points in %.2f s; peak resident %.0f MB (%.0f MB before the read); "
              "output: points and arrays %.0f MB, vertex cells %.0f MB\n",
    static_cast<long long>(cloud->GetNumberOfPoints()),
    seconds,
    PeakMegabytes(),
    before,
    arrays,
    cells);
  return cloud->GetNumberOfPoints() > 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

} // namespace

int main(int argc, char* argv[])
{
  if (argc >= 3 && std::string(argv[1]) == "write")
  {
    const std::uint64_t count = argc > 3 ? std::strtoull(argv[3], nullptr, 10) : 10000000;
    const int format = argc > 4 ? std::atoi(argv[4]) : 3;
    return Write(argv[2], count, format >= 0 && format <= 3 ? format : 3);
  }
  if (argc >= 3 && std::string(argv[1]) == "read")
  {
    return Read(argv[2]);
  }
  std::fprintf(stderr, "usage: %s write FILE.las [points] [format 0-3] | read FILE.las\n", argv[0]);
  return EXIT_FAILURE;
}
