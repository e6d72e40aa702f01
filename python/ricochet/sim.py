"""Run simulations from Python: ``run`` (one call, the results as an
xarray.Dataset) and ``Session`` (a run advanced in pieces, with the state in
between), over libricochet's ``rc_run`` and sessions (docs/python.md).

Units are SI (a deck in other named units is converted when read): times
[s], positions [m], velocities [m/s], angular velocities [rad/s] (body
frame), forces [N], energies [J].

Threads: the library's calls release the GIL (ctypes), so runs and sessions
in separate Python threads integrate in parallel. The event callback is
called with the GIL held: for ``run`` on the calling thread, for a
``Session`` on the session's integration thread (a thread of the library)
while the thread that called ``run_until`` waits. A Session is used by one
thread at a time: a second thread's call while one runs raises
RuntimeError.
"""
# SPDX-License-Identifier: GPL-3.0-or-later
import collections
import collections.abc
import math
import numbers
import os
import shutil
import tempfile
import threading
import warnings

from . import _lib
from .errors import InputError, RicochetError, RicochetIOError, Status, error_for

__all__ = ["run", "Session", "BodyState", "EventValues", "RunStats", "RicochetWarning", "format_set"]


class RicochetWarning(UserWarning):
    """A warning of the library: of the reading (ignored cards, unit
    conversions), or physics-check violations that a run went on after
    (``on_violation="warn"``)."""


# the values of an event: penetration P [m], approach speed dP/dt [m/s] (> 0
# approaching), normal force [N] after the event (NaN for a non-interface)
EventValues = collections.namedtuple("EventValues", "penetration approach_speed normal_force")

# a body's state: centre of mass in the deck's coordinates [m] (3), unit
# quaternion (w, x, y, z) body -> global [-] (4), velocity of the centre of
# mass, global frame [m/s] (3), angular velocity, body frame [rad/s] (3)
BodyState = collections.namedtuple("BodyState", "position quaternion velocity angular_velocity")

_METHODS = {"cvode": 1, "ida": 2, "static": 3, 1: 1, 2: 2, 3: 3}
_VIOLATION = {"stop": _lib.RC_ON_VIOLATION_STOP, "warn": _lib.RC_ON_VIOLATION_WARN}


class RunStats(dict):
    """Statistics of a run (``rc_stats``) as a dict: counters (steps,
    rhs_evals, jac_evals, lin_setups, nonlin_iters, nonlin_fails,
    err_test_fails, root_evals, events, reinits, impacts, settles,
    violations, preload_iters, switches_explicit, switches_implicit,
    steps_explicit, records_thinned), t_end [s] (simulated time reached), wall_time
    [s], energy_residual [J], t_settle [s] (NaN: none), preloaded (bool),
    preload_wall_time [s], the notes (sampling_note, physics_note,
    contacts_note, vibration_note, tolerance_note), ``impact``: the first 5 impacts as dicts (inter_id,
    t_close [s], t_open [s], duration [s], pen_max [m], t_pen_max [s],
    fn_max [N], t_fn_max [s], v_in [m/s], v_out [m/s], restitution [-],
    energy_lost [J]); ``contacts``, the number of persistent contacts, and
    ``contact``: the first 5 of them as dicts (inter_id, t_close [s], t_open
    [s] (NaN: still closed at the end), duration [s], fn_max [N], fn_mean
    [N], pen_max [m], slip [m]; docs/output-format.md, "Persistent contacts
    table"); and ``status`` (a Status) and ``message`` of the run."""


def _stats(s, status, message):
    out = RunStats()
    for name, _t in _lib.RcStats._fields_:
        v = getattr(s, name)
        if name == "impact":
            n = min(int(s.impacts), _lib.RC_STATS_IMPACTS)
            v = [{f: getattr(v[k], f) for f, _ in _lib.RcImpact._fields_} for k in range(n)]
        elif name == "contact":
            n = min(int(s.contacts), _lib.RC_STATS_CONTACTS)
            v = [{f: getattr(v[k], f) for f, _ in _lib.RcContact._fields_} for k in range(n)]
        elif isinstance(v, bytes):
            v = v.decode(errors="replace")
        out[name] = v
    out["preloaded"] = bool(out["preloaded"])
    out["status"] = Status(status)
    out["message"] = message
    return out


def _msg(err):
    return err.msg.decode(errors="replace")


def _raise(st, err, **kw):
    e = error_for(st, _msg(err), **kw)
    if isinstance(e, RicochetIOError):
        e.abandoned = bool(_lib.lib().rc_output_abandoned())
    raise e


def format_value(v):
    """The text of one ``set`` value: repr() of a float (it reads back as the
    same double), an int as written, a str as given."""
    if isinstance(v, bool):
        raise TypeError(f"set: a bool ({v}) is not a field value; give a number")
    if isinstance(v, numbers.Integral):
        return str(int(v))
    if isinstance(v, numbers.Real):
        return repr(float(v))
    if isinstance(v, str):
        return v
    raise TypeError(f"set: expected a number or a str for a field value, got {type(v).__name__} {v!r}")


def format_set(set):
    """The ``CARD:FIELD=VALUE`` strings of ``set``: a dict {"CARD:FIELD": value},
    or a list of such strings (None: none)."""
    if set is None:
        return []
    if isinstance(set, (str, bytes)):
        raise TypeError("set: expected a dict {'CARD:FIELD': value} or a list of 'CARD:FIELD=VALUE' strings, got a str")
    if isinstance(set, collections.abc.Mapping):
        out = []
        for k, v in set.items():
            if not isinstance(k, str):
                raise TypeError(f"set: expected 'CARD:FIELD' keys (e.g. '/INTER/TYPE6/1:Fric'), got {k!r}")
            out.append(f"{k}={format_value(v)}")
        return out
    out = list(set)
    for s in out:
        if not isinstance(s, str):
            raise TypeError(f"set: expected 'CARD:FIELD=VALUE' strings, got {s!r}")
    return out


def _positive(name, v):
    """t_end, dt_out: None (the deck's) or a finite number > 0 [s]; 0 is not
    taken as 'the deck's' (the C struct's convention) but refused."""
    if v is None:
        return 0.0
    if isinstance(v, bool) or not isinstance(v, numbers.Real) or not (math.isfinite(v) and v > 0):
        raise InputError(f"{name}: expected a positive finite number of seconds, got {v!r}")
    return float(v)


class _Model:
    """A deck read (with its overrides) and compiled; the case is freed once
    compiled. ``deck`` is a path, or a ricochet.deck.Deck written to a
    temporary file that lives as long as this object."""

    def __init__(self, deck, set=None, rtol=None, method=None, preload=None, switch=None):
        L = _lib.lib()
        self.ptr = None
        self._tmp = None
        sets = format_set(set)
        if hasattr(deck, "text") and callable(deck.text):  # a ricochet.deck.Deck
            self._tmp = tempfile.mkdtemp(prefix="ricochet-deck-")
            path = os.path.join(self._tmp, "deck.rad")
            with open(path, "w") as f:
                f.write(deck.text())
        else:
            path = os.fspath(deck)
        self.path = path
        if method is not None and method not in _METHODS:
            self.free()
            raise InputError(f"method: expected 'cvode', 'ida' or 'static' (or 1, 2, 3), got {method!r}")
        err = _lib.RcError()
        case = _lib.c_void_p()
        argv = (_lib.c_char_p * max(len(sets), 1))(*[s.encode() for s in sets])
        st = L.rc_case_load_set(os.fsencode(path), argv, len(sets), _lib.byref(case), _lib.byref(err))
        if st:
            self.free()
            _raise(st, err)
        for i in range(L.rc_case_warning_count(case)):
            warnings.warn(L.rc_case_warning(case, i).decode(errors="replace"), RicochetWarning, stacklevel=4)
        m = _lib.c_void_p()
        st = L.rc_model_compile(case, _lib.byref(m), _lib.byref(err))
        L.rc_case_free(case)
        if st:
            self.free()
            _raise(st, err)
        self.ptr = m
        for i in range(L.rc_model_note_count(m)):
            warnings.warn(L.rc_model_note(m, i).decode(errors="replace"), RicochetWarning, stacklevel=4)
        # in the order of `ricochet run`: the derived tolerances follow rtol
        st = 0
        if rtol is not None:
            if isinstance(rtol, bool) or not isinstance(rtol, numbers.Real):
                self.free()
                raise InputError(f"rtol: expected a number in (0, 1), got {rtol!r}")
            st = L.rc_model_set_rtol(m, float(rtol), _lib.byref(err))
        if not st and preload is False:
            st = L.rc_model_set_preload(m, 0, _lib.byref(err))
        if not st and method is not None:
            st = L.rc_model_set_method(m, _METHODS[method], _lib.byref(err))
        if not st and preload is True:
            st = L.rc_model_set_preload(m, 1, _lib.byref(err))
        if not st and switch is not None:
            if not isinstance(switch, bool):
                self.free()
                raise InputError(f"switch: expected True or False, got {switch!r}")
            st = L.rc_model_set_switch(m, int(switch), _lib.byref(err))
        if st:
            self.free()
            _raise(st, err)
        self.ny = L.rc_model_state_size(m)
        self.body_ids = [L.rc_model_body_id(m, i) for i in range(L.rc_model_body_count(m))]

    def free(self):
        if self.ptr is not None:
            _lib.lib().rc_model_free(self.ptr)
            self.ptr = None
        if self._tmp is not None:
            shutil.rmtree(self._tmp, ignore_errors=True)
            self._tmp = None

    def body(self, y, body_id):
        """BodyState of /RBODY body_id from a state vector y (a ctypes
        pointer to doubles, or None for a fixed body)."""
        if isinstance(body_id, bool) or not isinstance(body_id, numbers.Integral):
            raise TypeError(f"body: expected an /RBODY id (int), got {body_id!r}")
        import numpy as np
        out = (_lib.c_double * 13)()
        err = _lib.RcError()
        st = _lib.lib().rc_model_body_state(self.ptr, y, int(body_id), out, _lib.byref(err))
        if st:
            _raise(st, err)
        a = np.array(out[:], dtype=float)
        return BodyState(a[0:3], a[3:7], a[7:10], a[10:13])


class _Bridge:
    """The event callback: calls on_event(t, kind, element, values); a true
    return stops the run; an exception (any BaseException, KeyboardInterrupt
    included) is kept, stops the run, and is raised by the caller once the
    library has returned."""

    def __init__(self, fn):
        if not callable(fn):
            raise TypeError(f"on_event: expected a callable (t, kind, element, values), got {fn!r}")
        self.fn = fn
        self.exc = None
        self.thread = None  # ident of the thread running the callback, while it runs

        def call(user, t, kind, element, values):
            self.thread = threading.get_ident()
            try:
                v = EventValues(values[0], values[1], values[2])
                return 1 if fn(t, kind.decode(), element.decode(), v) else 0
            except BaseException as e:  # noqa: B902 (re-raised by the caller)
                self.exc = e
                return 1
            finally:
                self.thread = None
        self.cfunc = _lib.EVENT_FN(call)

    def reraise(self):
        if self.exc is not None:
            e, self.exc = self.exc, None
            raise e


def _options(path, t_end, dt_out, on_violation, bridge):
    opt = _lib.RcRunOptions()
    opt.output_path = os.fsencode(path) if path is not None else None
    opt.progress = 0
    opt.t_end_override = _positive("t_end", t_end)
    opt.dt_out_override = _positive("dt_out", dt_out)
    if on_violation is not None and on_violation not in _VIOLATION:
        raise InputError(f"on_violation: expected 'stop' or 'warn', got {on_violation!r}")
    opt.on_violation = _VIOLATION.get(on_violation, 0)
    if bridge is not None:
        opt.on_event = bridge.cfunc
    return opt


def run(deck, set=None, out=None, t_end=None, dt_out=None, rtol=None, method=None, on_event=None,
        on_violation=None, preload=None, switch=None, xarray=True):
    """Run a deck with libricochet and return its results.

    deck          path of the case file, or a ricochet.deck.Deck
    set           fields set by name as `ricochet run --set`: a dict
                  {"/INTER/TYPE6/1:Fric": 0.3} (values written with repr(),
                  which reads back as the same double) or a list of
                  "CARD:FIELD=VALUE" strings; each value is in its card's
                  own units (docs/case-format.md)
    out           results file to write and keep; None: a temporary file,
                  deleted once read
    t_end, dt_out end time and output interval [s] instead of the deck's
    rtol          relative tolerance instead of /SOLVER Rtol (the derived
                  absolute tolerances follow it)
    method        'cvode', 'ida' or 'static' (or 1, 2, 3) instead of /SOLVER Method
    on_event      callable(t [s], kind, element, values) called at every
                  event (values: EventValues, penetration [m], approach
                  speed [m/s], normal force [N]); a true return stops the
                  run (InterruptedRun); an exception stops it and is raised
    on_violation  'stop' or 'warn' (what a failed physics check does)
    preload       True/False: start from the static equilibrium or not
    switch        True/False: method switching between BDF and an explicit
                  method on the CVODE path (/SOLVER Switch, docs/theory.md 7.9)
    xarray        True: an xarray.Dataset; False: a ricochet.Results (dict
                  of numpy arrays, needs netCDF4)

    Returns the results read whole into memory (docs/output-format.md; the
    overrides in attrs["overrides"]). Raises InputError (nothing run),
    SolverError, PhysicsCheckError, InterruptedRun, RicochetIOError: their
    ``dataset`` holds the partial results the run kept.
    """
    from .results import read
    bridge = _Bridge(on_event) if on_event is not None else None
    model = _Model(deck, set=set, rtol=rtol, method=method, preload=preload, switch=switch)
    tmp = None
    try:
        if out is None:
            tmp = tempfile.mkdtemp(prefix="ricochet-run-")
            path = os.path.join(tmp, "results.nc")
        else:
            path = os.fspath(out)
        opt = _options(path, t_end, dt_out, on_violation, bridge)
        stats = _lib.RcStats()
        err = _lib.RcError()
        st = _lib.lib().rc_run(model.ptr, _lib.byref(opt), _lib.byref(stats), _lib.byref(err))
        rs = _stats(stats, st, _msg(err) if st else "")
        ds = None
        if st != Status.EINPUT and os.path.exists(path):
            try:
                ds = read(path, xarray=xarray)
            except Exception:
                if st == Status.OK:
                    raise
                ds = None  # the failed run's file did not read back; the run's error says why
        if bridge is not None:
            bridge.reraise()
        if st:
            _raise(st, err, dataset=ds, path=None if out is None else path, stats=rs)
        if rs["violations"] > 0:
            warnings.warn(f"physics checks: {rs['physics_note']}", RicochetWarning, stacklevel=2)
        return ds
    finally:
        model.free()
        if tmp is not None:
            shutil.rmtree(tmp, ignore_errors=True)


class Session:
    """A run advanced in pieces (libricochet's rc_session):

        with ricochet.Session("drop.rad") as s:
            while not s.finished:
                s.run_until(s.time + 0.01)
                print(s.time, s.body(1).position[2])

    The arguments are those of ``run`` (out=None: no results file). Opening
    starts the run at t = 0 (the initial state available). ``close()`` (or
    leaving the ``with``) ends it: a run not at its end time is stopped
    there (the file marked incomplete). Running in pieces gives the same
    steps, events and records as one ``run`` when the pieces end on output
    times (docs/embedding.md, "Stepping").
    """

    def __init__(self, deck, set=None, out=None, t_end=None, dt_out=None, rtol=None, method=None, on_event=None,
                 on_violation=None, preload=None, switch=None):
        self._ptr = None
        self._stats = None
        self._bridge = _Bridge(on_event) if on_event is not None else None
        self._lock = threading.Lock()
        self._model = _Model(deck, set=set, rtol=rtol, method=method, preload=preload, switch=switch)
        self.path = None if out is None else os.fspath(out)
        try:
            self._opt = _options(self.path, t_end, dt_out, on_violation, self._bridge)  # kept alive: the session uses it
            err = _lib.RcError()
            ptr = _lib.c_void_p()
            st = _lib.lib().rc_session_open(self._model.ptr, _lib.byref(self._opt), _lib.byref(ptr), _lib.byref(err))
            if self._bridge is not None:
                self._bridge.reraise()
            if st:
                _raise(st, err)
            self._ptr = ptr
        except BaseException:
            self._model.free()
            raise

    # -- the calls that integrate: one thread at a time ------------------
    def _enter(self, what):
        if self._ptr is None:
            raise RicochetError(f"Session.{what}: the session is closed")
        if self._bridge is not None and self._bridge.thread == threading.get_ident():
            return False  # from its own event callback: the library refuses it (InputError)
        if not self._lock.acquire(blocking=False):
            raise RuntimeError(f"Session.{what}: the session is in use by another thread (a Session is used "
                               f"by one thread at a time)")
        return True

    def run_until(self, t):
        """Advance to min(t, end time) [s] (math.inf: to the end time); a t at
        or before the time reached does nothing. Returns the time reached
        [s]. Raises the run's error (SolverError, PhysicsCheckError,
        InterruptedRun when the event callback stopped it, ...), or the
        exception the event callback raised."""
        if isinstance(t, bool) or not isinstance(t, numbers.Real):
            raise TypeError(f"run_until: expected a time in seconds, got {t!r}")
        locked = self._enter("run_until")
        try:
            err = _lib.RcError()
            st = _lib.lib().rc_run_until(self._ptr, float(t), _lib.byref(err))
        finally:
            if locked:
                self._lock.release()
        if self._bridge is not None and locked:
            self._bridge.reraise()
        if st:
            _raise(st, err, path=self.path)
        return self.time

    @property
    def time(self):
        """The time reached [s]."""
        if self._ptr is None:
            raise RicochetError("Session.time: the session is closed")
        return _lib.lib().rc_session_time(self._ptr)

    @property
    def finished(self):
        """True once the run reached its end time or ended on an error."""
        return self._ptr is None or bool(_lib.lib().rc_session_finished(self._ptr))

    @property
    def state(self):
        """A numpy copy of the state vector at ``time`` (layout in
        docs/theory.md; positions in the deck's coordinates)."""
        import numpy as np
        if self._ptr is None:
            raise RicochetError("Session.state: the session is closed")
        y = _lib.lib().rc_session_state(self._ptr)
        return np.ctypeslib.as_array(y, shape=(self._model.ny,)).copy()

    @property
    def bodies(self):
        """The /RBODY ids of the model (fixed bodies included)."""
        return list(self._model.body_ids)

    def body(self, body_id):
        """BodyState of /RBODY body_id at ``time``: position of the centre of
        mass in the deck's coordinates [m], quaternion (w, x, y, z) body ->
        global [-], velocity [m/s] (global frame), angular velocity [rad/s]
        (body frame); numpy arrays (copies). A fixed body: its pose, at rest."""
        if self._ptr is None:
            raise RicochetError("Session.body: the session is closed")
        return self._model.body(_lib.lib().rc_session_state(self._ptr), body_id)

    def close(self):
        """End the session (a run not at its end time is stopped there, its
        file marked incomplete) and return its RunStats, whose ``status`` and
        ``message`` say how the run ended (Status.EINTERRUPT, "stopped by the
        caller at t = ..." when closed early). The run's errors were raised
        by run_until; close does not raise them again. Closing twice returns
        the same stats."""
        if self._ptr is None:
            return self._stats
        locked = self._enter("close")
        try:
            stats = _lib.RcStats()
            err = _lib.RcError()
            st = _lib.lib().rc_session_close(self._ptr, _lib.byref(stats), _lib.byref(err))
            if st == Status.EINPUT and not locked:
                _raise(st, err)  # from its own event callback: refused, the session left open
            self._ptr = None
            self._stats = _stats(stats, st, _msg(err) if st else "")
        finally:
            if locked:
                self._lock.release()
        self._model.free()
        return self._stats

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    def __del__(self):
        try:
            if getattr(self, "_ptr", None) is not None:
                warnings.warn("ricochet.Session was not closed; closing it", ResourceWarning, stacklevel=2)
                self.close()
        except Exception:
            pass
