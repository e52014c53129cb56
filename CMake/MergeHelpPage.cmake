# Adds a hand-written fragment to a help page that ParaView generated from a
# proxy's XML <Documentation> (paraview_client_documentation): the fragment
# goes after the description, before the generated settings table (or
# before </body> when there is none).
#   cmake -Dgenerated=PAGE -Dfragment=FRAGMENT -Doutput=OUT -P MergeHelpPage.cmake
# The generated page is overwritten by the merged one when the help is
# compiled; a fragment added before (between the markers) is replaced, so
# that running this again adds it once.
set(begin_marker "<!-- pcurv-help-fragment -->")
set(end_marker "<!-- pcurv-help-fragment-end -->")
file(READ "${generated}" page)
file(READ "${fragment}" extra)
# ParaView words an optional input array (the normals) as a requirement.
string(REGEX REPLACE "The dataset must contain a field array \\(point\\)[ \t\r\n]*with 3 component\\(s\\)\\."
  "Normals, if the dataset has them, are a point array of 3 components; they are estimated otherwise."
  page "${page}")
string(FIND "${page}" "${begin_marker}" previous_begin)
if (previous_begin GREATER_EQUAL 0)
  string(FIND "${page}" "${end_marker}" previous_end)
  string(LENGTH "${end_marker}" end_length)
  math(EXPR previous_end "${previous_end} + ${end_length}")
  string(SUBSTRING "${page}" 0 ${previous_begin} head)
  string(SUBSTRING "${page}" ${previous_end} -1 tail)
  set(page "${head}${tail}")
endif ()
string(FIND "${page}" "<table" anchor)
if (anchor LESS 0)
  string(FIND "${page}" "</body>" anchor)
endif ()
if (anchor LESS 0)
  message(FATAL_ERROR "${generated}: neither a <table nor a </body>")
endif ()
string(SUBSTRING "${page}" 0 ${anchor} head)
string(SUBSTRING "${page}" ${anchor} -1 tail)
file(WRITE "${output}" "${head}${begin_marker}\n${extra}${end_marker}\n${tail}")
