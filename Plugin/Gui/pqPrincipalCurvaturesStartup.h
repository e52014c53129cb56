/**
 * @class pqPrincipalCurvaturesStartup
 * @brief The plugin's GUI part, started when ParaView's GUI loads the
 * plugin: Abort that stops the filters (pqCloudFilterAbortBehavior), a
 * color map per view and array (pqCloudColorMapBehavior), readers' outputs
 * shown in true colors and in view (pqCloudReaderDisplayBehavior), the
 * plugin's readers as File > Open's defaults for point cloud files
 * (pqPointCloudReaderDefaults).
 * pvpython and pvbatch
 * do not start it.
 */
#ifndef pqPrincipalCurvaturesStartup_h
#define pqPrincipalCurvaturesStartup_h

#include <QObject>

class pqPrincipalCurvaturesStartup : public QObject
{
  Q_OBJECT
public:
  explicit pqPrincipalCurvaturesStartup(QObject* parent = nullptr);
  void startup();
  void shutdown() {}
};

#endif
