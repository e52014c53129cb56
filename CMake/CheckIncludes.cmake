# The import rules of every folder of the product, checked when CMake
# configures it, so that an include that runs the wrong way fails the build:
# - a header of a product folder is included by its folder's name
#   ("Fits/OrientedCircleFit.h", in quotes or angle brackets), and only
#   from the folder itself or from a folder that declares it among what it
#   may import;
# - in the VTK-free libraries, no VTK header (they do not link VTK), and a
#   header without a folder is one of the including file's own folder (the
#   VTK side also includes VTK's, Qt's and ParaView's headers that way).
#
# pcurv_check_includes(<folder path> <folder name> [VTK] ALLOWED <names>...
#   FILES <files>...)
#
# As a script, cmake -DFOLDER=<path> -P CheckIncludes.cmake checks that no
# source or header under <path> includes a VTK header (the CoreHasNoVtk test).

if (CMAKE_SCRIPT_MODE_FILE)
  cmake_policy(VERSION 3.13) # IN_LIST in the functions below, as in the project
endif ()

# Every folder whose headers are checked: the core's libraries, the file
# formats and the VTK side.
set(PCURV_LIBRARY_FOLDERS
  Settings Common Kernels Neighbors Cloud Fits Scale Normals Outliers Estimation Lines
  FileFormats Filters IO Plugin)

function (pcurv_vtk_includes_in folder out)
  set(offenders "")
  foreach (file IN LISTS ARGN)
    file(STRINGS "${folder}/${file}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]([^>\"]*/)?vtk")
    foreach (line IN LISTS lines)
      string(STRIP "${line}" line)
      list(APPEND offenders "${file}: ${line}")
    endforeach ()
  endforeach ()
  set(${out} "${offenders}" PARENT_SCOPE)
endfunction ()

# The includes of `file` (under `folder`) that break the rule, appended to
# the list named `out`.
function (pcurv_wrong_includes folder file name vtk allowed out)
  set(wrong "${${out}}")
  get_filename_component(directory "${folder}/${file}" DIRECTORY)
  file(STRINGS "${folder}/${file}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
  foreach (line IN LISTS lines)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*([<\"])([^>\"]*)[>\"].*" "\\1;\\2" parts "${line}")
    list(GET parts 0 bracket)
    list(GET parts 1 included)
    if (included MATCHES "^([^/]+)/")
      set(imported "${CMAKE_MATCH_1}")
      if (imported IN_LIST PCURV_LIBRARY_FOLDERS AND NOT imported STREQUAL name
          AND NOT imported IN_LIST allowed)
        list(APPEND wrong "${file} includes ${included}: ${name} may import only ${allowed}")
      endif ()
    elseif (bracket STREQUAL "\"" AND NOT vtk AND NOT EXISTS "${directory}/${included}")
      list(APPEND wrong "${file} includes ${included}: name another folder's header with its folder")
    endif ()
  endforeach ()
  set(${out} "${wrong}" PARENT_SCOPE)
endfunction ()

function (pcurv_check_includes folder name)
  cmake_parse_arguments(PARSE_ARGV 2 arg "VTK" "" "ALLOWED;FILES")
  if (NOT arg_VTK)
    pcurv_vtk_includes_in("${folder}" offenders ${arg_FILES})
    if (offenders)
      list(JOIN offenders "\n  " listing)
      message(FATAL_ERROR "The VTK-free library ${name} must not include VTK headers:\n  ${listing}")
    endif ()
  endif ()
  set(wrong "")
  foreach (file IN LISTS arg_FILES)
    pcurv_wrong_includes("${folder}" "${file}" ${name} "${arg_VTK}" "${arg_ALLOWED}" wrong)
  endforeach ()
  if (wrong)
    list(JOIN wrong "\n  " listing)
    message(FATAL_ERROR "An include runs the wrong way in ${name}:\n  ${listing}")
  endif ()
endfunction ()

# The sources and headers under `folder` (relative paths), for the VTK
# side's folders, whose files are listed by VTK's and ParaView's functions.
function (pcurv_sources_under folder out)
  file(GLOB_RECURSE files RELATIVE "${folder}" "${folder}/*.h" "${folder}/*.cxx" "${folder}/*.inc")
  set(${out} "${files}" PARENT_SCOPE)
endfunction ()

if (CMAKE_SCRIPT_MODE_FILE AND DEFINED FOLDER)
  file(GLOB_RECURSE files RELATIVE "${FOLDER}" "${FOLDER}/*.h" "${FOLDER}/*.cxx" "${FOLDER}/*.inc")
  if (NOT files)
    message(FATAL_ERROR "No source files found in ${FOLDER}")
  endif ()
  pcurv_vtk_includes_in("${FOLDER}" offenders ${files})
  if (offenders)
    list(JOIN offenders "\n  " listing)
    message(FATAL_ERROR "The VTK-free libraries must not include VTK headers:\n  ${listing}")
  endif ()
  list(LENGTH files count)
  message(STATUS "${count} files, none includes a VTK header")
endif ()

# As a script with -DSELF_TEST_DIR=<empty folder>: writes includes that
# break the rule and includes that keep it into small files there, and
# fails unless exactly the breaking ones are reported (the ImportRules test).
if (CMAKE_SCRIPT_MODE_FILE AND DEFINED SELF_TEST_DIR)
  file(REMOVE_RECURSE "${SELF_TEST_DIR}")
  file(WRITE "${SELF_TEST_DIR}/Fits/Own.h" "")
  file(WRITE "${SELF_TEST_DIR}/Plugin/Gui/Own.h" "")
  # name | VTK side (VTK or -) | allowed imports | include line | whether it
  # breaks the rule
  set(cases
    "Fits|-|Common|#include \"Lines/LineTypes.h\"|1"
    "Fits|-|Common|#include <Lines/LineTypes.h>|1"
    "Fits|-|Common|  #  include \"Outliers/SurfaceOutliers.h\"|1"
    "Fits|-|Common|#include \"Common/Hash.h\"|0"
    "Fits|-|Common|#include <Common/Hash.h>|0"
    "Fits|-|Common|#include <vector>|0"
    "Fits|-|Common|#include <Eigen/Dense>|0"
    "Fits|-|Common|#include \"Own.h\"|0"
    "Fits|-|Common|#include \"Elsewhere.h\"|1"
    "Plugin|VTK|Filters,Estimation|#include \"Normals/NormalSettings.h\"|1"
    "Plugin|VTK|Filters,Estimation|#include \"Estimation/ShapeClass.h\"|0"
    "Plugin|VTK|Filters,Estimation|#include \"pqApplicationCore.h\"|0"
    "Plugin|VTK|Filters,Estimation|#include <IO/vtkLASPointCloudReader.h>|1")
  set(failures "")
  set(index 0)
  foreach (case IN LISTS cases)
    string(REPLACE "|" ";" fields "${case}")
    list(GET fields 0 name)
    list(GET fields 1 vtk)
    list(GET fields 2 allowed)
    list(GET fields 3 line)
    list(GET fields 4 breaks)
    string(REPLACE "," ";" allowed "${allowed}")
    if (vtk STREQUAL "-")
      set(vtk "")
    endif ()
    set(file "${name}/Case${index}.cxx")
    if (name STREQUAL "Plugin")
      set(file "Plugin/Gui/Case${index}.cxx")
    endif ()
    file(WRITE "${SELF_TEST_DIR}/${file}" "${line}\n")
    string(REGEX MATCH "^[^/]+/(.*)$" matched "${file}")
    set(relative "${CMAKE_MATCH_1}")
    set(wrong "")
    pcurv_wrong_includes("${SELF_TEST_DIR}/${name}" "${relative}" ${name} "${vtk}" "${allowed}" wrong)
    set(reported 0)
    if (wrong)
      set(reported 1)
    endif ()
    if (NOT reported EQUAL breaks)
      list(APPEND failures "${name}: '${line}' reported ${reported}, expected ${breaks}")
    endif ()
    math(EXPR index "${index} + 1")
  endforeach ()
  if (failures)
    list(JOIN failures "\n  " listing)
    message(FATAL_ERROR "The import check misjudged:\n  ${listing}")
  endif ()
  list(LENGTH cases count)
  message(STATUS "${count} includes judged as the rule says")
endif ()
