# The libraries that ParaView 5.11's Qt components (pqComponents and the
# VTK modules under it) name in their link interfaces, found here: Debian's
# ParaView package finds them only for the modules a project asks for by
# name, so linking pqComponents fails with "X11::X11 ... target was not
# found" otherwise. Sets pcurv_gui_dependencies_found.
#   Debian: qtbase5-dev qttools5-dev libqt5opengl5-dev libglew-dev
#           libxml2-dev libnetcdf-dev libhdf5-dev (libx11-dev, libboost-dev)
set(pcurv_vtk_find_modules "${ParaView_DIR}/vtk")
list(APPEND CMAKE_MODULE_PATH "${pcurv_vtk_find_modules}")
set(pcurv_gui_dependencies_found ON)
find_package(Qt5 QUIET COMPONENTS Widgets OpenGL)
foreach (package X11 GLEW LibXml2 NetCDF Boost)
  find_package(${package} QUIET)
  if (NOT ${package}_FOUND)
    set(pcurv_gui_dependencies_found OFF)
    message(STATUS "GUI part: ${package} not found")
  endif ()
endforeach ()
find_package(HDF5 QUIET COMPONENTS C HL)
if (NOT Qt5_FOUND OR NOT HDF5_FOUND)
  set(pcurv_gui_dependencies_found OFF)
  message(STATUS "GUI part: Qt5 (Widgets, OpenGL) or HDF5 not found")
endif ()
list(REMOVE_ITEM CMAKE_MODULE_PATH "${pcurv_vtk_find_modules}")
