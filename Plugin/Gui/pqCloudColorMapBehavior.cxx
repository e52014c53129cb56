#include "pqCloudColorMapBehavior.h"

#include "CloudFilterNames.h"

#include "pqApplicationCore.h"
#include "pqRepresentation.h"
#include "pqServerManagerModel.h"
#include "pqView.h"
#include "vtkSMPVRepresentationProxy.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxy.h"

#include <string>

pqCloudColorMapBehavior::pqCloudColorMapBehavior(QObject* parent)
  : QObject(parent)
{
  pqServerManagerModel* model = pqApplicationCore::instance()->getServerManagerModel();
  QObject::connect(
    model, &pqServerManagerModel::viewAdded, this, &pqCloudColorMapBehavior::watchView);
  // The GUI's first view exists before the plugin is loaded.
  for (pqView* view : model->findItems<pqView*>())
  {
    this->watchView(view);
  }
}

void pqCloudColorMapBehavior::watchView(pqView* view)
{
  // A view reports a display once it is added to it, which ParaView does
  // after it has given the display the shared color map of its array.
  QObject::connect(
    view, &pqView::representationAdded, this, &pqCloudColorMapBehavior::giveOwnColorMap);
}

void pqCloudColorMapBehavior::giveOwnColorMap(pqRepresentation* representation)
{
  vtkSMProxy* display = representation ? representation->getProxy() : nullptr;
  if (!display || !display->GetProperty("UseSeparateColorMap") || !display->GetProperty("Input") ||
    pqApplicationCore::instance()->isLoadingState())
  {
    return;
  }
  if (!pcurv::IsCloudFilter(vtkSMPropertyHelper(display, "Input").GetAsProxy()))
  {
    return;
  }
  vtkSMPropertyHelper(display, "UseSeparateColorMap").Set(1);
  // The display is already colored (by the output's active scalars) with
  // the shared map: coloring again picks the display's own map, which is
  // then scaled to this output alone.
  vtkSMPropertyHelper colorArray(display, "ColorArrayName");
  const std::string arrayName =
    colorArray.GetInputArrayNameToProcess() ? colorArray.GetInputArrayNameToProcess() : "";
  if (!arrayName.empty())
  {
    vtkSMPVRepresentationProxy::SetScalarColoring(
      display, arrayName.c_str(), colorArray.GetInputArrayAssociation());
    vtkSMPVRepresentationProxy::RescaleTransferFunctionToDataRange(
      display, /*extend=*/false, /*force=*/true);
  }
  display->UpdateVTKObjects();
}
