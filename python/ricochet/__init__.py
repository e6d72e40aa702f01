"""ricochet from Python: read the results, write case decks.

    import ricochet
    ds = ricochet.read("out/demo.nc")    # xarray.Dataset when xarray is installed,
                                         # else a dict of numpy arrays (ricochet.Results)
    from ricochet.deck import Deck       # the fixed-width deck writer

The results file is netCDF-4 (docs/output-format.md); the simulator itself
is the `ricochet` program and the C library (docs/embedding.md).
"""
# SPDX-License-Identifier: GPL-3.0-or-later
from . import deck  # noqa: F401
from .results import Results, read  # noqa: F401

__all__ = ["read", "Results", "deck"]
