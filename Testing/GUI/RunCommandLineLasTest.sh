#!/usr/bin/env bash
# `paraview scan.las` with the plugin loaded at startup (its plugins XML in
# PV_PLUGIN_CONFIG_FILE), in the real GUI under Xvfb: the file must open
# with the LAS Point Cloud Reader, and the terminal must not show GDAL's
# "not recognized as a supported file format" (ParaView asks every reader
# that lists .las, GDAL's raster reader among them, whether it can read a
# file named on the command line). The file's entry in the pipeline
# browser is read by OCR (--script cannot be combined with a data file).
#   RunCommandLineLasTest.sh PARAVIEW PLUGINS_XML
set -u
paraview=$1 plugins_xml=$2
source "$(dirname "$0")/GuiHarness.sh"
gui_init
export PV_PLUGIN_CONFIG_FILE=$plugins_xml

# LAS 1.2, point format 0: a 20 x 20 grid of points.
/usr/bin/python3 - "$work/scan.las" <<'PYTHON'
import struct, sys
points = [(i, j, (i * j) % 7) for i in range(20) for j in range(20)]
header = bytearray(227)
header[0:4] = b"LASF"
header[24], header[25] = 1, 2
struct.pack_into("<HIIBHI", header, 94, 227, 227, 0, 0, 20, len(points))
struct.pack_into("<3d3d", header, 131, 0.01, 0.01, 0.01, 0.0, 0.0, 0.0)
struct.pack_into("<6d", header, 179, 19, 0, 19, 0, 6, 0)
records = b"".join(struct.pack("<3iHBBbBH", *(100 * c for c in p), 0, 0x09, 2, 0, 0, 0) for p in points)
with open(sys.argv[1], "wb") as handle:
    handle.write(bytes(header) + records)
PYTHON

# The pipeline browser (top left) of the screen, enlarged for OCR: holds
# the reader's entry once the file has opened.
browser_shows_scan() {
  gui_capture "$work/screen.png"
  convert "$work/screen.png" -crop 300x250+0+130 +repage -resize 300% -colorspace Gray "$work/browser.png"
  tesseract "$work/browser.png" - 2>/dev/null | grep -q "scan.las"
}
# No script to write a marker: the window's showing, then the file's entry
# read on screen, or time up.
gui_drive() {
  gui_place_window
  gui_until 60 browser_shows_scan
}
gui_run "$paraview" --dr "$work/scan.las"

status=0
gui_require_screenshot "$work/screen.png" || exit 1
if tesseract "$work/browser.png" - 2>/dev/null | grep -q "scan.las"; then
  echo "scan.las opened from the command line"
else
  echo "FAILED: scan.las not in the pipeline browser"
  status=1
fi
gui_check_no_gdal_probe
exit $status
