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

namespace
{
/// The color map of another visible display of the plugin's filters in the
/// same view, colored by the same array: the map the new display shares.
vtkSMProxy* MapOfSameArrayInView(pqRepresentation* representation,
  const std::string& arrayName,
  int association)
{
  pqView* view = representation->getView();
  if (!view)
  {
    return nullptr;
  }
  for (pqRepresentation* other : view->getRepresentations())
  {
    vtkSMProxy* proxy = other ? other->getProxy() : nullptr;
    if (!proxy || other == representation || !other->isVisible() ||
      !proxy->GetProperty("LookupTable") || !proxy->GetProperty("Input") ||
      !pcurv::IsCloudFilter(vtkSMPropertyHelper(proxy, "Input").GetAsProxy()))
    {
      continue;
    }
    vtkSMPropertyHelper colorArray(proxy, "ColorArrayName");
    const char* name = colorArray.GetInputArrayNameToProcess();
    if (name && arrayName == name && colorArray.GetInputArrayAssociation() == association)
    {
      return vtkSMPropertyHelper(proxy, "LookupTable").GetAsProxy();
    }
  }
  return nullptr;
}

/// Colors `display` with `map` (and its opacity function), and widens the
/// map to this display's range too.
void ShareMap(vtkSMProxy* display, vtkSMProxy* map)
{
  vtkSMPropertyHelper(display, "LookupTable").Set(map);
  if (display->GetProperty("ScalarOpacityFunction") && map->GetProperty("ScalarOpacityFunction"))
  {
    vtkSMPropertyHelper(display, "ScalarOpacityFunction")
      .Set(vtkSMPropertyHelper(map, "ScalarOpacityFunction").GetAsProxy());
  }
  display->UpdateVTKObjects();
  vtkSMPVRepresentationProxy::RescaleTransferFunctionToDataRange(
    display, /*extend=*/true, /*force=*/true);
}
} // namespace

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
  const int association = colorArray.GetInputArrayAssociation();
  if (vtkSMProxy* shared =
        arrayName.empty() ? nullptr : MapOfSameArrayInView(representation, arrayName, association))
  {
    ShareMap(display, shared);
  }
  else if (!arrayName.empty())
  {
    vtkSMPVRepresentationProxy::SetScalarColoring(
      display, arrayName.c_str(), colorArray.GetInputArrayAssociation());
    vtkSMPVRepresentationProxy::RescaleTransferFunctionToDataRange(
      display, /*extend=*/false, /*force=*/true);
  }
  display->UpdateVTKObjects();
}
