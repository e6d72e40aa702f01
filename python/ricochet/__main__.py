"""python3 -m ricochet study DECK --grid GRID.json [--scheduler ADDRESS] [-o STUDY.nc] [--study-dir DIR] ...

GRID.json: {"CARD:FIELD": [values, ...], ...} (full factorial), a list of
{"CARD:FIELD": value} (the cases as given), or {"lhs": {"CARD:FIELD": [lo,
hi], ...}, "n": N, "seed": S} (Latin hypercube). docs/python.md, "Studies".
Exit code: 0 when every case succeeded, 1 when some failed (the file is
written all the same), 2 for a wrong command line or grid file.
"""
# SPDX-License-Identifier: GPL-3.0-or-later
import argparse
import json
import sys


def _parameters(path):
    from .study import lhs
    with open(path) as f:
        g = json.load(f)
    if isinstance(g, dict) and "lhs" in g:
        if set(g) - {"lhs", "n", "seed"} or "n" not in g:
            raise ValueError(f"{path}: a Latin hypercube is {{\"lhs\": {{field: [lo, hi]}}, \"n\": N, \"seed\": S}}")
        return lhs({k: tuple(v) for k, v in g["lhs"].items()}, g["n"], g.get("seed"))
    if isinstance(g, (dict, list)):
        return g
    raise ValueError(f"{path}: expected a dict of lists, a list of dicts or an lhs object")


def main(argv=None):
    p = argparse.ArgumentParser(prog="python3 -m ricochet", description="ricochet from Python")
    sub = p.add_subparsers(dest="cmd", required=True)
    s = sub.add_parser("study", help="run a parameter study on Dask distributed")
    s.add_argument("deck", help="the case file")
    s.add_argument("--grid", required=True, help="JSON file of the parameters")
    s.add_argument("--scheduler", help="address of a Dask scheduler (default: a local cluster of processes)")
    s.add_argument("--workers", type=int, help="worker processes of the local cluster (default: one per CPU)")
    s.add_argument("-o", "--output", default="study.nc", help="the study's netCDF file (default study.nc)")
    s.add_argument("--set", action="append", default=[], metavar="CARD:FIELD=VALUE",
                   help="a field set in every case (repeatable)")
    s.add_argument("--outputs", default="", help="time series to keep, comma-separated (e.g. body_position,energy_total)")
    s.add_argument("--times", help="their common times [s]: START:STOP:N (N points) or a comma-separated list")
    s.add_argument("--impacts", type=int, default=5, help="impacts kept per case (default 5)")
    s.add_argument("--study-dir", help="the study's directory (the workers see it): the manifest, each case's results "
                   "file and summary; a rerun with the same directory runs only the cases not done")
    s.add_argument("--keep-dir", help="the older name of --study-dir")
    for o in ("--t-end", "--dt-out", "--rtol"):
        s.add_argument(o, type=float)
    s.add_argument("--method", choices=["cvode", "ida", "static"])
    s.add_argument("--on-violation", choices=["stop", "warn"])
    a = p.parse_args(argv)

    from .study import study
    try:
        params = _parameters(a.grid)
        outputs = [x for x in a.outputs.split(",") if x]
        times = None
        if a.times:
            import numpy as np
            if ":" in a.times:
                t0, t1, n = a.times.split(":")
                times = np.linspace(float(t0), float(t1), int(n))
            else:
                times = [float(x) for x in a.times.split(",")]
        kw = {k: v for k, v in (("t_end", a.t_end), ("dt_out", a.dt_out), ("rtol", a.rtol), ("method", a.method),
                                ("on_violation", a.on_violation)) if v is not None}
        ds = study(a.deck, params, client=a.scheduler, outputs=outputs, times=times, set=a.set or None,
                   n_impacts=a.impacts, keep_dir=a.keep_dir, study_dir=a.study_dir, workers=a.workers, **kw)
    except (OSError, ValueError, TypeError) as e:
        print(f"python3 -m ricochet study: {e}", file=sys.stderr)
        return 2
    ds.to_netcdf(a.output)
    failed = int(ds.attrs["failed_cases"])
    print(f"{ds.sizes['case']} cases, {failed} failed -> {a.output}")
    for i in range(ds.sizes["case"]):
        if int(ds.status[i]) != 0:
            print(f"  case {i}: {ds.message.values[i]}", file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
