"""The C library through ctypes: where it is found, the structs of
include/ricochet/ricochet.h and the prototypes of the functions used.

Nothing here computes physics: every run is libricochet's ``rc_run`` or
session. The library is loaded on first use (``lib()``), not at import, so
that ``import ricochet`` works where only the results reader is wanted.

Lookup, first match wins, and a library that is named but fails to load is
an error, never a reason to try the next:

1. the environment variable ``RICOCHET_LIB``: the path of libricochet.so
   (only that one is tried);
2. the installed library: ``libricochet.so.0`` as the dynamic loader finds
   it (ld.so.cache, LD_LIBRARY_PATH), then ``<prefix>/lib/libricochet.so.0``
   for a module installed by ``make install`` in
   ``<prefix>/lib/python3.N/dist-packages/ricochet`` (a prefix whose lib/
   the loader's cache does not list yet: run ``ldconfig`` after installing
   in /usr/local, or use this);
3. in a source checkout (python/ricochet), the checkout's ``build/``.

The structs mirror the header of version 0.2 (``HEADER_VERSION``): a
library of another minor version is refused, as its structs may differ
(before 1.0 the binary interface changes between minor versions,
docs/embedding.md). tests/python_run_test.py checks the sizes and offsets
of the structs against the C compiler's.
"""
# SPDX-License-Identifier: GPL-3.0-or-later
import contextlib
import ctypes
import os
import threading

from .errors import RicochetError

# the major.minor version of include/ricochet/ricochet.h these structs mirror
HEADER_VERSION = "0.2"
SONAME = "libricochet.so.0"

c_int, c_long, c_double, c_char_p, c_void_p = ctypes.c_int, ctypes.c_long, ctypes.c_double, ctypes.c_char_p, ctypes.c_void_p
POINTER, byref = ctypes.POINTER, ctypes.byref

RC_STATS_IMPACTS = 5
RC_STATS_CONTACTS = 5
RC_ON_VIOLATION_STOP, RC_ON_VIOLATION_WARN = 1, 2


class RcError(ctypes.Structure):
    _fields_ = [("code", c_int), ("msg", ctypes.c_char * 8192), ("src_file", c_char_p), ("src_line", c_int),
                ("src_func", c_char_p)]


class RcImpact(ctypes.Structure):
    _fields_ = [("inter_id", c_int), ("t_close", c_double), ("t_open", c_double), ("duration", c_double),
                ("pen_max", c_double), ("t_pen_max", c_double), ("fn_max", c_double), ("t_fn_max", c_double),
                ("v_in", c_double), ("v_out", c_double), ("restitution", c_double), ("energy_lost", c_double)]


class RcContact(ctypes.Structure):
    _fields_ = [("inter_id", c_int), ("t_close", c_double), ("t_open", c_double), ("duration", c_double),
                ("fn_max", c_double), ("fn_mean", c_double), ("pen_max", c_double), ("slip", c_double)]


class RcStats(ctypes.Structure):
    _fields_ = [("steps", c_long), ("rhs_evals", c_long), ("jac_evals", c_long), ("lin_setups", c_long),
                ("nonlin_iters", c_long), ("nonlin_fails", c_long), ("err_test_fails", c_long),
                ("root_evals", c_long), ("events", c_long), ("reinits", c_long), ("t_end", c_double),
                ("wall_time", c_double), ("energy_residual", c_double), ("impacts", c_long),
                ("impact", RcImpact * RC_STATS_IMPACTS), ("sampling_note", ctypes.c_char * 320),
                ("settles", c_long), ("t_settle", c_double), ("violations", c_long),
                ("physics_note", ctypes.c_char * 640), ("contacts_note", ctypes.c_char * 640),
                ("preloaded", c_int), ("preload_iters", c_long), ("preload_wall_time", c_double),
                ("contacts", c_long), ("contact", RcContact * RC_STATS_CONTACTS),
                ("switches_explicit", c_long), ("switches_implicit", c_long), ("steps_explicit", c_long),
                ("records_thinned", c_long), ("vibration_note", ctypes.c_char * 480), ("tolerance_note", ctypes.c_char * 480)]


# int (*rc_event_fn)(void *user, double t, const char *kind, const char *element, const double values[3])
EVENT_FN = ctypes.CFUNCTYPE(c_int, c_void_p, c_double, c_char_p, c_char_p, POINTER(c_double))


class RcRunOptions(ctypes.Structure):
    _fields_ = [("output_path", c_char_p), ("progress", c_int), ("t_end_override", c_double),
                ("y_end", POINTER(c_double)), ("stop", POINTER(c_int)),  # volatile sig_atomic_t * (an int)
                ("dt_out_override", c_double), ("on_event", EVENT_FN), ("user", c_void_p),
                ("on_violation", c_int)]


_PROTOTYPES = {
    # name: (restype, argtypes)
    "rc_version": (c_char_p, []),
    "rc_build_commit": (c_char_p, []),
    "rc_status_str": (c_char_p, [c_int]),
    "rc_status_exit_code": (c_int, [c_int]),
    "rc_case_load_set": (c_int, [c_char_p, POINTER(c_char_p), c_int, POINTER(c_void_p), POINTER(RcError)]),
    "rc_case_free": (None, [c_void_p]),
    "rc_case_warning_count": (c_int, [c_void_p]),
    "rc_case_warning": (c_char_p, [c_void_p, c_int]),
    "rc_model_compile": (c_int, [c_void_p, POINTER(c_void_p), POINTER(RcError)]),
    "rc_model_free": (None, [c_void_p]),
    "rc_model_note_count": (c_int, [c_void_p]),
    "rc_model_note": (c_char_p, [c_void_p, c_int]),
    "rc_model_set_rtol": (c_int, [c_void_p, c_double, POINTER(RcError)]),
    "rc_model_set_method": (c_int, [c_void_p, c_int, POINTER(RcError)]),
    "rc_model_set_preload": (c_int, [c_void_p, c_int, POINTER(RcError)]),
    "rc_model_set_switch": (c_int, [c_void_p, c_int, POINTER(RcError)]),
    "rc_model_rtol": (c_double, [c_void_p]),
    "rc_model_t_end": (c_double, [c_void_p]),
    "rc_model_dt_out": (c_double, [c_void_p]),
    "rc_model_state_size": (c_int, [c_void_p]),
    "rc_model_body_count": (c_int, [c_void_p]),
    "rc_model_body_id": (c_int, [c_void_p, c_int]),
    "rc_model_body_index": (c_int, [c_void_p, c_int]),
    "rc_model_body_state": (c_int, [c_void_p, POINTER(c_double), c_int, POINTER(c_double), POINTER(RcError)]),
    "rc_run": (c_int, [c_void_p, POINTER(RcRunOptions), POINTER(RcStats), POINTER(RcError)]),
    "rc_output_abandoned": (c_int, []),
    "rc_netcdf_lock": (None, []),
    "rc_netcdf_unlock": (None, []),
    "rc_session_open": (c_int, [c_void_p, POINTER(RcRunOptions), POINTER(c_void_p), POINTER(RcError)]),
    "rc_run_until": (c_int, [c_void_p, c_double, POINTER(RcError)]),
    "rc_session_time": (c_double, [c_void_p]),
    "rc_session_state": (POINTER(c_double), [c_void_p]),
    "rc_session_finished": (c_int, [c_void_p]),
    "rc_session_close": (c_int, [c_void_p, POINTER(RcStats), POINTER(RcError)]),
}

_lock = threading.Lock()
_lib = None
_where = None


def _candidates():
    """(how, path) pairs to try, in order (see the module's docstring)."""
    env = os.environ.get("RICOCHET_LIB")
    if env:
        return [("RICOCHET_LIB", env)]
    here = os.path.dirname(os.path.abspath(__file__))
    out = [("the installed library (dynamic loader)", SONAME)]
    # <prefix>/lib/python3.N/dist-packages/ricochet -> <prefix>/lib
    parts = here.split(os.sep)
    if len(parts) >= 4 and parts[-2] in ("dist-packages", "site-packages") and parts[-3].startswith("python"):
        out.append(("the prefix the module is installed in", os.path.join(os.sep.join(parts[:-3]), SONAME)))
    # source checkout: python/ricochet -> build/
    root = os.path.dirname(os.path.dirname(here))
    if os.path.isfile(os.path.join(root, "include", "ricochet", "ricochet.h")):
        out.append(("the source checkout's build/", os.path.join(root, "build", SONAME)))
    return out


def _load():
    tried = []
    for how, path in _candidates():
        if os.sep in path and not os.path.exists(path):
            if how == "RICOCHET_LIB":
                raise RicochetError(f"RICOCHET_LIB={path}: no such file; expected the path of libricochet.so")
            tried.append(f"{how}: {path} (absent)")
            continue
        try:
            lib = ctypes.CDLL(path)
        except OSError as e:
            if how == "RICOCHET_LIB" or os.sep in path:
                # a library that is there but does not load is an error, not a reason to look further
                raise RicochetError(f"{how}: {path} does not load: {e}") from None
            tried.append(f"{how}: {path} ({e})")
            continue
        return lib, f"{path} ({how})"
    raise RicochetError("libricochet not found; tried " + "; ".join(tried) +
                        ". Install it (make install; then ldconfig), or set RICOCHET_LIB to the path of "
                        "libricochet.so (e.g. build/libricochet.so in a source checkout)")


def _bind(lib, where):
    for name, (res, args) in _PROTOTYPES.items():
        try:
            f = getattr(lib, name)
        except AttributeError:
            raise RicochetError(f"{where} has no function {name}: it is older than this module "
                                f"(ricochet {HEADER_VERSION}.x with rc_model_body_state); rebuild or "
                                f"reinstall the library") from None
        f.restype, f.argtypes = res, args
    version = lib.rc_version().decode()
    if ".".join(version.split(".")[:2]) != HEADER_VERSION:
        raise RicochetError(f"{where} is ricochet {version}; this Python module mirrors the structs of "
                            f"ricochet {HEADER_VERSION}.x (they may differ between minor versions before 1.0): "
                            f"install the module and the library from the same version")


def lib():
    """The loaded and checked library (loaded on the first call)."""
    global _lib, _where
    if _lib is None:
        with _lock:
            if _lib is None:
                lib_, where = _load()
                _bind(lib_, where)
                _where, _lib = where, lib_
    return _lib


def library_path():
    """Where the library was loaded from, and how it was found (loads it)."""
    lib()
    return _where


_tls = threading.local()


@contextlib.contextmanager
def netcdf_guard():
    """Around the module's own netCDF calls (reading a results file). When
    the library is loaded, runs of other threads may be writing their files
    at the same time: hold the library's netCDF lock (rc_netcdf_lock; HDF5
    under netCDF is not thread-safe), and switch HDF5's printing of its
    error stack off in this thread, as netCDF does in the thread that first
    uses it (else netCDF4-python's probes of optional attributes print
    HDF5-DIAG traces from other threads). No library loaded: nothing to do."""
    L = _lib
    if L is None:
        yield
        return
    if not getattr(_tls, "hdf5_quiet", False):
        # H5Eset_auto2(H5E_DEFAULT, NULL, NULL), found through the library's
        # dependencies (libnetcdf -> libhdf5); absent: HDF5 may print, harmless
        try:
            f = L.H5Eset_auto2
            f.restype, f.argtypes = c_int, [ctypes.c_int64, c_void_p, c_void_p]
            f(0, None, None)
        except AttributeError:
            pass
        _tls.hdf5_quiet = True
    L.rc_netcdf_lock()
    try:
        yield
    finally:
        L.rc_netcdf_unlock()
