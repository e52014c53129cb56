#include "pqNormalsArraySelector.h"

#include "vtkSMArrayListDomain.h"
#include "vtkSMProperty.h"

#include <QAbstractItemModel>
#include <QComboBox>
#include <QIcon>
#include <QPixmap>

pqNormalsArraySelector::pqNormalsArraySelector(vtkSMProxy* proxy,
  vtkSMProperty* property,
  QWidget* parent)
  : Superclass(property, proxy, parent)
{
  auto* domain = property->FindDomain<vtkSMArrayListDomain>();
  this->NoneString = domain && domain->GetNoneString() ? domain->GetNoneString() : "";
  this->Choices = this->findChild<QComboBox*>();
  if (!this->Choices || this->NoneString.isEmpty())
  {
    return;
  }
  // Empty, and as large as the other entries' icons: the names stay aligned.
  QPixmap empty(this->Choices->iconSize());
  empty.fill(Qt::transparent);
  this->PlainIcon = QIcon(empty);
  QAbstractItemModel* model = this->Choices->model();
  auto plain = [this]() { this->PlainNoneEntry(); };
  this->connect(model, &QAbstractItemModel::rowsInserted, this, plain);
  this->connect(model, &QAbstractItemModel::modelReset, this, plain);
  this->connect(model, &QAbstractItemModel::dataChanged, this, plain);
  this->PlainNoneEntry();
}

void pqNormalsArraySelector::PlainNoneEntry()
{
  const int entry = this->Choices->findText(this->NoneString);
  if (entry < 0)
  {
    return;
  }
  // Setting the icon changes the model again: once is enough.
  if (this->Choices->itemIcon(entry).cacheKey() != this->PlainIcon.cacheKey())
  {
    this->Choices->setItemIcon(entry, this->PlainIcon);
  }
}
