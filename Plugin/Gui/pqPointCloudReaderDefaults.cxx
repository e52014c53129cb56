#include "pqPointCloudReaderDefaults.h"

#include "pqActiveObjects.h"
#include "pqApplicationCore.h"
#include "pqServer.h"
#include "pqServerManagerModel.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxyManager.h"
#include "vtkSMReaderFactory.h"
#include "vtkSMSessionProxyManager.h"
#include "vtkSMSettings.h"
#include "vtkSMSettingsProxy.h"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <string>
#include <vector>

namespace
{
struct ReaderDefault
{
  const char* Pattern;
  const char* Reader; // a proxy of the "sources" group, PointCloudReaders.xml
};

const ReaderDefault PointCloudReaders[] = { { "*.xyz", "ASCIIPointCloudReader" },
  { "*.pts", "ASCIIPointCloudReader" },
  { "*.pwn", "ASCIIPointCloudReader" },
  { "*.las", "ALASPointCloudReader" },
  { "*.laz", "ALASPointCloudReader" } };

// Triples (patterns separated by spaces, description, reader name), as
// pqLoadDataReaction writes and reads them.
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

std::string readerDescription(pqServer* server, const std::string& reader)
{
  vtkSMReaderFactory* factory = vtkSMProxyManager::GetProxyManager()->GetReaderFactory();
  for (const FileTypeDetailed& type : factory->GetSupportedFileTypesDetailed(server->session()))
  {
    if (type.Name == reader)
    {
      return type.Description;
    }
  }
  return reader;
}

// The settings proxy mirrors the setting; ParaView's settings dialog writes
// the proxy back, so both are kept the same (as pqLoadDataReaction does).
void appendDefault(pqServer* server, const std::vector<std::string>& entry)
{
  vtkSMSettings* settings = vtkSMSettings::GetInstance();
  const unsigned int first = settings->GetSettingNumberOfElements(ReaderDetails);
  vtkSMSettingsProxy* proxy = vtkSMSettingsProxy::SafeDownCast(
    server->proxyManager()->GetProxy("settings", "RepresentedArrayListSettings"));
  for (unsigned int i = 0; i < entry.size(); ++i)
  {
    settings->SetSetting(ReaderDetails, first + i, entry[i]);
    if (proxy)
    {
      vtkSMPropertyHelper(proxy, "ReaderDetails").Set(first + i, entry[i].c_str());
    }
  }
  if (proxy)
  {
    proxy->UpdateVTKObjects();
  }
}
}

pqPointCloudReaderDefaults::pqPointCloudReaderDefaults(QObject* parent)
  : QObject(parent)
{
  pqServerManagerModel* model = pqApplicationCore::instance()->getServerManagerModel();
  QObject::connect(
    model, &pqServerManagerModel::serverAdded, this, &pqPointCloudReaderDefaults::addDefaults);
  // The plugin may be loaded after the connection (a script's LoadPlugin).
  if (pqServer* server = pqActiveObjects::instance().activeServer())
  {
    this->addDefaults(server);
  }
}

void pqPointCloudReaderDefaults::addDefaults(pqServer* server)
{
  if (!server || !server->proxyManager())
  {
    return;
  }
  vtkSMSettings* settings = vtkSMSettings::GetInstance();
  for (const ReaderDefault& entry : PointCloudReaders)
  {
    if (!hasDefaultFor(settings, entry.Pattern))
    {
      appendDefault(
        server, { entry.Pattern, readerDescription(server, entry.Reader), entry.Reader });
    }
  }
}
