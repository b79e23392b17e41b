#!/usr/bin/env bash
############################################################################
# MODULE:    tools/setup.sh (r3.sbrt addon)
# PURPOSE:   Installs, through apt-get, the Debian packages the addon needs
#            to build, run its demo and its tests; does nothing when they
#            are all there. Never writes into the GRASS installation.
#            One list for Debian 12 (GRASS 8.2) and Debian 13 (GRASS 8.4):
#            every name exists in both (tools/grass84_root.sh installs it
#            in a Debian 13 root).
# COPYRIGHT: (C) 2026 by the r3.sbrt authors. GNU GPL v2 or later.
############################################################################
set -euo pipefail
packages=(
    make g++ pkg-config zlib1g-dev libzstd-dev
    grass-core grass-dev             # GRASS (8.2 or 8.4) and its headers/make system
    libglm-dev                       # vector maths
    libegl-dev libopengl-dev libegl-mesa0 libgl1-mesa-dri libosmesa6-dev
    libgtest-dev                     # unit tests
    clang libclang-rt-dev            # libFuzzer and the sanitizers' runtimes
    valgrind                         # memcheck of the modules
    universal-ctags                  # the functions' lengths (tools/check_function_length.sh)
    libpng-dev                       # the PNG file of a render
    nlohmann-json3-dev               # JSON output written by a library: valid by construction
    python3-pil                      # tests read the PNG back with a real decoder
    python3-matplotlib               # g.gui.sbrt's column profile
    netcdf-bin                       # ncgen writes the NetCDF files of the import tests
    libcairo2-dev fonts-dejavu-core  # the PNG's annotations: legend, north arrow, scale bar
    ffmpeg                           # video= of an animation (and ffprobe in its test)
    slurm-wlm munge parallel         # the cluster recipes, run on a one-node Slurm cluster and GNU parallel
    grass-gui                        # g.gui.sbrt: wxPython and GRASS's GUI parts (map selectors)
    xvfb xdotool imagemagick         # the tests drive g.gui.sbrt on a virtual screen
    jupyter-nbconvert python3-ipykernel python3-nbclient python3-nbformat  # docs/r3_sbrt.ipynb, run by the tests
)
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "setup: installing ${missing[*]}"
if [ "$(id -u)" -ne 0 ]; then
    echo "setup: run as root (or install these Debian packages): ${missing[*]}" >&2
    exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
