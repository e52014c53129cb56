#include "pqPrincipalCurvaturesStartup.h"

#include "pqCloudColorMapBehavior.h"
#include "pqCloudFilterAbortBehavior.h"
#include "pqCloudReaderDisplayBehavior.h"
#include "pqPointCloudReaderDefaults.h"

pqPrincipalCurvaturesStartup::pqPrincipalCurvaturesStartup(QObject* parent)
  : QObject(parent)
{
}

void pqPrincipalCurvaturesStartup::startup()
{
  // Owned by this object, which ParaView keeps until the plugin unloads.
  new pqCloudFilterAbortBehavior(this);
  new pqCloudColorMapBehavior(this);
  new pqCloudReaderDisplayBehavior(this);
  new pqPointCloudReaderDefaults(this);
}
