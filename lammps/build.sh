#!/usr/bin/env bash
# lammps/build.sh: LAMMPS with the PLUGIN package and MPI (Debian's Open MPI),
# built from Debian's source package into build/lammps, then the hcbd
# plugins (build/lammps/plugin/gibdplugin.so, hcbdplugin.so) against it.  `make lammps` runs
# this.  Everything comes from Debian packages: cmake, g++, libopenmpi-dev,
# openmpi-bin, and the lammps source package (apt-get source, which needs a
# deb-src entry: .ci/run adds one).  A tool that is missing skips the build
# with a message (exit 0); a failing build exits 1.
#
# Cached: LAMMPS is rebuilt only when build/lammps/lmp is missing or was
# built from another source version; the plugin is rebuilt by make when
# its sources change.  Takes about 6 minutes on 2 cores the first time.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
B=$root/build/lammps
jobs=${JOBS:-2}

missing=""
for t in cmake mpicxx mpirun c++ tar xz; do command -v $t >/dev/null 2>&1 || missing="$missing $t"; done
if [ -n "$missing" ]; then
    echo "make lammps: skipped, missing:$missing (apt-get install cmake g++ libopenmpi-dev openmpi-bin xz-utils)"
    exit 0
fi
mkdir -p "$B/pkg"

# the source: Debian's package, downloaded once
tarball=$(ls "$B"/pkg/lammps_*.orig.tar.xz 2>/dev/null | head -n 1 || true)
if [ -z "$tarball" ]; then
    if ! (cd "$B/pkg" && apt-get source --download-only lammps >/dev/null 2>&1); then
        echo "make lammps: skipped, apt-get source lammps failed (needs a deb-src entry:"
        echo "  sed 's/^Types: deb\$/Types: deb-src/' /etc/apt/sources.list.d/debian.sources \\"
        echo "      > /etc/apt/sources.list.d/debsrc.sources && apt-get update)"
        exit 0
    fi
    tarball=$(ls "$B"/pkg/lammps_*.orig.tar.xz | head -n 1)
fi
# the stamp names the configuration too: changing it below rebuilds
version="$(basename "$tarball" .orig.tar.xz) shared mpi plugin brownian sph dpd"

if [ ! -x "$B/lmp" ] || [ "$(cat "$B/version" 2>/dev/null)" != "$version" ]; then
    # BROWNIAN, SPH, DPD: the peers of bench/peers/run.sh in the same build
    echo "make lammps: building $version in $B"
    rm -rf "$B/src" "$B/cmake-build" "$B/lmp"
    mkdir -p "$B/src"
    tar -xf "$tarball" -C "$B/src" --strip-components=1
    # plugins load only into a LAMMPS built as a shared library
    cmake -S "$B/src/cmake" -B "$B/cmake-build" -D CMAKE_BUILD_TYPE=Release \
        -D CMAKE_CXX_FLAGS_RELEASE="-O2 -DNDEBUG" -D BUILD_SHARED_LIBS=on \
        -D BUILD_MPI=on -D BUILD_OMP=off -D PKG_PLUGIN=on -D PKG_BROWNIAN=on \
        -D PKG_SPH=on -D PKG_DPD-SMOOTH=on -D PKG_DPD-BASIC=on \
        -D LAMMPS_SIZES=smallbig > "$B/cmake.log" 2>&1 || { tail -n 30 "$B/cmake.log"; exit 1; }
    cmake --build "$B/cmake-build" -j"$jobs" > "$B/build.log" 2>&1 || { tail -n 30 "$B/build.log"; exit 1; }
    ln -sf cmake-build/lmp "$B/lmp"
    echo "$version" > "$B/version"
fi

cmake -S "$root/lammps" -B "$B/plugin" -D CMAKE_BUILD_TYPE=Release -D LAMMPS_HEADER_DIR="$B/src/src" \
    -D HCBD_DIR="$root" > "$B/plugin-cmake.log" 2>&1 || { tail -n 30 "$B/plugin-cmake.log"; exit 1; }
cmake --build "$B/plugin" -j"$jobs" > "$B/plugin-build.log" 2>&1 || { tail -n 40 "$B/plugin-build.log"; exit 1; }
# the star potential of hcbd_star_potential as a pair table (in.gibd_star)
awk -v f=128 -v sigma=1 -v eps=1 -v n=5000 -v rlo=0.01 -v rhi=2.5 -f "$root/bench/peers/star_table.awk" \
    > "$B/star.table"
echo "make lammps: $B/lmp, $B/plugin/gibdplugin.so, $B/plugin/hcbdplugin.so and $B/star.table"
