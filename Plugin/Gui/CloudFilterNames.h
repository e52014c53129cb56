/**
 * @file CloudFilterNames.h
 * @brief Which proxies are this plugin's filters and readers, for the GUI
 * behaviors.
 */
#ifndef CloudFilterNames_h
#define CloudFilterNames_h

#include "vtkSMProxy.h"

#include <cstring>

namespace pcurv
{

/// The plugin's filters (Plugin/PrincipalCurvatures.xml): the curvatures
/// and the normals alone.
inline bool IsCloudFilter(vtkSMProxy* proxy)
{
  const char* name = proxy ? proxy->GetXMLName() : nullptr;
  return name &&
    (std::strcmp(name, "PrincipalCurvatureEstimation") == 0 ||
      std::strcmp(name, "PointCloudNormalEstimation") == 0);
}

/// The plugin's Curvature Lines filter (Plugin/CurvatureLines.xml).
inline bool IsCurvatureLines(vtkSMProxy* proxy)
{
  const char* name = proxy ? proxy->GetXMLName() : nullptr;
  return name && std::strcmp(name, "CurvatureLines") == 0;
}

/// The plugin's readers (Plugin/PointCloudReaders.xml).
inline bool IsCloudReader(vtkSMProxy* proxy)
{
  const char* name = proxy ? proxy->GetXMLName() : nullptr;
  const char* const readers[] = {
    "ASCIIPointCloudReader", "ALASPointCloudReader", "APLYPointCloudReader", "OFFMeshReader"
  };
  for (const char* reader : readers)
  {
    if (name && std::strcmp(name, reader) == 0)
    {
      return true;
    }
  }
  return false;
}

} // namespace pcurv

#endif
