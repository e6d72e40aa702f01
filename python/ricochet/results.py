"""Read a ricochet results file (netCDF-4, docs/output-format.md).

``read(path)`` returns an ``xarray.Dataset`` when xarray is installed
(its ``vec3`` and ``quat`` dimensions labelled x, y, z and w, x, y, z, so
that ``ds.body_position.sel(vec3="z")`` is the heights)
(Debian: python3-xarray), else a ``Results``: a dict of numpy arrays, one
per variable, with the global attributes in ``.attrs``, the variables'
attributes in ``.var_attrs`` and the dimensions of each variable in
``.dims``. Both are read whole into memory and the file is closed: a file
still being written, or one marked incomplete (``attrs["complete"] ==
"no"``, the reason in ``attrs["status"]``), reads the records it has.
"""
# SPDX-License-Identifier: GPL-3.0-or-later
import numpy as np


class Results(dict):
    """Variables of a results file as numpy arrays (a dict), with
    ``attrs`` (global attributes), ``var_attrs`` (per variable) and ``dims``
    (dimension names per variable)."""

    def __init__(self):
        super().__init__()
        self.attrs = {}
        self.var_attrs = {}
        self.dims = {}

    def __repr__(self):
        return "<ricochet.Results %s: %s>" % (self.attrs.get("title", "?"),
                                              ", ".join(f"{k}{self.dims[k]}" for k in self))


def _have_xarray():
    try:
        import xarray  # noqa: F401
        return True
    except ImportError:
        return False


def read(path, xarray=None):
    """The results at ``path``: an xarray.Dataset if ``xarray`` is True, or
    None and xarray is installed; else a Results (dict of numpy arrays).
    Fill values stay as stored (NaN where the file has NaN)."""
    from ._lib import netcdf_guard
    with netcdf_guard():  # runs of other threads may be writing (docs/python.md, "Threads")
        return _read(path, xarray)


def _read(path, xarray):
    if xarray is None:
        xarray = _have_xarray()
    if xarray:
        import xarray as xr
        # time stays in seconds (the file's time axis is CF-decodable to
        # dates from an arbitrary origin, which is no use here)
        with xr.open_dataset(path, engine="netcdf4", mask_and_scale=False, decode_times=False) as ds:
            ds = ds.load()
        # the components by name: ds.body_position.sel(vec3="z"),
        # ds.body_quaternion.sel(quat="w")
        labels = {"vec3": ["x", "y", "z"], "quat": ["w", "x", "y", "z"]}
        return ds.assign_coords({d: v for d, v in labels.items() if d in ds.dims and ds.sizes[d] == len(v)})
    from netCDF4 import Dataset
    out = Results()
    with Dataset(path, "r") as nc:
        nc.set_auto_mask(False)
        out.attrs = {k: nc.getncattr(k) for k in nc.ncattrs()}
        for name, var in nc.variables.items():
            out[name] = np.asarray(var[...])
            out.var_attrs[name] = {k: var.getncattr(k) for k in var.ncattrs()}
            out.dims[name] = tuple(var.dimensions)
    return out
