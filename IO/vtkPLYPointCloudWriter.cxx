#include "vtkPLYPointCloudWriter.h"

#include "FileFormats/PlyWriter.h"
#include "PointCloudWriterSupport.h"

#include "vtkAlgorithm.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkPLYPointCloudWriter);

//------------------------------------------------------------------------------
vtkPLYPointCloudWriter::vtkPLYPointCloudWriter() = default;

//------------------------------------------------------------------------------
vtkPLYPointCloudWriter::~vtkPLYPointCloudWriter()
{
  this->SetFileName(nullptr);
  this->SetNormalsArray(nullptr);
}

//------------------------------------------------------------------------------
int vtkPLYPointCloudWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

//------------------------------------------------------------------------------
void vtkPLYPointCloudWriter::WriteData()
{
  const pcurv::ply::Format format =
    this->FileType == ASCII ? pcurv::ply::Format::Ascii : pcurv::ply::Format::BinaryLittleEndian;
  pcurv::writers::WriteOptions options;
  options.WithFaces = true;
  options.WithFieldData = true;
  options.PointsAsFloat = this->PointsAsFloat;
  options.NormalsArray = this->NormalsArray ? this->NormalsArray : "";
  this->SetErrorCode(pcurv::writers::WriteInput(this,
    this->FileName,
    options,
    [format](const char* fileName, pcurv::table::Cloud& cloud)
    { return pcurv::ply::WriteFile(fileName, cloud, format); }));
}

//------------------------------------------------------------------------------
void vtkPLYPointCloudWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "NormalsArray: " << (this->NormalsArray ? this->NormalsArray : "(none)") << "\n";
  os << indent << "PointsAsFloat: " << this->PointsAsFloat << "\n";
  os << indent << "FileType: " << (this->FileType == ASCII ? "ASCII" : "BINARY") << "\n";
}
