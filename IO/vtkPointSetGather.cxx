#include "vtkPointSetGather.h"

#include "vtkAlgorithm.h"
#include "vtkAppendFilter.h"
#include "vtkAppendPolyData.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"

#include <cstring>

vtkStandardNewMacro(vtkPointSetGather);

namespace
{

/// Whether every input is a polydata (then appended as one).
bool AllPolyData(vtkInformationVector* inputs)
{
  for (int i = 0; i < inputs->GetNumberOfInformationObjects(); ++i)
  {
    if (!vtkPolyData::GetData(inputs, i))
    {
      return false;
    }
  }
  return true;
}

} // namespace

//------------------------------------------------------------------------------
int vtkPointSetGather::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkPointSetGather::RequestDataObject(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkInformationVector* inputs = inputVector[0];
  vtkPointSet* first = vtkPointSet::GetData(inputs, 0);
  if (!first)
  {
    return 0;
  }
  vtkSmartPointer<vtkPointSet> output;
  if (inputs->GetNumberOfInformationObjects() == 1)
  {
    output.TakeReference(first->NewInstance());
  }
  else if (AllPolyData(inputs))
  {
    output = vtkSmartPointer<vtkPolyData>::New();
  }
  else
  {
    output = vtkSmartPointer<vtkUnstructuredGrid>::New();
  }
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkDataObject* existing = outInfo->Get(vtkDataObject::DATA_OBJECT());
  if (!existing || std::strcmp(existing->GetClassName(), output->GetClassName()) != 0)
  {
    outInfo->Set(vtkDataObject::DATA_OBJECT(), output);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkPointSetGather::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkInformationVector* inputs = inputVector[0];
  vtkPointSet* output = vtkPointSet::GetData(outputVector, 0);
  vtkPointSet* first = vtkPointSet::GetData(inputs, 0);
  if (!output || !first)
  {
    return 0;
  }
  if (inputs->GetNumberOfInformationObjects() == 1)
  {
    output->ShallowCopy(first);
    return 1;
  }
  vtkSmartPointer<vtkAlgorithm> append;
  if (vtkPolyData::SafeDownCast(output))
  {
    append = vtkSmartPointer<vtkAppendPolyData>::New();
  }
  else
  {
    append = vtkSmartPointer<vtkAppendFilter>::New();
  }
  for (int i = 0; i < inputs->GetNumberOfInformationObjects(); ++i)
  {
    append->AddInputDataObject(vtkPointSet::GetData(inputs, i));
  }
  append->Update();
  output->ShallowCopy(append->GetOutputDataObject(0));
  output->GetFieldData()->ShallowCopy(first->GetFieldData());
  return 1;
}

//------------------------------------------------------------------------------
void vtkPointSetGather::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
