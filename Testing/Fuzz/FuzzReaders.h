// The LAS and PLY parsers under the fuzz target (first byte 251: the rest
// is a LAS file; 252: a PLY file).
#ifndef FuzzReaders_h
#define FuzzReaders_h

#include <cstddef>
#include <cstdint>

void FuzzLasFile(const std::uint8_t* data, std::size_t size);
void FuzzPlyFile(const std::uint8_t* data, std::size_t size);

#endif
