#include "pqCloudReaderDisplayBehavior.h"

#include "CloudFilterNames.h"

#include "pqApplicationCore.h"
#include "pqDataRepresentation.h"
#include "pqServerManagerModel.h"
#include "pqView.h"
#include "vtkBoundingBox.h"
#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkPVArrayInformation.h"
#include "vtkPVDataInformation.h"
#include "vtkSMPVRepresentationProxy.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMRenderViewProxy.h"
#include "vtkWeakPointer.h"

#include <QPointer>
#include <QTimer>

#include <cmath>

namespace
{
/// Colored by 8-bit colors: 3 (RGB) or 4 (RGBA) unsigned-char components,
/// which VTK shows as they are when Map Scalars is off.
bool ColoredByEightBitColors(vtkSMProxy* display)
{
  if (!vtkSMPVRepresentationProxy::GetUsingScalarColoring(display))
  {
    return false;
  }
  vtkPVArrayInformation* info =
    vtkSMPVRepresentationProxy::GetArrayInformationForColorArray(display);
  return info && info->GetDataType() == VTK_UNSIGNED_CHAR &&
    (info->GetNumberOfComponents() == 3 || info->GetNumberOfComponents() == 4);
}

/// Colored by 8-bit colors that are the same at every point (a scan whose
/// Red, Green and Blue fields were never filled, all 0): they show nothing.
bool ColoredByConstantColors(vtkSMProxy* display)
{
  vtkPVArrayInformation* info =
    vtkSMPVRepresentationProxy::GetArrayInformationForColorArray(display);
  for (int component = 0; info && component < info->GetNumberOfComponents(); ++component)
  {
    const double* range = info->GetComponentRange(component);
    if (range[0] != range[1])
    {
      return false;
    }
  }
  return info != nullptr;
}

/// Map Scalars off while the display is colored by 8-bit colors (its own
/// colors), on while it is colored by anything else (through the color
/// map: with Map Scalars off VTK would take a classification or a
/// curvature as gray levels or black). True when the display shows true
/// colors.
bool MapScalarsUnlessColors(vtkSMProxy* display)
{
  if (!display->GetProperty("MapScalars"))
  {
    return false;
  }
  const bool colors = ColoredByEightBitColors(display);
  vtkSMPropertyHelper mapScalars(display, "MapScalars");
  if (mapScalars.GetAsInt() != (colors ? 0 : 1))
  {
    mapScalars.Set(colors ? 0 : 1);
    display->UpdateVTKObjects();
  }
  return colors;
}

/// No scalar bar for a display in true colors: it would describe a map
/// that is not used.
void HideUnusedScalarBar(vtkSMProxy* display, pqView* view)
{
  if (display && view && vtkSMPropertyHelper(display, "MapScalars").GetAsInt() == 0 &&
    vtkSMPVRepresentationProxy::IsScalarBarVisible(display, view->getProxy()))
  {
    vtkSMPVRepresentationProxy::SetScalarBarVisibility(display, view->getProxy(), false);
    view->render();
  }
}

/// Map Scalars after the display's colored array changed (by the toolbar,
/// the Properties panel or Python), and the view drawn again.
void FollowColorArray(pqDataRepresentation* display)
{
  if (!display)
  {
    return;
  }
  if (MapScalarsUnlessColors(display->getProxy()))
  {
    HideUnusedScalarBar(display->getProxy(), display->getView());
  }
  display->renderViewEventually();
}

/// Every corner of `bounds` projects inside the view's window (depth aside:
/// ParaView fits the clipping range to the data at each render).
bool WhollyInView(vtkSMRenderViewProxy* view, const double bounds[6])
{
  int size[2] = { 1, 1 };
  vtkSMPropertyHelper(view, "ViewSize").Get(size, 2);
  const double aspect = size[1] > 0 ? static_cast<double>(size[0]) / size[1] : 1.0;
  vtkMatrix4x4* projection =
    view->GetActiveCamera()->GetCompositeProjectionTransformMatrix(aspect, -1, 1);
  for (int corner = 0; corner < 8; ++corner)
  {
    const double point[4] = {
      bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)], bounds[4 + ((corner >> 2) & 1)], 1.0
    };
    double clip[4];
    projection->MultiplyPoint(point, clip);
    if (!(clip[3] > 0.0) || std::fabs(clip[0]) > clip[3] || std::fabs(clip[1]) > clip[3])
    {
      return false;
    }
  }
  return true;
}

/// The bounds of every visible display in the view (the new one included).
vtkBoundingBox VisibleBounds(pqView* view)
{
  vtkBoundingBox box;
  for (pqRepresentation* representation : view->getRepresentations())
  {
    auto* data = qobject_cast<pqDataRepresentation*>(representation);
    vtkPVDataInformation* info =
      data && data->isVisible() ? data->getInputDataInformation() : nullptr;
    if (info && vtkMath::AreBoundsInitialized(info->GetBounds()))
    {
      box.AddBounds(info->GetBounds());
    }
  }
  return box;
}

void BringIntoView(pqDataRepresentation* display)
{
  pqView* view = display->getView();
  auto* renderView = view ? vtkSMRenderViewProxy::SafeDownCast(view->getProxy()) : nullptr;
  vtkPVDataInformation* info = display->getInputDataInformation();
  if (!renderView || !info || !vtkMath::AreBoundsInitialized(info->GetBounds()) ||
    WhollyInView(renderView, info->GetBounds()))
  {
    return;
  }
  const vtkBoundingBox visible = VisibleBounds(view);
  double bounds[6];
  visible.GetBounds(bounds);
  renderView->ResetCamera(bounds);
  view->render();
}
} // namespace

pqCloudReaderDisplayBehavior::pqCloudReaderDisplayBehavior(QObject* parent)
  : QObject(parent)
{
  pqServerManagerModel* model = pqApplicationCore::instance()->getServerManagerModel();
  QObject::connect(
    model, &pqServerManagerModel::viewAdded, this, &pqCloudReaderDisplayBehavior::watchView);
  // The GUI's first view exists before the plugin is loaded.
  for (pqView* view : model->findItems<pqView*>())
  {
    this->watchView(view);
  }
}

void pqCloudReaderDisplayBehavior::watchView(pqView* view)
{
  // A view reports a display once it is added to it: shown, colored, its
  // reader's output up to date.
  QObject::connect(
    view, &pqView::representationAdded, this, &pqCloudReaderDisplayBehavior::startDisplay);
}

void pqCloudReaderDisplayBehavior::startDisplay(pqRepresentation* representation)
{
  auto* display = qobject_cast<pqDataRepresentation*>(representation);
  vtkSMProxy* proxy = display ? display->getProxy() : nullptr;
  if (!proxy || !proxy->GetProperty("Input") || pqApplicationCore::instance()->isLoadingState() ||
    !pcurv::IsCloudReader(vtkSMPropertyHelper(proxy, "Input").GetAsProxy()))
  {
    return;
  }
  if (ColoredByEightBitColors(proxy) && ColoredByConstantColors(proxy))
  {
    vtkSMPVRepresentationProxy::SetScalarColoring(proxy, nullptr, 0);
    proxy->UpdateVTKObjects();
  }
  QPointer<pqDataRepresentation> watched(display);
  QObject::connect(display,
    &pqDataRepresentation::colorArrayNameModified,
    this,
    [watched]() { FollowColorArray(watched); });
  if (MapScalarsUnlessColors(proxy))
  {
    // The Apply that made the display shows its scalar bar after this
    // (pqApplyBehavior): hidden once the Apply is over.
    HideUnusedScalarBar(proxy, display->getView());
    vtkWeakPointer<vtkSMProxy> weakDisplay(proxy);
    QPointer<pqView> view(display->getView());
    QTimer::singleShot(0, this, [weakDisplay, view]() { HideUnusedScalarBar(weakDisplay, view); });
  }
  BringIntoView(display);
}
