# The import rules of the VTK-free libraries, checked when CMake configures
# them, so that an include that runs the wrong way fails the build:
# - no VTK header (the libraries do not link VTK);
# - a header of a library folder is included by its folder's name
#   ("Fits/OrientedCircleFit.h"), and only from the folder itself or from a
#   folder that declares it among what it may import;
# - a header without a folder is one of the including file's own folder.
#
# pcurv_check_includes(<folder path> <folder name> ALLOWED <names>... FILES <files>...)
#
# As a script, cmake -DFOLDER=<path> -P CheckIncludes.cmake checks that no
# source or header under <path> includes a VTK header (the CoreHasNoVtk test).

# Every folder whose headers are checked, and the VTK side's folders, which
# none of them may include.
set(PCURV_LIBRARY_FOLDERS
  Settings Common Kernels Neighbors Cloud Fits Scale Normals Estimation FileFormats
  Filters Readers Plugin)

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

function (pcurv_check_includes folder name)
  cmake_parse_arguments(PARSE_ARGV 2 arg "" "" "ALLOWED;FILES")
  pcurv_vtk_includes_in("${folder}" offenders ${arg_FILES})
  if (offenders)
    list(JOIN offenders "\n  " listing)
    message(FATAL_ERROR "The VTK-free library ${name} must not include VTK headers:\n  ${listing}")
  endif ()
  set(wrong "")
  foreach (file IN LISTS arg_FILES)
    file(STRINGS "${folder}/${file}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
    foreach (line IN LISTS lines)
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]*)\".*" "\\1" included "${line}")
      if (included MATCHES "^([^/]+)/")
        set(imported "${CMAKE_MATCH_1}")
        if (imported IN_LIST PCURV_LIBRARY_FOLDERS AND NOT imported STREQUAL name
            AND NOT imported IN_LIST arg_ALLOWED)
          list(APPEND wrong "${file} includes ${included}: ${name} may import only ${arg_ALLOWED}")
        endif ()
      elseif (NOT EXISTS "${folder}/${included}")
        list(APPEND wrong "${file} includes ${included}: name another folder's header with its folder")
      endif ()
    endforeach ()
  endforeach ()
  if (wrong)
    list(JOIN wrong "\n  " listing)
    message(FATAL_ERROR "An include runs the wrong way in ${name}:\n  ${listing}")
  endif ()
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
