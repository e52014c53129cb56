# pcurv_check_no_vtk_includes(<folder> <file>...): a fatal error naming the
# file and line when one of the files includes a VTK header. Also usable as
# a script: cmake -DFOLDER=<folder> -P CheckNoVtkIncludes.cmake checks every
# source and header in the folder (the CoreHasNoVtk test).
function (pcurv_check_no_vtk_includes folder)
  set(offenders "")
  foreach (file IN LISTS ARGN)
    file(STRINGS "${folder}/${file}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]([^>\"]*/)?vtk")
    foreach (line IN LISTS lines)
      string(STRIP "${line}" line)
      list(APPEND offenders "${file}: ${line}")
    endforeach ()
  endforeach ()
  if (offenders)
    list(JOIN offenders "\n  " listing)
    message(FATAL_ERROR "The numeric core must not include VTK headers:\n  ${listing}")
  endif ()
endfunction ()

if (CMAKE_SCRIPT_MODE_FILE AND DEFINED FOLDER)
  file(GLOB files RELATIVE "${FOLDER}" "${FOLDER}/*.h" "${FOLDER}/*.cxx" "${FOLDER}/*.inc")
  if (NOT files)
    message(FATAL_ERROR "No core files found in ${FOLDER}")
  endif ()
  pcurv_check_no_vtk_includes("${FOLDER}" ${files})
  list(LENGTH files count)
  message(STATUS "${count} core files, none includes a VTK header")
endif ()
