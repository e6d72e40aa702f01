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
import hashlib
import itertools
import json
import math
import numbers
import os
import re
import shutil
import tempfile

__all__ = ["study", "grid", "lhs", "run_case", "StudyDirError"]

# the study directory (study_dir=): its manifest, and per case the results
# file and the summary (the gathered values, JSON; docs/python.md, "Nothing lost")
MANIFEST = "study.json"
_MANIFEST_VERSION = 1


class StudyDirError(ValueError):
    """The study directory holds another study (a different deck, parameters
    or options than its manifest's)."""

# the last values kept of every body (the results file's variables)
_BODY_VARS = ("body_position", "body_quaternion", "body_velocity", "body_angular_velocity")
# the impact table's columns (docs/output-format.md, "Impacts table")
_IMPACT_VARS = ("impact_inter", "impact_close_time", "impact_open_time", "impact_duration", "impact_max_penetration",
                "impact_max_penetration_time", "impact_peak_force", "impact_peak_force_time", "impact_speed_in",
                "impact_speed_out", "impact_restitution", "impact_energy_lost")
# the persistent contacts table's columns (docs/output-format.md, "Persistent contacts table")
_PERSIST_VARS = ("persistent_inter", "persistent_close_time", "persistent_open_time", "persistent_duration",
                 "persistent_peak_force", "persistent_mean_force", "persistent_max_penetration",
                 "persistent_slip_distance")


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


def _padded_table(ds, dim, names, n_rows):
    """The first n_rows rows of a table of the results file (the impacts,
    the persistent contacts): {variable: array of n_rows}, padded with -1
    (the interface id column, *_inter) or NaN; and the table's length."""
    import numpy as np

    table = {}
    for v in names:
        if v in ds.variables:
            a = np.asarray(ds[v].values)[:n_rows]
            ids = v.endswith("_inter")
            pad = np.full(n_rows, -1 if ids else np.nan, dtype=int if ids else float)
            pad[:len(a)] = a
            table[v] = pad
    return table, int(ds.sizes.get(dim, 0))


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
    final = keep
    if keep is not None:  # written under a name of its own, renamed at the end: a cancelled task still
        import uuid       # running (or a rerun) never writes into the file another one reads
        keep = f"{keep}.{uuid.uuid4().hex[:8]}.part"
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
        res["impacts"], res["n_impacts"] = _padded_table(ds, "impact", _IMPACT_VARS, n_impacts)
        res["persistent"], res["n_persistent"] = _padded_table(ds, "persistent", _PERSIST_VARS, n_impacts)
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
        if keep is not None and os.path.exists(keep):
            os.replace(keep, final)


def _enc(x):
    """A case's result as JSON-able values, exactly: arrays keep their dtype
    and shape, floats their bits (repr round-trips; NaN as NaN)."""
    import numpy as np
    if isinstance(x, np.ndarray):
        if x.dtype == object:
            return {"__nd__": "O", "shape": list(x.shape), "data": [_enc(v) for v in x.ravel().tolist()]}
        return {"__nd__": x.dtype.str, "shape": list(x.shape), "data": x.ravel().tolist()}
    if isinstance(x, np.generic):
        return x.item()
    if isinstance(x, dict):
        return {str(k): _enc(v) for k, v in x.items()}
    if isinstance(x, tuple):
        return {"__tuple__": [_enc(v) for v in x]}
    if isinstance(x, list):
        return [_enc(v) for v in x]
    return x


def _dec(x):
    import numpy as np
    if isinstance(x, dict):
        if "__nd__" in x:
            dt = object if x["__nd__"] == "O" else np.dtype(x["__nd__"])
            data = [_dec(v) for v in x["data"]] if dt is object else x["data"]
            return np.array(data, dtype=dt).reshape(x["shape"])
        if "__tuple__" in x:
            return tuple(_dec(v) for v in x["__tuple__"])
        return {k: _dec(v) for k, v in x.items()}
    if isinstance(x, list):
        return [_dec(v) for v in x]
    return x


def _canon(x):
    """x as its JSON text reads back (the form the manifest compares)."""
    return json.loads(json.dumps(_enc(x), allow_nan=True))


def _write_json(path, obj):
    """Write atomically: a reader (or a rerun after a crash) sees the old file
    or the whole new one, never a part."""
    tmp = f"{path}.{os.getpid()}.tmp"
    with open(tmp, "w") as f:
        json.dump(obj, f, indent=1, allow_nan=True)
        f.flush()
        os.fsync(f.fileno())
    os.replace(tmp, path)


def _case_files(study_dir, i):
    return (os.path.join(study_dir, f"case_{i:04d}.nc"), os.path.join(study_dir, f"case_{i:04d}.json"))


def _open_study_dir(study_dir, manifest):
    """Create the directory and its manifest, or check that the manifest there
    is this study's; returns {case: result} of the cases already done (a
    summary whose status is the run's own: not -1, a Python error, nor -2,
    a lost worker, which run again)."""
    os.makedirs(study_dir, exist_ok=True)
    mpath = os.path.join(study_dir, MANIFEST)
    want = _canon(manifest)
    if os.path.exists(mpath):
        with open(mpath) as f:
            try:
                have = json.load(f)
            except ValueError as e:
                raise StudyDirError(f"study: {mpath} is not a study manifest ({e})") from None
        if not isinstance(have, dict) or have.get("version") != _MANIFEST_VERSION:
            raise StudyDirError(f"study: {mpath} is not a version {_MANIFEST_VERSION} study manifest")
        for k in ("deck_sha256", "cases", "common", "run_options", "outputs", "times", "n_impacts"):
            if have.get(k) != want.get(k):
                what = {"deck_sha256": f"the deck differs (sha256 {str(have.get(k))[:12]}... there, "
                                       f"{str(want.get(k))[:12]}... now: {want.get('deck')})",
                        "cases": "the parameter sets differ", "common": "the common set= overrides differ",
                        "run_options": "the run options differ", "outputs": "the outputs differ",
                        "times": "the output times differ", "n_impacts": "n_impacts differs"}[k]
                raise StudyDirError(f"study: {study_dir} holds another study: {what}; use another study_dir "
                                    f"(or remove that one)")
    else:
        _write_json(mpath, want)
    done = {}
    for i in range(len(manifest["cases"])):
        nc, js = _case_files(study_dir, i)
        if not os.path.exists(js):
            continue
        try:
            with open(js) as f:
                summ = json.load(f)
            r = _dec(summ["result"])
        except (OSError, ValueError, KeyError):
            continue  # unreadable: run the case again
        if summ.get("case") == i and r.get("status") not in (-1, -2):
            done[i] = r
    return done


def _summary(i, case, r, nc):
    return {"case": i, "parameters": _enc(case), "status": r.get("status"), "message": r.get("message", ""),
            "results_file": os.path.basename(nc) if os.path.exists(nc) else None, "result": _enc(r)}


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
          workers=None, study_dir=None, on_case=None, **run_kw):
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
    study_dir   a directory (the workers write the results files there):
                the manifest study.json (the deck's path and sha256, the
                parameter sets, set=, the run options, outputs, times,
                n_impacts), per case its results file case_NNNN.nc and its
                summary case_NNNN.json (the values gathered). Rerunning the
                same study with the same directory runs only the cases not
                done (no summary, or status -1/-2) and gives the same
                Dataset; a directory holding another study (a different
                deck, parameters or options) raises StudyDirError
    keep_dir    the older name of study_dir (the same behaviour); None: the
                results files are temporary, nothing is kept
    on_case     None, or a function f(case, status) called in this process
                as each case ends (not for the cases found done); an
                exception from it stops the study: the pending cases are
                cancelled, the exception propagates, the cases done so far
                stay in study_dir
    run_kw      t_end, dt_out, rtol, method, on_violation, preload, switch: as ``run``

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
    bad = [k for k in run_kw if k not in ("t_end", "dt_out", "rtol", "method", "on_violation", "preload", "switch")]
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
        deck_path, sha = None, hashlib.sha256(text.encode()).hexdigest()
    else:
        path = os.fspath(deck)
        with open(path, "rb") as fh:
            raw = fh.read()
        text, name = raw.decode(), path
        deck_path, sha = os.path.abspath(path), hashlib.sha256(raw).hexdigest()
        if re.search(r"^#include", text, re.M):
            text, name = os.path.abspath(path), None  # the workers read it (and its includes) at its path

    # the study directory: what is there already is checked and kept
    if study_dir is not None and keep_dir is not None and \
            os.path.abspath(os.fspath(study_dir)) != os.path.abspath(os.fspath(keep_dir)):
        raise ValueError("study: keep_dir is the older name of study_dir: give one of them")
    sdir = study_dir if study_dir is not None else keep_dir
    results = [None] * len(cases)
    if sdir is not None:
        sdir = os.path.abspath(os.fspath(sdir))
        manifest = {"version": _MANIFEST_VERSION, "deck": deck_path, "deck_sha256": sha, "cases": cases,
                    "common": common, "run_options": dict(run_kw), "outputs": list(outputs),
                    "times": times, "n_impacts": n_impacts}
        for i, r in _open_study_dir(sdir, manifest).items():
            results[i] = r
    todo = [i for i, r in enumerate(results) if r is None]

    if todo:
        c, to_close = _client(client, workers)
        futures = {}
        try:
            import uuid
            from distributed import as_completed
            tag = uuid.uuid4().hex[:12]
            for i in todo:
                ov = dict(common)
                ov.update(cases[i])
                keep = None if sdir is None else _case_files(sdir, i)[0]
                # retries=1: a case whose task fails is run once more; a case on a
                # worker that dies is rescheduled by the scheduler (up to its
                # distributed.scheduler.allowed-failures), then ends KilledWorker
                fut = c.submit(run_case, text, name, ov, dict(run_kw), outputs, times, n_impacts, keep,
                               key=f"ricochet-case-{i}-{tag}", pure=False, retries=1)
                futures[fut] = i
            for fut in as_completed(list(futures)):
                i = futures.pop(fut)
                try:
                    r = fut.result()
                except Exception as e:  # the worker died (KilledWorker) or the task could not run there
                    r = {"status": -2, "exit_code": 1, "message": f"worker failed: {type(e).__name__}: {e}"}
                results[i] = r
                if sdir is not None:
                    nc, js = _case_files(sdir, i)
                    _write_json(js, _summary(i, cases[i], r, nc))
                if on_case is not None:
                    on_case(i, int(r["status"]))
        finally:
            if futures:  # stopped early: the cases not ended are cancelled
                try:
                    c.cancel(list(futures))
                except Exception:  # noqa: BLE001 (closing anyway)
                    pass
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
        pnames = [v for v in _PERSIST_VARS if any(v in r.get("persistent", {}) for r in ok)]
        if pnames:
            ds["persistent_count"] = ("case", np.array([r.get("n_persistent", -1) for r in results]),
                                      {"long_name": "persistent contacts of the run (all of them; the table keeps "
                                                    "the first n_impacts)"})
            punits = {"persistent_inter": "1", "persistent_peak_force": "N", "persistent_mean_force": "N",
                      "persistent_max_penetration": "m", "persistent_slip_distance": "m"}
            for v in pnames:
                fill = -1 if v == "persistent_inter" else np.nan
                a = np.full((n, n_impacts), fill, dtype=int if v == "persistent_inter" else float)
                for i, r in enumerate(results):
                    if v in r.get("persistent", {}):
                        a[i] = r["persistent"][v]
                ds[v] = (("case", "persistent"), a,
                         {"units": punits.get(v, "s"), "long_name": f"{v} of the first persistent contacts "
                                                                    "(padded: NaN, -1)"})
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
