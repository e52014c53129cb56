// The fuzz target's LAS and PLY checks (FuzzReaders.cxx) in the ordinary
// build, without libFuzzer: each seed given must be accepted by its parser,
// then the seed cut at every length and with every byte set to 0x00, 0xFF
// and its bits flipped goes through the fuzz checks (which abort on a
// broken invariant; the sanitizer build also catches memory errors).
//   ReplayReaderSeeds SEED...
#include "FuzzReaders.h"

#include "FileFormats/LasFile.h"
#include "FileFormats/PlyFile.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <vector>

namespace
{

using Bytes = std::vector<std::uint8_t>;

void Fuzz(const Bytes& file)
{
  if (file.empty())
  {
    return;
  }
  (file[0] == 251 ? FuzzLasFile : FuzzPlyFile)(file.data() + 1, file.size() - 1);
}

/// Whether the seed (after its routing byte) opens without an error.
bool Accepted(const Bytes& seed, const char* name)
{
  std::vector<std::uint8_t> copy(seed.begin() + 1, seed.end());
  std::FILE* stream = fmemopen(copy.data(), copy.size(), "rb");
  std::string error = "cannot open";
  if (stream && seed[0] == 251)
  {
    pcurv::las::File file;
    error = file.Open(stream);
  }
  else if (stream)
  {
    pcurv::ply::File file;
    error = file.Open(stream);
  }
  if (!error.empty())
  {
    std::printf("FAILED %s: %s\n", name, error.c_str());
  }
  return error.empty();
}

} // namespace

int main(int argc, char* argv[])
{
  int failed = 0;
  std::size_t runs = 0;
  for (int a = 1; a < argc; ++a)
  {
    std::ifstream in(argv[a], std::ios::binary);
    const Bytes seed((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (seed.size() < 2 || (seed[0] != 251 && seed[0] != 252) || !Accepted(seed, argv[a]))
    {
      std::printf("FAILED %s: not an accepted LAS (251) or PLY (252) seed\n", argv[a]);
      ++failed;
      continue;
    }
    for (std::size_t length = 1; length <= seed.size(); ++length, ++runs)
    {
      Fuzz(Bytes(seed.begin(), seed.begin() + length));
    }
    for (std::size_t at = 1; at < seed.size(); ++at)
    {
      for (int change = 0; change < 3; ++change, ++runs)
      {
        Bytes mutated = seed;
        mutated[at] = change == 0 ? 0x00 : (change == 1 ? 0xFF : mutated[at] ^ 0xFF);
        Fuzz(mutated);
      }
    }
  }
  std::printf("%zu runs on %d seeds, %d failed\n", runs, argc - 1, failed);
  return failed == 0 && argc > 1 ? EXIT_SUCCESS : EXIT_FAILURE;
}
