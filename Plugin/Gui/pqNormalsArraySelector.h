/**
 * @class pqNormalsArraySelector
 * @brief The Normals row of the Principal Curvatures panel: ParaView's
 * array selector, its "None (automatic)" entry without the red no-entry
 * icon.
 *
 * ParaView draws the entry a domain's none_string names with its cancel
 * icon, which reads as an error. Here it is the automatic choice (the
 * normals attribute if the input has one, estimated normals otherwise),
 * so it is drawn with an empty icon of the same size: the names stay
 * aligned and nothing looks wrong.
 */
#ifndef pqNormalsArraySelector_h
#define pqNormalsArraySelector_h

#include "pqArraySelectorPropertyWidget.h"

#include <QIcon>

class QComboBox;
class vtkSMProperty;
class vtkSMProxy;

class pqNormalsArraySelector : public pqArraySelectorPropertyWidget
{
  Q_OBJECT
  typedef pqArraySelectorPropertyWidget Superclass;

public:
  pqNormalsArraySelector(vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent = nullptr);

private:
  /// Replaces the icon of the none_string entry (ParaView sets it again
  /// whenever the input's arrays change the list).
  void PlainNoneEntry();

  QComboBox* Choices = nullptr;
  QString NoneString;
  QIcon PlainIcon;
};

#endif
