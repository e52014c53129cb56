/**
 * @class pqPointCloudReaderDefaults
 * @brief Makes File > Open read point cloud files with the plugin's readers
 * without asking: .xyz .pts .pwn with the Point Cloud Text Reader, .las
 * .laz with the LAS Point Cloud Reader.
 *
 * ParaView 5.11's File > Open (with its "Supported Files" filter) first
 * looks for the file's pattern in the default readers the user set ("Set
 * reader as default" in the reader dialog, the ReaderDetails setting);
 * without one, when several readers claim the extension, it asks, and for
 * .xyz it preselects PLOT3D, which cannot read a text cloud. This adds the
 * plugin's readers to those defaults, on every server connection, for each
 * pattern the user has not given a default of their own. .txt is left out
 * (CSV tables are .txt too), and so is .ply (a mesh wants the PLY Reader):
 * for them ParaView still asks.
 *
 * GDAL's raster reader also lists .las: ParaView then asks GDAL about
 * every .las named on its command line (which the defaults above do not
 * cover), and GDAL prints "not recognized as a supported file format".
 * The .las extension is taken out of that reader's hint for the session.
 *
 * ParaView saves the user's settings when it quits: the entries are taken
 * out again before (aboutToQuit), so that a ParaView started later without
 * the plugin does not look for its readers.
 */
#ifndef pqPointCloudReaderDefaults_h
#define pqPointCloudReaderDefaults_h

#include <QObject>

class pqServer;

class pqPointCloudReaderDefaults : public QObject
{
  Q_OBJECT
public:
  explicit pqPointCloudReaderDefaults(QObject* parent);

private Q_SLOTS:
  void addDefaults(pqServer* server);
  void removeDefaults();
};

#endif
