#include "pqCloudFilterAbortBehavior.h"

#include "CloudFilterNames.h"

#include "pqApplicationCore.h"
#include "pqCoreUtilities.h"
#include "pqPipelineSource.h"
#include "pqProgressManager.h"
#include "pqServer.h"
#include "pqServerManagerModel.h"
#include "vtkAlgorithm.h"
#include "vtkCommand.h"
#include "vtkSMProxy.h"

#include <QAbstractButton>
#include <QApplication>
#include <QMouseEvent>

namespace
{
/// Often enough for a click to act at once, seldom enough to cost nothing
/// (the filter reports ten times a second).
constexpr qint64 EventIntervalMilliseconds = 40;

/// The status bar's Abort button: pqStatusBar lists it, with the progress
/// bar, among the progress manager's non-blockable objects.
QAbstractButton* FindAbortButton(pqProgressManager* progress)
{
  for (const QPointer<QObject>& object : progress->nonBlockableObjects())
  {
    if (auto* button = qobject_cast<QAbstractButton*>(object.data()))
    {
      return button;
    }
  }
  return nullptr;
}

bool IsPress(const QEvent* event)
{
  switch (event->type())
  {
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonDblClick:
    case QEvent::KeyPress:
    case QEvent::ShortcutOverride:
    case QEvent::Wheel:
      return true;
    default:
      return false;
  }
}
} // namespace

pqCloudFilterAbortBehavior::pqCloudFilterAbortBehavior(QObject* parent)
  : QObject(parent)
{
  pqApplicationCore* core = pqApplicationCore::instance();
  QObject::connect(core->getServerManagerModel(),
    &pqServerManagerModel::sourceAdded,
    this,
    &pqCloudFilterAbortBehavior::watch);
  QObject::connect(core->getProgressManager(),
    &pqProgressManager::abort,
    this,
    &pqCloudFilterAbortBehavior::abortRunningFilter);
  this->SinceEventsHandled.start();
}

void pqCloudFilterAbortBehavior::watch(pqPipelineSource* source)
{
  // Only a filter in this process can be stopped from here, and only there
  // may the GUI handle events while it runs.
  if (!source || !source->getServer() || source->getServer()->isRemote() ||
    !pcurv::IsCloudFilter(source->getProxy()))
  {
    return;
  }
  auto* algorithm = vtkAlgorithm::SafeDownCast(source->getProxy()->GetClientSideObject());
  if (!algorithm)
  {
    return;
  }
  pqCoreUtilities::connect(
    algorithm, vtkCommand::ProgressEvent, this, SLOT(onFilterProgress(vtkObject*)));
  pqCoreUtilities::connect(algorithm, vtkCommand::EndEvent, this, SLOT(onFilterEnd(vtkObject*)));
}

void pqCloudFilterAbortBehavior::onFilterProgress(vtkObject* object)
{
  auto* algorithm = vtkAlgorithm::SafeDownCast(object);
  if (!algorithm)
  {
    return;
  }
  if (this->Running != algorithm)
  {
    this->Running = algorithm;
    pqApplicationCore::instance()->getProgressManager()->setEnableAbort(true);
  }
  if (this->SinceEventsHandled.elapsed() >= EventIntervalMilliseconds)
  {
    this->handleEventsForAbort();
    this->SinceEventsHandled.restart();
  }
}

void pqCloudFilterAbortBehavior::handleEventsForAbort()
{
  pqProgressManager* progress = pqApplicationCore::instance()->getProgressManager();
  this->AbortButton = FindAbortButton(progress);
  if (!this->AbortButton)
  {
    return;
  }
  // This filter does the blocking (see the class documentation): the
  // manager's own would drop the click before it reaches the button.
  const bool wasUnblocked = progress->unblockEvents(true);
  qApp->installEventFilter(this);
  QCoreApplication::processEvents();
  qApp->removeEventFilter(this);
  progress->unblockEvents(wasUnblocked);
}

bool pqCloudFilterAbortBehavior::eventFilter(QObject* watched, QEvent* event)
{
  if (!IsPress(event))
  {
    return QObject::eventFilter(watched, event);
  }
  const auto* mouse = dynamic_cast<const QMouseEvent*>(event);
  const bool onAbortButton = mouse && this->AbortButton &&
    this->AbortButton->rect().contains(this->AbortButton->mapFromGlobal(mouse->globalPos()));
  return !onAbortButton;
}

void pqCloudFilterAbortBehavior::onFilterEnd(vtkObject* object)
{
  if (this->Running && this->Running == object)
  {
    this->Running = nullptr;
    pqApplicationCore::instance()->getProgressManager()->setEnableAbort(false);
  }
}

void pqCloudFilterAbortBehavior::abortRunningFilter()
{
  if (this->Running)
  {
    // With the time of the abort, so that the pipeline runs the filter
    // again at the next Apply instead of keeping the empty output.
    this->Running->SetAbortExecuteAndUpdateTime();
  }
}
