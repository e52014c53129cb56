#!/usr/bin/env bash
# Installs the Debian 12 packages the project needs (only those missing),
# then configures and builds into build/. Safe to run again.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  paraview-dev python3-paraview build-essential cmake
  libopenmpi-dev libdouble-conversion-dev libeigen3-dev python3-numpy
  # parallel ParaView tests: mpiexec
  openmpi-bin
  # the GUI test: ParaView under a virtual display, window control, capture, OCR
  xvfb xauth xdotool imagemagick tesseract-ocr tesseract-ocr-eng libqt5svg5
  # the plugin's GUI part (Plugin/Gui): ParaView's Qt components and what
  # their link interfaces name (CMake/ParaViewGuiDependencies.cmake)
  qtbase5-dev qttools5-dev libqt5opengl5-dev libx11-dev libglew-dev libxml2-dev
  libnetcdf-dev libhdf5-dev libboost-dev
  # the plugin's help pages (the "?" in the GUI): xmlpatterns and
  # qhelpgenerator (qttools5-dev above brings qhelpgenerator-qt5)
  qtxmlpatterns5-dev-tools qhelpgenerator-qt5
)
missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "Installing: ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -q
  $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$(nproc)"
