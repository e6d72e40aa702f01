"""The scripts' interpreter: Debian's packages (numpy, netCDF4, matplotlib)
live in /usr/bin/python3; a script started by another python3 that lacks
them (a pyenv or a venv first on PATH) runs again with Debian's."""
import os
import sys

DEBIAN_PYTHON = "/usr/bin/python3"


def reexec_or_exit(exc, tool):
    """After the ImportError exc of script `tool`: exec the same command line
    with /usr/bin/python3 (once), or exit with what to install."""
    if (os.path.exists(DEBIAN_PYTHON) and not os.environ.get("RC_PLOT_REEXEC")
            and os.path.realpath(sys.executable) != os.path.realpath(DEBIAN_PYTHON)):
        os.environ["RC_PLOT_REEXEC"] = "1"
        os.execv(DEBIAN_PYTHON, [DEBIAN_PYTHON] + sys.argv)
    sys.exit(f"{tool}: {exc}; install python3-netcdf4 python3-numpy python3-matplotlib "
             "(scripts/install-deps.sh)")
