#include "pqPointCloudReaderDefaults.h"

#include "pqActiveObjects.h"
#include "pqApplicationCore.h"
#include "pqPluginManager.h"
#include "pqServer.h"
#include "pqServerManagerModel.h"
#include "vtkNew.h"
#include "vtkPVXMLElement.h"
#include "vtkSMNamedPropertyIterator.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxy.h"
#include "vtkSMProxyManager.h"
#include "vtkSMReaderFactory.h"
#include "vtkSMSessionProxyManager.h"
#include "vtkSMSettings.h"
#include "vtkSMStringVectorProperty.h"

#include <QCoreApplication>

#include <algorithm>
#include <cctype>
#include <sstream>

namespace
{
// A proxy of the "sources" group (PointCloudReaders.xml) and its
// ReaderFactory file_description.
struct ReaderDefault
{
  const char* Pattern;
  const char* Description;
  const char* Reader;
};

const ReaderDefault PointCloudReaders[] = {
  { "*.xyz", "Point cloud text files", "ASCIIPointCloudReader" },
  { "*.pts", "Point cloud text files", "ASCIIPointCloudReader" },
  { "*.pwn", "Point cloud text files", "ASCIIPointCloudReader" },
  { "*.las", "LAS lidar point files", "ALASPointCloudReader" },
  { "*.laz", "LAS lidar point files", "ALASPointCloudReader" },
};

// Triples (patterns separated by spaces, description, reader name), as
// pqLoadDataReaction writes and reads them; the settings proxy
// (RepresentedArrayListSettings) mirrors the setting.
const char* const ReaderDetails = ".settings.RepresentedArrayListSettings.ReaderDetails";

std::string lowerCase(std::string text)
{
  std::transform(text.begin(),
    text.end(),
    text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool hasDefaultFor(vtkSMSettings* settings, const std::string& pattern)
{
  const unsigned int count = settings->GetSettingNumberOfElements(ReaderDetails);
  for (unsigned int index = 0; index + 2 < count; index += 3)
  {
    std::istringstream patterns(settings->GetSettingAsString(ReaderDetails, index, ""));
    std::string each;
    while (patterns >> each)
    {
      if (lowerCase(each) == pattern)
      {
        return true;
      }
    }
  }
  return false;
}

vtkSMProxy* settingsProxy(pqServer* server)
{
  return server && server->proxyManager()
    ? server->proxyManager()->GetProxy("settings", "RepresentedArrayListSettings")
    : nullptr;
}

/// GDAL's raster reader lists .las among its extensions (ParaView's
/// ReaderFactory hint), so when ParaView picks a reader itself (a file
/// named on the command line), the reader factory asks GDAL whether it can
/// read the lidar file, and GDAL prints "ERROR 4: ... not recognized as a
/// supported file format". With this plugin loaded .las is lidar: the
/// extension is dropped from that hint for the session (the file can still
/// be opened with GDAL through "Open Data With...").
void dropGdalLasClaim(pqServer* server)
{
  vtkSMSessionProxyManager* pxm = server ? server->proxyManager() : nullptr;
  vtkSMProxy* gdal = pxm ? pxm->GetPrototypeProxy("sources", "GDALRasterReader") : nullptr;
  vtkPVXMLElement* hints = gdal ? gdal->GetHints() : nullptr;
  vtkPVXMLElement* factory = hints ? hints->FindNestedElementByName("ReaderFactory") : nullptr;
  const char* extensions = factory ? factory->GetAttribute("extensions") : nullptr;
  if (!extensions)
  {
    return;
  }
  std::istringstream all(extensions);
  std::string kept, each;
  bool claimed = false;
  while (all >> each)
  {
    if (lowerCase(each) == "las")
    {
      claimed = true;
    }
    else
    {
      kept += (kept.empty() ? "" : " ") + each;
    }
  }
  if (claimed)
  {
    factory->SetAttribute("extensions", kept.c_str());
    vtkSMProxyManager::GetProxyManager()->GetReaderFactory()->UpdateAvailableReaders();
  }
}

bool isEntry(const std::vector<std::string>& values, std::size_t first, const ReaderDefault& entry)
{
  return values[first] == entry.Pattern && values[first + 1] == entry.Description &&
    values[first + 2] == entry.Reader;
}
}

pqPointCloudReaderDefaults::pqPointCloudReaderDefaults(QObject* parent)
  : QObject(parent)
{
  pqServerManagerModel* model = pqApplicationCore::instance()->getServerManagerModel();
  QObject::connect(
    model, &pqServerManagerModel::serverAdded, this, &pqPointCloudReaderDefaults::addDefaults);
  // Loading a plugin rebuilds the reader factory's list.
  QObject::connect(pqApplicationCore::instance()->getPluginManager(),
    &pqPluginManager::pluginsUpdated,
    this,
    [] { dropGdalLasClaim(pqActiveObjects::instance().activeServer()); });
  QObject::connect(QCoreApplication::instance(),
    &QCoreApplication::aboutToQuit,
    this,
    &pqPointCloudReaderDefaults::removeDefaults);
  // The plugin may be loaded after the connection (a script's LoadPlugin).
  if (pqServer* server = pqActiveObjects::instance().activeServer())
  {
    this->addDefaults(server);
  }
}

void pqPointCloudReaderDefaults::addDefaults(pqServer* server)
{
  dropGdalLasClaim(server);
  vtkSMProxy* proxy = settingsProxy(server);
  if (!proxy)
  {
    return;
  }
  vtkSMSettings* settings = vtkSMSettings::GetInstance();
  for (const ReaderDefault& entry : PointCloudReaders)
  {
    if (hasDefaultFor(settings, entry.Pattern))
    {
      continue;
    }
    const unsigned int first = settings->GetSettingNumberOfElements(ReaderDetails);
    const char* values[] = { entry.Pattern, entry.Description, entry.Reader };
    for (unsigned int i = 0; i < 3; ++i)
    {
      settings->SetSetting(ReaderDetails, first + i, std::string(values[i]));
      vtkSMPropertyHelper(proxy, "ReaderDetails").Set(first + i, values[i]);
    }
  }
  proxy->UpdateVTKObjects();
}

void pqPointCloudReaderDefaults::removeDefaults()
{
  vtkSMProxy* proxy = settingsProxy(pqActiveObjects::instance().activeServer());
  auto* property =
    proxy ? vtkSMStringVectorProperty::SafeDownCast(proxy->GetProperty("ReaderDetails")) : nullptr;
  if (!property)
  {
    return;
  }
  const std::vector<std::string> values = property->GetElements();
  std::vector<std::string> kept;
  for (std::size_t first = 0; first + 2 < values.size(); first += 3)
  {
    const bool added = std::any_of(std::begin(PointCloudReaders),
      std::end(PointCloudReaders),
      [&](const ReaderDefault& entry) { return isEntry(values, first, entry); });
    if (!added)
    {
      kept.insert(kept.end(), values.begin() + first, values.begin() + first + 3);
    }
  }
  property->SetElements(kept);
  vtkNew<vtkSMNamedPropertyIterator> readerDetailsOnly;
  readerDetailsOnly->SetProxy(proxy);
  readerDetailsOnly->SetPropertyNames(std::vector<std::string>{ "ReaderDetails" });
  vtkSMSettings::GetInstance()->SetProxySettings(proxy, readerDetailsOnly);
}
