#!/usr/bin/env bash
# Puts real scans from Debian's libcgal-demo package (CGAL's data set) into
# Data/: the Stanford bunny mesh (bunny00.off, 37k vertices) and the kitten
# point set with normals (kitten.xyz). Installs the package if missing.
set -euo pipefail
cd "$(dirname "$0")/.."
archive=/usr/share/doc/libcgal-dev/data.tar.gz
if [ ! -f "$archive" ]; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  DEBIAN_FRONTEND=noninteractive $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends libcgal-demo
fi
tar xzf "$archive" -C Data --strip-components=2 data/meshes/bunny00.off data/points_3/kitten.xyz
ls -l Data/bunny00.off Data/kitten.xyz
