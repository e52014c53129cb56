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
  this->SetErrorCode(pcurv::writers::WriteInput(this,
    this->FileName,
    false,
    [](const char* fileName, pcurv::table::Cloud& cloud)
    { return pcurv::csv::WriteFile(fileName, cloud); }));
}

//------------------------------------------------------------------------------
void vtkCSVPointCloudWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
