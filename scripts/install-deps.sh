#!/usr/bin/env bash
# Install the Debian 12 packages ricochet needs, only those missing.
# Idempotent: does nothing (and needs no privileges) when all are present.
#   scripts/install-deps.sh        build, tests, plots
#   scripts/install-deps.sh fuzz   the same, and clang with libFuzzer (make fuzz)
set -euo pipefail
# (pkgconf: `make check` builds the embedding example through pkg-config;
# python3-xarray: reading the results with xarray in the tests and the module)
PKGS=(gcc make pkgconf libsundials-dev libsuitesparse-dev libgsl-dev libnetcdf-dev netcdf-bin
      python3 python3-numpy python3-scipy python3-netcdf4 python3-matplotlib
      # tests only: the ParaView export read back and rendered off screen with
      # VTK (xvfb: a display for it); python3-distributed: the Python
      # module's studies on Dask (ricochet.study, a LocalCluster in the tests)
      python3-xarray python3-vtk9 xvfb xauth python3-distributed)
# clang 14 and its runtime libraries (libFuzzer, ASan, UBSan)
if [ "${1:-}" = fuzz ]; then PKGS+=(clang libclang-rt-14-dev); fi
missing=()
for p in "${PKGS[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$p")
    fi
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
    if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
        echo "install-deps: missing packages (${missing[*]}) and not root; install them with apt-get" >&2
        exit 1
    fi
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
