"""Calibration from Python: ``ricochet.fit`` runs the program's ``ricochet
fit`` (docs/calibration.md) and returns its JSON report as a dict.

    rep = ricochet.fit("drop.rad", "measured.csv",
                       log={"/INTER/TYPE6/1:FscaleId": 1e5, "/INTER/TYPE6/1:Visc": 5},
                       free={"/INTER/TYPE6/1:Fric": (0.2, 0.0, 1.0)})
    rep["parameters"][0]["value"], rep["parameters"][0]["standard_error"]

The program is found as RICOCHET (a path), else beside the library the
module loads (a build directory), else on PATH.
"""
# SPDX-License-Identifier: GPL-3.0-or-later
import json
import os
import shutil
import subprocess
import tempfile

import numpy as np

from .errors import RicochetError, Status, error_for
from .sim import format_set, format_value


def program():
    """The ``ricochet`` program the fits run: RICOCHET, else the one beside
    the loaded library, else on PATH; None when none is found."""
    env = os.environ.get("RICOCHET")
    if env:
        return env
    try:
        from ._lib import library_path
        lib = str(library_path()).rsplit(" (", 1)[0]  # "PATH (how it was found)"
        cand = os.path.join(os.path.dirname(lib), "ricochet")
        if os.path.dirname(lib) and os.access(cand, os.X_OK):
            return cand
    except Exception:  # noqa: BLE001 - no library: look on PATH
        pass
    return shutil.which("ricochet")


def _free_args(option, params):
    """--free / --log arguments of {name: start or (start, lo, hi)}."""
    out = []
    for name, v in (params or {}).items():
        if isinstance(v, (tuple, list)):
            if len(v) != 3:
                raise TypeError(f"{option} {name}: expected start or (start, lo, hi), got {v!r}")
            arg = f"{name}={format_value(v[0])},{format_value(v[1])}:{format_value(v[2])}"
        else:
            arg = f"{name}={format_value(v)}"
        out += [option, arg]
    return out


def fit(deck, data, free=None, log=None, set=None, impacts=None, rtol=None, method=None, max_iter=None, jobs=None,
        trs=None, max_rse=None, fitted=None, quiet=True, jacobian=None):
    """Fit numeric fields of ``deck`` to the signals measured in ``data`` (a
    CSV file, docs/calibration.md "The data file").

    free, log: {"CARD:FIELD": start} or {"CARD:FIELD": (start, lo, hi)},
    values in the card's units; ``log`` ones are fitted in log(value).
    set: fields fixed for the fit (as ``run``'s ``set``). impacts: a CSV
    file of measured impact quantities (docs/calibration.md, "Impacts").
    jacobian: "fd" (finite differences, the default) or "sens" (forward
    sensitivities, one run per Jacobian; of the impacts, t_close, duration,
    v_in and v_out only).
    fitted: the
    measured-against-fitted CSV (default: a temporary file, read back).

    Returns the JSON report (a dict: "parameters", those of ``free`` then
    those of ``log``, each with "name", "value",
    "standard_error", "lo95", "hi95", "identifiable", "reason"; "correlation";
    "signals"; "set"; "converged"; ...) with "fitted" added: the
    measured-against-fitted table as a numpy array (first column the time,
    then measured and fitted per signal, in the data's units; NaN where not
    measured). Raises InputError (exit code 2), SolverError (3),
    RicochetIOError (4), RicochetError (not converged: the report in
    ``.report``)."""
    exe = program()
    if not exe:
        raise RicochetError("ricochet fit: the ricochet program was not found (set RICOCHET to its path)",
                            status=Status.EINPUT)
    with tempfile.TemporaryDirectory(prefix="ricochet-fit-") as d:
        js = os.path.join(d, "report.json")
        fit_csv = fitted or os.path.join(d, "fitted.csv")
        cmd = [exe, "fit", str(deck), "--data", str(data), "--json", js, "--fitted", fit_csv]
        cmd += _free_args("--free", free) + _free_args("--log", log)
        for s in format_set(set):
            cmd += ["--set", s]
        for opt, v in (("--impacts", impacts), ("--rtol", rtol), ("--method", method), ("--max-iter", max_iter), ("--jobs", jobs),
                       ("--trs", trs), ("--max-rse", max_rse), ("--jacobian", jacobian)):
            if v is not None:
                cmd += [opt, str(v)]
        if quiet:
            cmd.append("-q")
        p = subprocess.run(cmd, capture_output=True, text=True)
        msg = p.stderr.strip().replace("ricochet fit: ", "")
        if p.returncode not in (0, 1):
            raise error_for(Status(p.returncode) if p.returncode in (2, 3, 4) else Status.EINTERNAL,
                            msg or f"ricochet fit exited with status {p.returncode}")
        with open(js) as f:
            rep = json.load(f)
        rep["fitted"] = np.genfromtxt(fit_csv, delimiter=",", skip_header=1, ndmin=2)
        rep["report"] = p.stdout
    if p.returncode == 1:
        err = RicochetError(f"ricochet fit: {rep['status']}", status=Status.ESOLVER)
        err.report = rep
        raise err
    return rep
