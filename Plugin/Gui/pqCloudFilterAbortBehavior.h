/**
 * @class pqCloudFilterAbortBehavior
 * @brief Makes the status bar's Abort button stop this plugin's filters in
 * ParaView 5.11's GUI.
 *
 * ParaView 5.11 never enables that button, nothing listens to its click,
 * and the GUI handles no input while a filter runs (the progress bar is
 * only repainted), so a click waits until the run is over. While one of
 * this plugin's filters runs in the GUI's own process (the builtin
 * session), this behavior enables the button, lets the GUI handle events
 * at the filter's progress events, passing mouse and key presses to the
 * Abort button alone, and on Abort sets the filter's abort flag, which the
 * filter reads at its next progress pass (a tenth of a second) before
 * stopping its threads. ParaView 5.12 does much the same for every filter.
 * (pqProgressManager's own blocking cannot be used: it lets presses through
 * only when they are sent to the button itself, but Qt sends a click to the
 * window first, so 5.11 drops it there.)
 */
#ifndef pqCloudFilterAbortBehavior_h
#define pqCloudFilterAbortBehavior_h

#include <QElapsedTimer>
#include <QObject>

#include "vtkWeakPointer.h"

class QAbstractButton;
class pqPipelineSource;
class vtkAlgorithm;
class vtkObject;

class pqCloudFilterAbortBehavior : public QObject
{
  Q_OBJECT
public:
  explicit pqCloudFilterAbortBehavior(QObject* parent = nullptr);

protected:
  /// While events are handled during a run: drops every press but those
  /// on the Abort button.
  bool eventFilter(QObject* watched, QEvent* event) override;

private Q_SLOTS:
  /// Listens to the filter's progress when `source` is one of this plugin's
  /// filters executing in this process.
  void watch(pqPipelineSource* source);
  void onFilterProgress(vtkObject* algorithm);
  void onFilterEnd(vtkObject* algorithm);
  /// The Abort button's click (pqProgressManager::abort).
  void abortRunningFilter();

private:
  /// Paints, and a click on the Abort button.
  void handleEventsForAbort();

  vtkWeakPointer<vtkAlgorithm> Running;
  QAbstractButton* AbortButton = nullptr;
  /// Events are handled at most every few hundredths of a second.
  QElapsedTimer SinceEventsHandled;
};

#endif
