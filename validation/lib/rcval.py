"""Run ricochet and read its netCDF output, for the validation checks.

Each check prints one line per assertion, "PASS name: ..." or
"FAIL name: ...", and scripts/check.sh counts them.

RICOCHET_VAL_SOLVER=default in the environment runs every deck at ricochet's
default solver settings: run() and run_file() remove the deck's /SOLVER card
before running (unless called with keep_solver=True, for the runs of a
convergence study over rtol), and check() prefixes each check name with
"default:" so that the two modes' lines are told apart.

RICOCHET_VAL_METHOD=ida runs every deck on the IDA path (ricochet run
--method ida) and prefixes the check names with "ida:".

RICOCHET_VAL_SWITCH=1 runs every deck with method switching forced on
(ricochet run --switch: BDF and the explicit method, docs/theory.md 7.9;
only the CVODE path switches) and prefixes the check names with "switch:".
The switch events (method_explicit, method_implicit: the integrator's, not
the model's) are left out of Result's events, so that the checks of the
events see the model's alone; RICOCHET_VAL_SWITCH_EVENTS=1 keeps them.
"""
import atexit
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np
from netCDF4 import Dataset

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
RICOCHET = os.environ.get("RICOCHET", os.path.join(ROOT, "build", "ricochet"))
FAILED = []
PROBLEM = os.path.basename(os.path.dirname(os.path.abspath(sys.argv[0])))
DEFAULTS = os.environ.get("RICOCHET_VAL_SOLVER", "") == "default"
METHOD = os.environ.get("RICOCHET_VAL_METHOD", "")
SWITCH = os.environ.get("RICOCHET_VAL_SWITCH", "") == "1"
PREFIX = ("default:" if DEFAULTS else "") + (METHOD + ":" if METHOD else "") + ("switch:" if SWITCH else "")


_TMPROOT = []


def tmpdir():
    """A fresh directory for one run's deck and results, inside one directory
    per process that is removed when the process ends (RICOCHET_VAL_KEEP=1
    keeps it, for looking at the files)."""
    if not _TMPROOT:
        _TMPROOT.append(tempfile.mkdtemp(prefix="rcval-"))
        if os.environ.get("RICOCHET_VAL_KEEP", "") != "1":
            atexit.register(shutil.rmtree, _TMPROOT[0], True)
    return tempfile.mkdtemp(dir=_TMPROOT[0])


def strip_solver(text):
    """The deck text without its /SOLVER card (header and data lines, up to
    the next card header)."""
    out, skip = [], False
    for ln in text.splitlines(keepends=True):
        if ln.startswith("/"):
            skip = ln.split()[0] in ("/SOLVER", "/SOLVER/1")
        if not skip:
            out.append(ln)
    return "".join(out)


def _execute(case, out):
    cmd = [RICOCHET, "run", case, "-o", out, "-q"] + (["--method", METHOD] if METHOD else []) + \
        (["--switch"] if SWITCH else [])
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError(f"ricochet failed ({p.returncode}): {p.stderr.strip()}")
    # the physics checks that failed while the run went on: said, not hidden
    with Dataset(out) as nc:
        if getattr(nc, "physics_violations", 0) > 0:
            print(f"info: {PREFIX}{PROBLEM}: {os.path.basename(case)}: physics checks: {nc.physics_checks}")
    return out


def run(deck, name="case", keep_solver=False):
    """Write the deck to a temporary directory, run it, return the output path.
    In the defaults mode the /SOLVER card is removed unless keep_solver."""
    d = tmpdir()
    case = os.path.join(d, name + ".rad")
    out = os.path.join(d, name + ".nc")
    text = deck.text()
    if DEFAULTS and not keep_solver:
        text = strip_solver(text)
    with open(case, "w") as f:
        f.write(text)
    return _execute(case, out)


def run_file(case, keep_solver=False):
    """Run a deck file, return the output path. In the defaults mode a copy
    without the /SOLVER card is run unless keep_solver."""
    d = tmpdir()
    out = os.path.join(d, "out.nc")
    if DEFAULTS and not keep_solver:
        with open(case) as f:
            text = strip_solver(f.read())
        case = os.path.join(d, "case.rad")
        with open(case, "w") as f:
            f.write(text)
    return _execute(case, out)


def run_case(name="case.rad", keep_solver=False):
    """Run the deck file `name` of the problem's folder (that of the check.py
    being run), as run_file; return the output path."""
    return run_file(os.path.join(os.path.dirname(os.path.abspath(sys.argv[0])), name), keep_solver=keep_solver)


class Result:
    """The parts of an output file the checks use."""

    def __init__(self, path):
        self.path = path
        with Dataset(path) as nc:
            self.t = np.array(nc["time"][:])
            self.at_event = np.array(nc["at_event"][:])
            self.pos = np.array(nc["body_position"][:])
            self.quat = np.array(nc["body_quaternion"][:])  # (w, x, y, z)
            self.vel = np.array(nc["body_velocity"][:])
            self.fn = np.array(nc["inter_force_normal"][:]) if "inter_force_normal" in nc.variables else None
            self.inter_id = np.array(nc["inter_id"][:]) if "inter_id" in nc.variables else None
            self.pen = np.array(nc["inter_penetration"][:]) if "inter_penetration" in nc.variables else None
            v = nc.variables
            self.ffric = np.array(v["inter_force_friction"][:]) if "inter_force_friction" in v else None
            self.vslip = np.array(v["inter_slip_speed"][:]) if "inter_slip_speed" in v else None
            self.slip = np.array(v["inter_slip"][:]) if "inter_slip" in v else None
            self.mode = np.array(v["inter_mode"][:]) if "inter_mode" in v else None  # 1 open, 2 closed, 3 released
            n = len(nc.dimensions["event"])
            self.ev_t = np.array(nc["event_time"][:]) if n else np.zeros(0)
            self.ev_kind = [str(k) for k in nc["event_kind"][:]] if n else []
            self.ev_elem = [str(k) for k in nc["event_element"][:]] if n else []
            # the interface's approach speed dP/dt at the event [m/s] (NaN
            # for events of other elements)
            self.ev_vn = np.array(nc["event_normal_speed"][:]) if n else np.zeros(0)
            if SWITCH and os.environ.get("RICOCHET_VAL_SWITCH_EVENTS", "") != "1":
                keep = [k not in ("method_explicit", "method_implicit") for k in self.ev_kind]
                self.ev_t, self.ev_vn = self.ev_t[keep], self.ev_vn[keep]
                self.ev_kind = [k for k, w in zip(self.ev_kind, keep) if w]
                self.ev_elem = [e for e, w in zip(self.ev_elem, keep) if w]
            self.attrs = {k: nc.getncattr(k) for k in nc.ncattrs()}
            self.energy = {v: np.array(nc[v][:]) for v in nc.variables if v.startswith("energy_")}

    def events(self, *kinds):
        return np.array([t for t, k in zip(self.ev_t, self.ev_kind) if k in kinds])

    def contact_ends(self):
        """Times a contact stops pushing: the force released at zero
        (contact_open) or the bodies separated at P = 0 (contact_separate)."""
        return self.events("contact_open", "contact_separate")

    def state_at(self, t, kind_filter=None):
        """Index of the event record written at time t."""
        idx = np.where((self.at_event == 1) & (np.abs(self.t - t) <= 1e-14 * max(1.0, abs(t))))[0]
        return idx[-1]


def check(name, ok, detail):
    name = PREFIX + name
    print(f"{'PASS' if ok else 'FAIL'} {name}: {detail}")
    sys.stdout.flush()
    if not ok:
        FAILED.append(name)


def check_ledger(name, r, tol):
    """The energy ledger of result r stays constant: max |E_total(t) - E_total(0)| / E_total(0) < tol."""
    et = r.energy["energy_total"]
    drift = np.max(np.abs(et - et[0])) / et[0]
    check(name, drift < tol, f"max |E_total(t) - E_total(0)| / E_total(0) = {drift:.2e} (< {tol:g})")


def rel(a, b):
    return abs(a - b) / abs(b)


def down_crossings(t, x):
    """Times where the record series x crosses 0 downwards, by a cubic
    through the 4 nearest records."""
    out = []
    for k in range(1, len(t) - 2):
        if x[k] > 0 >= x[k + 1]:
            p = np.polyfit(t[k - 1:k + 3] - t[k], x[k - 1:k + 3], 3)
            r = [z.real for z in np.roots(p) if abs(z.imag) < 1e-12 and 0 <= z.real <= t[k + 1] - t[k]]
            out.append(t[k] + r[0])
    return np.array(out)


def parabola_peak(v, k):
    """The extreme of the record series v near record k: the vertex of the
    parabola through v[k - 1], v[k], v[k + 1] (v[k] where the three lie on a
    line); in v's units."""
    a, b, c = v[k - 1], v[k], v[k + 1]
    return b + 0.125 * (a - c) ** 2 / (2 * b - a - c) if 2 * b - a - c != 0 else b


def refined_extreme(x, sign):
    """The extreme of the record series x (sign +1: max, -1: min), refined by
    parabola_peak around the extreme record (kept off the ends); in x's units."""
    i = int(np.argmax(sign * x))
    i = min(max(i, 1), len(x) - 2)
    return parabola_peak(x, i)


def finish():
    sys.exit(1 if FAILED else 0)


def entry(main, cases):
    """The end of every check.py: with --write-case on the command line, write
    the problem's deck(s) into its folder, else run main().

    cases: a callable returning the Deck written as case.rad, or a dict
    {file name: Deck} for problems with several case files."""
    if "--write-case" in sys.argv:
        made = cases()
        if not isinstance(made, dict):
            made = {"case.rad": made}
        here = os.path.dirname(os.path.abspath(sys.argv[0]))
        for name, d in made.items():
            d.write(os.path.join(here, name))
    else:
        main()
