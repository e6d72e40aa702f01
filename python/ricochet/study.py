"""Parameter studies on Dask distributed: every case is one ``ricochet.run``
of the same deck with fields set by name, run in a Dask worker; the results
are gathered into one xarray.Dataset with a ``case`` dimension
(docs/python.md, "Studies").

    import ricochet
    st = ricochet.study("drop.rad", {"/SURF/PLANE/2:ZM": [-0.1, -0.2, -0.4]})
    st = ricochet.study("drop.rad", ricochet.lhs({"/INTER/TYPE6/1:Fric": (0.1, 0.5)}, 20, seed=1),
                        client="tcp://scheduler:8786")

Parameters: a dict {field: [values]} (full factorial, the last field varying
fastest), a list of dicts {field: value} (the cases as given), or
``lhs(...)`` (Latin hypercube). A field is a ``set=`` key of ``run``,
"CARD:FIELD" (docs/case-format.md), its value in the card's own units.
"""
# SPDX-License-Identifier: GPL-3.0-or-later
import itertools
import math
import numbers
import os
import re
import shutil
import tempfile

__all__ = ["study", "grid", "lhs", "run_case"]

# the last values kept of every body (the results file's variables)
_BODY_VARS = ("body_position", "body_quaternion", "body_velocity", "body_angular_velocity")
# the impact table's columns (docs/output-format.md, "Impacts table")
_IMPACT_VARS = ("impact_inter", "impact_close_time", "impact_open_time", "impact_duration", "impact_max_penetration",
                "impact_max_penetration_time", "impact_peak_force", "impact_peak_force_time", "impact_speed_in",
                "impact_speed_out", "impact_restitution", "impact_energy_lost")


def grid(parameters):
    """The full factorial of {field: [values]}: a list of dicts, the last
    field varying fastest."""
    if not isinstance(parameters, dict) or not parameters:
        raise ValueError("grid: expected a non-empty dict {'CARD:FIELD': [values, ...]}")
    names = list(parameters)
    lists = []
    for k in names:
        v = parameters[k]
        if isinstance(v, (str, bytes)) or not hasattr(v, "__iter__"):
            raise ValueError(f"grid: the values of {k!r} must be a list, got {v!r}")
        v = list(v)
        if not v:
            raise ValueError(f"grid: no values for {k!r}")
        lists.append(v)
    return [dict(zip(names, combo)) for combo in itertools.product(*lists)]


def lhs(ranges, n, seed=None):
    """A Latin hypercube of n cases over {field: (lo, hi)}: each field's range
    cut into n equal strata, one value drawn uniformly in each, the strata
    shuffled independently per field (numpy's default_rng(seed)). Returns a
    list of n dicts {field: float}."""
    import numpy as np
    if not isinstance(ranges, dict) or not ranges:
        raise ValueError("lhs: expected a non-empty dict {'CARD:FIELD': (lo, hi)}")
    if isinstance(n, bool) or not isinstance(n, numbers.Integral) or n < 1:
        raise ValueError(f"lhs: expected a number of cases n >= 1, got {n!r}")
    rng = np.random.default_rng(seed)
    cols = {}
    for k, r in ranges.items():
        try:
            lo, hi = (float(x) for x in r)
        except (TypeError, ValueError):
            raise ValueError(f"lhs: the range of {k!r} must be (lo, hi), got {r!r}") from None
        if not (math.isfinite(lo) and math.isfinite(hi) and lo < hi):
            raise ValueError(f"lhs: the range of {k!r} must be finite with lo < hi, got ({lo!r}, {hi!r})")
        u = (rng.permutation(n) + rng.random(n)) / n
        cols[k] = lo + u * (hi - lo)
    return [{k: float(cols[k][i]) for k in cols} for i in range(n)]


def _cases(parameters):
    if isinstance(parameters, dict):
        return grid(parameters)
    cases = list(parameters)
    if not cases:
        raise ValueError("study: no cases")
    for c in cases:
        if not isinstance(c, dict):
            raise ValueError(f"study: expected parameters as a dict of lists, a list of dicts or lhs(...); got an item {c!r}")
    keys = list(cases[0])
    for i, c in enumerate(cases):
        if list(c) != keys and set(c) != set(keys):
            raise ValueError(f"study: case {i} sets {sorted(c)}, case 0 sets {sorted(keys)}: every case must set the same fields")
    return cases


def _varname(field):
    """A netCDF-safe variable name for a field ("/SURF/PLANE/2:ZM" -> "SURF_PLANE_2_ZM")."""
    s = re.sub(r"[^A-Za-z0-9_]+", "_", field).strip("_")
    return s if s and not s[0].isdigit() else "p_" + s


def run_case(deck, deck_name, overrides, run_kw, outputs, times, n_impacts, keep):
    """One case, in a worker: ``ricochet.run`` of the deck (its text, written
    to a temporary file, or a path the worker reads when deck_name is None)
    with the overrides; returns a dict of small numpy arrays (the final
    states, the energy ledger at the end, the first n_impacts impacts, the
    outputs at times) and the status. Never raises for a failing run."""
    import numpy as np
    from .errors import RicochetError
    from .sim import run
    tmp = None
    res = {"status": 0, "exit_code": 0, "message": ""}
    try:
        if deck_name is not None:
            tmp = tempfile.mkdtemp(prefix="ricochet-case-")
            path = os.path.join(tmp, os.path.basename(deck_name) or "deck.rad")
            with open(path, "w") as f:
                f.write(deck)
        else:
            path = deck
        try:
            ds = run(path, set=overrides, out=keep, **run_kw)
        except RicochetError as e:
            msg = str(e)
            if tmp is not None:  # name the deck as the user knows it
                msg = msg.replace(path, deck_name)
            res.update(status=int(e.status) if e.status is not None else 1, exit_code=e.exit_code, message=msg)
            ds = e.dataset
        if ds is None:
            return res
        if "time" not in ds.variables or ds.sizes.get("time", 0) == 0:
            return res
        t = np.asarray(ds["time"].values, dtype=float)
        res["final_time"] = float(t[-1])
        res["body"] = np.asarray(ds["body"].values)
        for v in _BODY_VARS:
            res["final_" + v] = np.asarray(ds[v].values[-1], dtype=float)
        res["energy"] = {v: float(ds[v].values[-1]) for v in ds.data_vars
                         if v.startswith("energy_") and ds[v].dims == ("time",)}
        imp = {}
        n = ds.sizes.get("impact", 0)
        for v in _IMPACT_VARS:
            if v in ds.variables:
                a = np.asarray(ds[v].values)[:n_impacts]
                fill = -1 if v == "impact_inter" else np.nan
                pad = np.full(n_impacts, fill, dtype=int if v == "impact_inter" else float)
                pad[:len(a)] = a
                imp[v] = pad
        res["impacts"] = imp
        res["n_impacts"] = int(n)
        series = {}
        for name in outputs:
            if name not in ds.variables:
                raise ValueError(f"outputs: no variable {name!r} in the results file (its time series: "
                                 f"{', '.join(v for v in ds.data_vars if ds[v].dims[:1] == ('time',))})")
            var = ds[name]
            if var.dims[:1] != ("time",):
                raise ValueError(f"outputs: {name!r} is not a time series (dimensions {var.dims})")
            a = np.asarray(var.values, dtype=float)
            flat = a.reshape(len(t), -1)
            out = np.empty((len(times), flat.shape[1]))
            for j in range(flat.shape[1]):
                out[:, j] = np.interp(times, t, flat[:, j], left=np.nan, right=np.nan)
            series[name] = (out.reshape((len(times),) + a.shape[1:]), var.dims[1:], dict(var.attrs))
        res["series"] = series
        return res
    except Exception as e:  # a failure of this function, not of the run: the case records it
        res.update(status=-1, exit_code=1, message=f"{type(e).__name__}: {e}")
        return res
    finally:
        if tmp is not None:
            shutil.rmtree(tmp, ignore_errors=True)


def _client(client, workers):
    """(client, things to close): the given Client, a Client on a scheduler
    address, or a LocalCluster with worker processes."""
    from distributed import Client, LocalCluster
    if client is None:
        n = workers or os.cpu_count() or 1
        cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=None)
        c = Client(cluster)
        return c, [c, cluster]
    if isinstance(client, str):
        c = Client(client)
        return c, [c]
    return client, []


def study(deck, parameters, client=None, outputs=(), times=None, set=None, n_impacts=5, keep_dir=None,
          workers=None, **run_kw):
    """Run one case per parameter set on Dask and gather the results.

    deck        the case file (its text is sent to the workers, so they need
                no shared file system; a deck with #include is read by the
                workers at its path), or a ricochet.deck.Deck
    parameters  {field: [values]} (full factorial), a list of {field: value},
                or lhs({field: (lo, hi)}, n, seed)
    client      None: a distributed.LocalCluster with `workers` processes
                (default: one per CPU), closed at the end; a
                distributed.Client; or a scheduler address ("tcp://host:8786")
    outputs     names of time series of the results file (e.g.
                "body_position", "inter_force_normal", "energy_total") to
                interpolate (linearly) at `times` [s]; NaN outside a case's run
    set         overrides common to every case (as ``run``'s set)
    n_impacts   rows of the impact table kept per case (padded with NaN,
                impact_inter with -1)
    keep_dir    a directory (seen by the workers) where each case's results
                file is kept as case_NNNN.nc; None: not kept
    run_kw      t_end, dt_out, rtol, method, on_violation, preload: as ``run``

    Returns an xarray.Dataset with dimension ``case``: the parameters (one
    variable per field, its name made netCDF-safe, the field in its
    attribute ``field``), status / exit_code / message per case (a failing
    case does not stop the study), final_time [s], final_body_position [m],
    final_body_quaternion [-], final_body_velocity [m/s],
    final_body_angular_velocity [rad/s] (body frame), the energy ledger at
    the end (final_energy_* [J]), the first impacts (impact_*; dimension
    ``impact``) and impact_count, and the outputs (dimensions case, time,
    ...).
    """
    import numpy as np
    import xarray as xr
    cases = _cases(parameters)
    fields = list(cases[0])
    common = {}
    if set is not None:
        from .sim import format_set
        for s in format_set(set):
            k, _, v = s.partition("=")
            common[k] = v
    for f in fields:
        if f in common:
            raise ValueError(f"study: {f!r} is both a study parameter and in set=")
    bad = [k for k in run_kw if k not in ("t_end", "dt_out", "rtol", "method", "on_violation", "preload")]
    if bad:
        raise TypeError(f"study: unexpected arguments {bad}")
    if isinstance(outputs, str):
        outputs = (outputs,)
    outputs = tuple(outputs)
    if outputs and times is None:
        raise ValueError("study: outputs need the times to interpolate them at (times=[...] in s)")
    times = np.asarray(times if times is not None else [], dtype=float)
    if times.ndim != 1 or not np.all(np.isfinite(times)):
        raise ValueError("study: times must be a 1-D sequence of finite times [s]")
    varnames = {}
    for f in fields:
        v = _varname(f)
        if v in varnames.values() or v in ("status", "exit_code", "message", "case"):
            raise ValueError(f"study: parameters {f!r} and another give the same variable name {v!r}")
        varnames[f] = v

    # the deck: its text travels with the task unless it includes other files
    if hasattr(deck, "text") and callable(deck.text):
        text, name = deck.text(), "deck.rad"
    else:
        path = os.fspath(deck)
        with open(path) as fh:
            text = fh.read()
        name = path
        if re.search(r"^#include", text, re.M):
            text, name = os.path.abspath(path), None  # the workers read it (and its includes) at its path

    if keep_dir is not None:
        os.makedirs(keep_dir, exist_ok=True)
    c, to_close = _client(client, workers)
    try:
        from distributed import as_completed
        futures = {}
        for i, case in enumerate(cases):
            ov = dict(common)
            ov.update(case)
            keep = None if keep_dir is None else os.path.join(os.path.abspath(keep_dir), f"case_{i:04d}.nc")
            fut = c.submit(run_case, text, name, ov, dict(run_kw), outputs, times, n_impacts, keep,
                           key=f"ricochet-case-{i}-{os.getpid()}-{id(cases)}", pure=False)
            futures[fut] = i
        results = [None] * len(cases)
        for fut in as_completed(list(futures)):
            i = futures[fut]
            try:
                results[i] = fut.result()
            except Exception as e:  # the worker died (or the task could not run there)
                results[i] = {"status": -2, "exit_code": 1, "message": f"worker failed: {type(e).__name__}: {e}"}
    finally:
        for x in to_close:
            x.close()

    return _assemble(cases, fields, varnames, common, results, outputs, times, n_impacts, run_kw)


def _assemble(cases, fields, varnames, common, results, outputs, times, n_impacts, run_kw):
    import numpy as np
    import xarray as xr
    n = len(cases)
    ds = xr.Dataset(coords={"case": np.arange(n)})
    for f in fields:
        vals = [c[f] for c in cases]
        arr = np.asarray(vals) if all(isinstance(v, numbers.Real) and not isinstance(v, bool) for v in vals) \
            else np.asarray([str(v) for v in vals], dtype=object)
        ds[varnames[f]] = ("case", arr, {"field": f, "long_name": f"{f} (in its card's units)"})
    ds["status"] = ("case", np.array([r["status"] for r in results], dtype=int),
                    {"long_name": "rc_status of the case: 0 ok, 2 input, 3 solver, 4 I/O, 7 interrupted, "
                                  "8 physics check; -1 a Python error, -2 the worker failed"})
    ds["exit_code"] = ("case", np.array([r["exit_code"] for r in results], dtype=int),
                       {"long_name": "exit code `ricochet run` gives for the status"})
    ds["message"] = ("case", np.array([r["message"] for r in results], dtype=object),
                     {"long_name": "the error message (empty: success)"})
    ok = [r for r in results if "body" in r]
    if ok:
        bodies = ok[0]["body"]
        ds = ds.assign_coords(body=("body", bodies), vec3=["x", "y", "z"], quat=["w", "x", "y", "z"])
        ds["final_time"] = ("case", np.array([r.get("final_time", np.nan) for r in results]),
                            {"units": "s", "long_name": "time of the last record (the end time unless the run failed)"})
        units = {"body_position": ("m", "vec3", "centre of mass, deck's coordinates"),
                 "body_quaternion": ("1", "quat", "unit quaternion (w, x, y, z), body to global"),
                 "body_velocity": ("m s-1", "vec3", "velocity of the centre of mass, global frame"),
                 "body_angular_velocity": ("rad s-1", "vec3", "angular velocity, body frame")}
        for v in _BODY_VARS:
            u, comp, ln = units[v]
            a = np.full((n, len(bodies), 4 if comp == "quat" else 3), np.nan)
            for i, r in enumerate(results):
                if "final_" + v in r and len(r["body"]) == len(bodies):
                    a[i] = r["final_" + v]
            ds["final_" + v] = (("case", "body", comp), a, {"units": u, "long_name": ln + " at final_time"})
        enames = sorted({k for r in ok for k in r["energy"]})
        for e in enames:
            ds["final_" + e] = ("case", np.array([r.get("energy", {}).get(e, np.nan) for r in results]),
                                {"units": "J", "long_name": f"{e} at final_time (energy ledger, docs/output-format.md)"})
        inames = [v for v in _IMPACT_VARS if any(v in r["impacts"] for r in ok)]
        if inames:
            ds["impact_count"] = ("case", np.array([r.get("n_impacts", -1) for r in results]),
                                  {"long_name": "impacts of the run (all of them; the table keeps the first n_impacts)"})
            iunits = {"impact_inter": "1", "impact_max_penetration": "m", "impact_peak_force": "N",
                      "impact_speed_in": "m s-1", "impact_speed_out": "m s-1", "impact_restitution": "1",
                      "impact_energy_lost": "J"}
            for v in inames:
                fill = -1 if v == "impact_inter" else np.nan
                a = np.full((n, n_impacts), fill, dtype=int if v == "impact_inter" else float)
                for i, r in enumerate(results):
                    if v in r.get("impacts", {}):
                        a[i] = r["impacts"][v]
                ds[v] = (("case", "impact"), a, {"units": iunits.get(v, "s"),
                                                 "long_name": f"{v} of the first impacts (padded: NaN, -1)"})
    if outputs:
        ds = ds.assign_coords(time=("time", times, {"units": "s", "long_name": "common times of the outputs"}))
        for name in outputs:
            first = next((r["series"][name] for r in ok if name in r.get("series", {})), None)
            if first is None:
                continue
            shape, dims, attrs = first[0].shape, first[1], first[2]
            a = np.full((n,) + shape, np.nan)
            for i, r in enumerate(results):
                if name in r.get("series", {}):
                    a[i] = r["series"][name][0]
            attrs = {k: v for k, v in attrs.items() if k in ("units", "long_name", "comment")}
            ds[name] = (("case", "time") + tuple(dims), a, attrs)
    ds.attrs["title"] = "ricochet study"
    ds.attrs["parameters"] = "; ".join(f"{varnames[f]} = {f}" for f in fields)
    if common:
        ds.attrs["overrides_common"] = "; ".join(f"{k}={v}" for k, v in common.items())
    ds.attrs["run_options"] = "; ".join(f"{k}={v!r}" for k, v in run_kw.items()) or "the deck's"
    ds.attrs["cases"] = n
    ds.attrs["failed_cases"] = int(sum(r["status"] != 0 for r in results))
    return ds
