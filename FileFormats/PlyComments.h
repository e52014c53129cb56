/**
 * The header comments of the PLY files the plugin writes: what PLY's
 * properties cannot say (arrays of several components, names with spaces,
 * field data), in a form the plugin's PLY reader follows and other tools
 * show as comments. No VTK here.
 */
#ifndef pcurv_PlyComments_h
#define pcurv_PlyComments_h

#include <string>
#include <vector>

namespace pcurv
{
namespace ply
{

/**
 * A header comment "array <first property> <components> <name>" (the name
 * the rest of the line, spaces kept): the vertex properties from the first
 * on are the components of one array of that name. The plugin's PLY writer
 * adds one for each array whose name or components a PLY property cannot
 * hold as they are, so that the reader restores the array (PLY has no
 * multi-component properties, nor spaces in names).
 */
struct ArrayComment
{
  std::string FirstProperty;
  int Components = 1;
  std::string Name;
};
std::string FormatArrayComment(const ArrayComment& comment);
bool ParseArrayComment(const std::string& text, ArrayComment& comment);

/// A header comment "field <name> <value>": one field-data value of the
/// data set written (its unit, counts), as text, on one line (white space
/// in the name becomes '_', line ends in the value spaces). A field of
/// several values (class names) is one comment per value, in order.
std::string FormatFieldComment(const std::string& name, const std::string& value);
bool ParseFieldComment(const std::string& text, std::string& name, std::string& value);

/// A text file's line "# field <name> <value>" (CsvWriter.h), spaces
/// before the '#' and a carriage return at the end allowed.
bool ParseFieldCommentLine(const char* begin,
  const char* end,
  std::string& name,
  std::string& value);

/// The numbers of a field comment's value ("12", "0.5 1 2"); false when a
/// word is not a number (the value is then text).
bool ParseNumbers(const std::string& text, std::vector<double>& numbers);

} // namespace ply
} // namespace pcurv

#endif
