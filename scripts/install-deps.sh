#!/usr/bin/env bash
# Install the Debian 12 packages ricochet needs, only those missing.
# Idempotent: does nothing (and needs no privileges) when all are present.
#   scripts/install-deps.sh        build, run, plots (make, make demo, make gallery)
#   scripts/install-deps.sh test   the same, and what the tests need (make check)
#   scripts/install-deps.sh fuzz   the tests', and clang with libFuzzer (make fuzz)
set -euo pipefail
# (pkgconf: the embedding example and `make install` users build through
# pkg-config)
PKGS=(gcc make pkgconf libsundials-dev libsuitesparse-dev libgsl-dev libnetcdf-dev netcdf-bin
      python3 python3-numpy python3-netcdf4 python3-matplotlib)
case "${1:-}" in
    "") ;;
    test | fuzz)
        # the tests: SciPy references of the validation problems; xarray
        # (the results read by the Python module's tests); the ParaView
        # export read back and rendered off screen with VTK (xvfb: a display
        # for it); python3-distributed: the module's studies on Dask (a
        # LocalCluster in the tests)
        PKGS+=(python3-scipy python3-xarray python3-vtk9 xvfb xauth python3-distributed)
        # clang 14 and its runtime libraries (libFuzzer, ASan, UBSan)
        if [ "$1" = fuzz ]; then PKGS+=(clang libclang-rt-14-dev); fi ;;
    *) echo "install-deps: unknown set '$1' (expected nothing, test or fuzz)" >&2; exit 2 ;;
esac
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
