// What the plugin's file readers (LAS, PLY, text, OFF) share on the VTK side:
// the steps of RequestData around the reading itself, the piece of the points
// a request asks for, vertex cells, typed arrays.
#ifndef PointCloudReaderSupport_h
#define PointCloudReaderSupport_h

#include "vtkErrorCode.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

class vtkAlgorithm;
class vtkDataArray;
class vtkFieldData;
class vtkInformation;
class vtkInformationVector;
class vtkPolyData;

namespace pcurv
{
namespace readers
{

/// Why a read failed: what follows "<file name>: " in the error, and the
/// error code the reader then has. An empty Message: no failure.
struct ReadFailure
{
  ReadFailure() = default;
  /// Implicit, so that a core reader's error string (empty when all went
  /// well) is a failure of the file's format.
  ReadFailure(std::string message, unsigned long errorCode = vtkErrorCode::FileFormatError)
    : Message(std::move(message))
    , ErrorCode(errorCode)
  {
  }

  std::string Message;
  unsigned long ErrorCode = vtkErrorCode::NoError;
};

/// Fills output (the piece that outInfo asks for) from the file.
using ReadFunction =
  std::function<ReadFailure(const char* fileName, vtkPolyData* output, vtkInformation* outInfo)>;

/**
 * The RequestData of a reader around its read: 0 without an output, else 1
 * after setting errorCode (the reader's, which it sets back: the setter is
 * protected) to NoError, or NoFileNameError with the error "No FileName to
 * read.", or the read's failure's (outOfMemoryCode when out of memory) with
 * the error "<file name>: <message>" and an empty output. Failures are
 * reported, not returned, as VTK's readers do: the pipeline goes on with an
 * empty output.
 */
int RunRead(vtkAlgorithm* reader,
  const char* fileName,
  vtkInformationVector* outputVector,
  unsigned long outOfMemoryCode,
  const ReadFunction& read,
  unsigned long& errorCode);

/// The whole of a text file in buffer; on failure, "cannot read the file:
/// <the system's reason>" (CannotOpenFileError).
ReadFailure ReadWholeTextFile(const char* fileName, std::string& buffer);

/// 1 if the file can be opened for reading, else 0 (CanReadFile of the
/// readers that take any file of their extensions and report what is wrong).
int CanOpenFile(const char* fileName);

/// RequestInformation of a reader that reads any piece of its points.
int AllowPieceRequests(vtkInformationVector* outputVector);

/// Points [Begin, End) of Total: piece p of n gets the p-th of n
/// consecutive ranges (as the text reader does).
struct PieceRange
{
  std::uint64_t Begin = 0;
  std::uint64_t End = 0;
};
PieceRange RequestedPiece(vtkInformation* outInfo, std::uint64_t total);

/// One vertex cell per point of output, so that the cloud renders.
void AddVertexCells(vtkPolyData* output, vtkIdType count);

/// A new array of the VTK type (VTK_DOUBLE, ...) with count tuples.
vtkSmartPointer<vtkDataArray> NewArray(int vtkType,
  const char* name,
  int components,
  vtkIdType count);

/**
 * Field data from the (name, value text) pairs a file kept
 * (PointCloudWriterSupport.h's FieldTextsOf): a value of numbers ("12",
 * "0.5 1 2") a double array of one tuple, other text a string array; the
 * texts of pairs that share a name are the values of one string array, in
 * order.
 */
void AddFieldTexts(const std::vector<std::pair<std::string, std::string>>& fields,
  vtkFieldData* fieldData);

} // namespace readers
} // namespace pcurv

#endif
