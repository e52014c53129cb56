/**
 * @file OffMesh.h
 * @brief Parsing of OFF meshes (Geomview's Object File Format, text), as
 * CGAL's demo scans come (no VTK); vtkOFFMeshReader is its VTK glue.
 *
 * Accepted: a header word ending in "OFF" (OFF, COFF, NOFF, ...; the counts
 * may follow on its line), the counts "vertices faces [edges]", one vertex
 * per line (x y z first; further numbers, such as colors or normals of the
 * variants, are ignored), one face per line ("n i_1 ... i_n", indices from
 * 0, n >= 3; further numbers ignored). '#' starts a comment. Anything else is
 * an error naming the line and what is wrong; binary OFF is refused.
 */
#ifndef OffMesh_h
#define OffMesh_h

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pcurv
{

struct OffMesh
{
  std::vector<double> Points;                // 3 per vertex
  std::vector<std::int64_t> Offsets = { 0 }; // faces as in vtkCellArray
  std::vector<std::int64_t> Connectivity;    // vertex indices, from 0
  std::size_t Faces() const { return this->Offsets.size() - 1; }
};

/// Reads [data, data + size) into mesh; an empty string on success, else
/// what is wrong ("line N: ...").
std::string ParseOffMesh(const char* data, std::size_t size, OffMesh& mesh);

} // namespace pcurv

#endif
