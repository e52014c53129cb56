#!/usr/bin/env bash
# Sets up, builds, and estimates the principal curvatures of the default
# cloud (a torus with exact normals, generated into Data/), writing
# Data/torus_curvatures.vtp and printing a summary. Pass another input and
# output to run on your own cloud: Scripts/run-demo.sh in.ply out.vtp
set -euo pipefail
cd "$(dirname "$0")/.."
bash Scripts/setup.sh > build-setup.log 2>&1 || { cat build-setup.log; exit 1; }

input=Data/torus.vtp
output=Data/torus_curvatures.vtp
if [ $# -ge 2 ]; then
  input=$1
  output=$2
  shift 2
fi
if [ "$input" = "Data/torus.vtp" ] && [ ! -f "$input" ]; then
  ./build/bin/GenerateAnalyticCloud torus 200000 "$input" 1
fi
pvpython Tools/estimate_curvatures.py "$input" "$output" "$@"
