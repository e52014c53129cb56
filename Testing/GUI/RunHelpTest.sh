#!/usr/bin/env bash
# The "?" of the Properties panel, in the real ParaView GUI under Xvfb: with
# Principal Curvatures the active source (help_script.py), a real click on
# the panel's "?" button (found right of the Delete button, located by OCR)
# must open ParaView's help window on the plugin's own page for the filter
# (pqHelpReaction::showProxyHelp finds it in the plugin's Qt help), not on
# ParaView's front page: the help window's text, read back by OCR, must
# hold the page's title, its sign convention and output array names.
#   RunHelpTest.sh PARAVIEW PLUGIN SCREENSHOT.png
set -u
paraview=$1 plugin=$2 screenshot=$3
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export GUI_TEST_PLUGIN=$plugin GUI_TEST_MARKER=$work/marker GUI_TEST_WORK=$work
mkdir -p "$(dirname "$screenshot")"
rm -f "$screenshot"

xvfb-run -a -s "-screen 0 1600x1000x24" bash -c '
  "$0" --dr --script="$1" > "$GUI_TEST_WORK/paraview.log" 2>&1 &
  pid=$!
  for i in $(seq 1 120); do [ -s "$GUI_TEST_MARKER" ] && break; sleep 1; done
  window=$(xdotool search --sync --onlyvisible --name "ParaView" | head -n 1)
  if [ -n "$window" ]; then
    xdotool windowmove "$window" 0 0 windowsize "$window" 1600 1000
    sleep 5
    import -window root "$GUI_TEST_WORK/before.png"
    # The panel buttons Apply, Reset, Delete, ?: the word Delete by OCR
    # (tsv: left top width height of each word), at three times the size.
    convert "$GUI_TEST_WORK/before.png" -crop 500x1000+0+0 +repage -resize 300% \
      -colorspace Gray "$GUI_TEST_WORK/left.png"
    tesseract "$GUI_TEST_WORK/left.png" - tsv 2>/dev/null |
      awk -F "\t" "\$12 == \"Delete\" { print int((\$7 + \$9) / 3), int((\$8 + \$10 / 2) / 3); exit }" \
      > "$GUI_TEST_WORK/delete"
    read -r dx dy < "$GUI_TEST_WORK/delete"
    if [ -n "${dx:-}" ]; then
      # The "?" button: right of the Delete button, whose text ends about
      # 12 pixels before its edge; the ? button is about 26 pixels wide.
      echo "$dx $dy" > "$GUI_TEST_WORK/clicked"
      xdotool mousemove $((dx + 27)) "$dy" click 1
      help=$(timeout 60 xdotool search --sync --onlyvisible --name "Online Help" | head -n 1)
      if [ -n "$help" ]; then
        xdotool windowmove "$help" 0 0 windowsize "$help" 1600 1000
        sleep 5
        import -window root "$2"
        echo found > "$GUI_TEST_WORK/help_window"
      fi
    fi
  fi
  [ -s "$2" ] || import -window root "$2"
  kill "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  exit 0' "$paraview" "$here/help_script.py" "$screenshot"

status=0
marker=$(cat "$GUI_TEST_MARKER" 2>/dev/null || echo "no marker: the GUI script did not run")
echo "GUI script: $marker"
case "$marker" in ready*) ;; *) tail -n 20 "$work/paraview.log"; exit 1 ;; esac
if [ -s "$work/clicked" ]; then
  echo "clicked the ? right of Delete at $(cat "$work/clicked")"
else
  echo "FAILED: no Delete button found by OCR in the Properties panel"
  exit 1
fi
if [ ! -s "$work/help_window" ]; then
  echo "FAILED: no help window opened"
  exit 1
fi
# The help window's page, enlarged for OCR.
convert "$screenshot" -resize 200% -colorspace Gray "$work/help.png"
text=$(tesseract "$work/help.png" - 2>/dev/null)
[ -n "${GUI_TEST_DUMP_OCR:-}" ] && printf "%s\n" "$text" > "$GUI_TEST_DUMP_OCR"
for phrase in "PrincipalCurvatureEstimation" "Sign convention" "bends away from the" \
    "Mean_Curvature_Clipped" "Maximum_Curvature_Direction"; do
  if grep -q "$phrase" <<< "$text"; then
    echo "help page shows: $phrase"
  else
    echo "FAILED: the help window does not show '$phrase' (not the filter's page?)"
    status=1
  fi
done
echo "screenshot: $screenshot"
exit $status
