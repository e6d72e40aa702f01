"""ricochet from Python: run simulations, read the results, write case decks.

    import ricochet
    ds = ricochet.run("drop.rad", set={"/INTER/TYPE6/1:Fric": 0.3})   # xarray.Dataset
    with ricochet.Session("drop.rad") as s:                           # a run in pieces
        s.run_until(0.1); print(s.body(1).position)
    ds = ricochet.read("out/demo.nc")    # a results file: xarray.Dataset when xarray is
                                         # installed, else a dict of numpy arrays (Results)
    from ricochet.deck import Deck       # the fixed-width deck writer
    st = ricochet.study("drop.rad", {"/SURF/PLANE/2:ZM": [-0.1, -0.2]})  # cases on Dask
    rep = ricochet.fit("drop.rad", "measured.csv", log={"/INTER/TYPE6/1:Visc": 5})  # calibration

``run`` and ``Session`` call the C library (libricochet, through ctypes:
found through RICOCHET_LIB, the installed library, or a source checkout's
build/); ``read`` and ``deck`` need no library. docs/python.md.
"""
# SPDX-License-Identifier: GPL-3.0-or-later
from . import deck  # noqa: F401
from .fit import fit  # noqa: F401
from .errors import (InputError, InterruptedRun, PhysicsCheckError, RicochetError,  # noqa: F401
                     RicochetIOError, SolverError, Status)
from .results import Results, read  # noqa: F401
from .sim import BodyState, EventValues, RicochetWarning, RunStats, Session, run  # noqa: F401
from .study import StudyDirError, grid, lhs, study  # noqa: F401

__version__ = "0.2.0"

__all__ = ["read", "Results", "deck", "run", "Session", "BodyState", "EventValues", "RunStats", "study", "lhs",
           "grid", "StudyDirError", "RicochetError", "InputError", "SolverError", "RicochetIOError",
           "PhysicsCheckError", "InterruptedRun", "RicochetWarning", "Status", "library_path", "fit"]


def library_path():
    """Where libricochet was loaded from and how it was found (loads it)."""
    from ._lib import library_path as lp
    return lp()
