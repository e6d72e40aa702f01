"""The deck writer of the validation problems and the benchmarks.

It is the ricochet Python module's ``ricochet.deck`` (python/ricochet/deck.py);
this file only makes it importable as ``deck`` from validation/lib, without
installing the module.
"""
# SPDX-License-Identifier: GPL-3.0-or-later
import os
import sys

_PY = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python")
if _PY not in sys.path:
    sys.path.insert(0, _PY)

from ricochet.deck import Deck, i10, line, r20  # noqa: E402,F401
