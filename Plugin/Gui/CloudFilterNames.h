/**
 * @file CloudFilterNames.h
 * @brief Which proxies are this plugin's filters, for the GUI behaviors.
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

} // namespace pcurv

#endif
