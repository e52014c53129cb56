#include "vtkCSVPointCloudWriter.h"

#include "FileFormats/CsvWriter.h"
#include "PointCloudWriterSupport.h"

#include "vtkAlgorithm.h"
#include "vtkInformation.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkCSVPointCloudWriter);

//------------------------------------------------------------------------------
vtkCSVPointCloudWriter::vtkCSVPointCloudWriter() = default;

//------------------------------------------------------------------------------
vtkCSVPointCloudWriter::~vtkCSVPointCloudWriter()
{
  this->SetFileName(nullptr);
  this->SetNormalsArray(nullptr);
}

//------------------------------------------------------------------------------
int vtkCSVPointCloudWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

//------------------------------------------------------------------------------
void vtkCSVPointCloudWriter::WriteData()
{
  pcurv::writers::WriteOptions options;
  options.PointsAsFloat = this->PointsAsFloat;
  options.NormalsArray = this->NormalsArray ? this->NormalsArray : "";
  options.WithFieldData = this->FieldDataComments;
  this->SetErrorCode(pcurv::writers::WriteInput(this,
    this->FileName,
    options,
    [](const char* fileName, pcurv::table::Cloud& cloud)
    { return pcurv::csv::WriteFile(fileName, cloud); }));
}

//------------------------------------------------------------------------------
void vtkCSVPointCloudWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "NormalsArray: " << (this->NormalsArray ? this->NormalsArray : "(none)") << "\n";
  os << indent << "PointsAsFloat: " << this->PointsAsFloat << "\n";
  os << indent << "FieldDataComments: " << this->FieldDataComments << "\n";
}
