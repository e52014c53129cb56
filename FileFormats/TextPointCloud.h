/**
 * @file TextPointCloud.h
 * @brief Parsing of text point clouds (x y z [nx ny nz] [more columns] per
 * line) and the choice of what each column becomes (no VTK).
 *
 * vtkTextPointCloudReader is the VTK glue around this: it reads the file
 * with ReadTextFile, parses it with ParseTextCloud, asks ChooseColumnLayout
 * what the columns are and copies them into arrays. Its class documentation
 * has the rules for the lines and columns; the policy for bad lines is:
 * - a line whose numbers differ in count from the first data line's, fewer
 *   than 3 numbers on the first data line, a word that is not a number, a
 *   binary file: an error naming the line (parsing stops, no points);
 * - NaN or infinite numbers are numbers: such a point is kept (the
 *   curvature filter flags it, Unestimated_Bad_Coordinate), and the rows
 *   holding one are counted in TextCloud::NonFiniteRows so that the reader
 *   can warn once, naming the first line.
 */
#ifndef TextPointCloud_h
#define TextPointCloud_h

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace pcurv
{

/// The numbers of the data lines, row by row, and what came before them.
struct TextCloud
{
  std::size_t Columns = 0;
  std::vector<double> Values;     // Rows() x Columns, row major
  std::vector<std::string> Names; // the header's column names, or empty
  /// The "# field <name> <value>" lines before the data (CsvWriter.h).
  std::vector<std::pair<std::string, std::string>> Fields;
  std::size_t HeaderLine = 0;
  std::size_t FirstDataLine = 0;
  /// The rows holding a NaN or infinite number, with their line numbers.
  std::vector<std::pair<std::size_t, std::size_t>> NonFiniteRows;

  std::size_t Rows() const { return this->Columns ? this->Values.size() / this->Columns : 0; }
};

/**
 * Reads the lines of [data, data + size) into cloud. Returns an empty string
 * on success, else what is wrong, starting "line N: " where a line is to
 * blame. pts: the file is a Leica .pts (every line holding one integer is a
 * point count). With firstRowOnly, stops after the first data line.
 */
std::string ParseTextCloud(const char* data,
  std::size_t size,
  bool pts,
  bool firstRowOnly,
  TextCloud& cloud);

/**
 * Whether the start of a file, [data, data + size), looks like a file of
 * another format that shares the .xyz extension. A molecule (XYZ: an atom
 * count, a comment line, then lines "element x y z"). A PLOT3D grid: binary
 * (a NUL byte) and starting as one does, with either byte order: a Fortran
 * record (its length, 4 to 64 bytes, repeated after it) or three small
 * positive integers (grid count or dimensions); random bytes pass either
 * test with a chance below 1e-8.
 */
bool LooksLikeMolecule(const char* data, std::size_t size);
bool LooksLikePlot3d(const char* data, std::size_t size);

/// At most `limit` bytes of the file in buffer, or false with the reason in
/// error (the system's message).
bool ReadTextFile(const char* fileName, std::size_t limit, std::string& buffer, std::string& error);

/// The file name's extension in lower case, without the dot ("" if none).
std::string LowerExtension(const char* fileName);

/// What each column of the file becomes.
struct ColumnLayout
{
  std::vector<std::size_t> Position = { 0, 1, 2 };
  std::vector<std::size_t> Normal;                          // 3 columns or none
  std::vector<std::size_t> Color;                           // 3 columns or none
  std::vector<std::pair<std::size_t, std::string>> Scalars; // the others, named
};

/// The columns' roles (the rules of vtkTextPointCloudReader's documentation).
ColumnLayout ChooseColumnLayout(const TextCloud& cloud, bool pts);

/// The line numbers of the rows whose position columns hold a NaN or an
/// infinite number, in file order.
std::vector<std::size_t> NonFinitePositionLines(const TextCloud& cloud, const ColumnLayout& layout);

} // namespace pcurv

#endif
