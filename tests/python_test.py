"""The Python module (python/ricochet): the reader with and without xarray,
the deck writer shared with validation/lib. Prints PASS/FAIL lines.

    PYTHONPATH=<dir holding ricochet/> /usr/bin/python3 tests/python_test.py build/ricochet
"""
# SPDX-License-Identifier: GPL-3.0-or-later
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np

import ricochet
from ricochet.deck import Deck

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BIN = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "ricochet"))
failed = 0


def check(name, ok, detail=""):
    global failed
    print(("PASS " if ok else "FAIL ") + "python." + name + (": " + detail if detail else ""))
    failed += not ok


tmp = tempfile.mkdtemp(prefix="rc-python-test-")
out = os.path.join(tmp, "demo.nc")
subprocess.run([BIN, "run", os.path.join(ROOT, "cases", "demo_sphere_drop.rad"), "-o", out, "-q"], check=True)

check("module_location", True, ricochet.__file__)
# without xarray: a dict of numpy arrays
r = ricochet.read(out, xarray=False)
nt = r["time"].shape[0]
kinds = [str(k) for k in r["event_kind"]]
check("read_dict", isinstance(r, dict) and isinstance(r["body_position"], np.ndarray)
      and r["body_position"].shape[0] == nt and r.dims["body_position"][0] == "time"
      and r.attrs["complete"] == "yes" and len(kinds) == int(r.attrs["stats_events"]) == 21
      and kinds.count("contact_close") == 7 and abs(r["time"][-1] - 1.0) < 1e-15,
      f"{nt} records, {len(kinds)} events, {kinds.count('contact_close')} impacts, last t = {r['time'][-1]}")
try:
    import xarray  # noqa: F401
    have_xr = True
except ImportError:
    have_xr = False
if have_xr:
    ds = ricochet.read(out)
    same = all(np.array_equal(np.asarray(ds[v].values), r[v], equal_nan=True)
               for v in ("time", "body_position", "inter_force_normal", "event_time"))
    check("read_xarray", type(ds).__name__ == "Dataset" and ds.sizes["time"] == nt and same
          and ds.attrs["complete"] == "yes",
          f"xarray {xarray.__version__}: Dataset with {ds.sizes['time']} records, same values as the dict")
    z = ds.body_position.sel(vec3="z").values
    w = ds.body_quaternion.sel(quat="w").values
    check("read_xarray_labels", np.array_equal(z, r["body_position"][..., 2]) and np.array_equal(w, r["body_quaternion"][..., 0]),
          "body_position.sel(vec3='z') and body_quaternion.sel(quat='w') are the z and w components")
else:
    print("SKIP python.read_xarray: xarray not installed (Debian python3-xarray)")

# the deck writer is one code: validation/lib/deck.py re-exports ricochet.deck
sys.path.insert(0, os.path.join(ROOT, "validation", "lib"))
import deck as vdeck  # noqa: E402
src = os.path.join(ROOT, "python", "ricochet", "deck.py")
check("deck_shared", vdeck.Deck is ricochet.deck.Deck or
      (vdeck.Deck.__module__ == "ricochet.deck" and open(src).read() == open(ricochet.deck.__file__).read()),
      "validation/lib/deck.py imports ricochet.deck")

# a deck written with it reads and runs
d = Deck("python test: sphere on a plane")
d.nodes([(1, 0.0, 0.0, 0.2)])
d.rbody(1, 1, 1.0, (0.001, 0.001, 0.001))
d.sphere(1, 1, (0.0, 0.0, 0.2), 0.05)
d.plane(2, (0.0, 0.0, 0.0), (0.0, 0.0, 1.0))
d.grnod(1, [1])
d.grav(1, "Z", -9.81, 1)
d.funct(1, [0.0, 1.0], [0.0, 1e5])
d.type6(1, 1, 2, 1)
d.run(0.3, 0.01)
text = d.text()
path = os.path.join(tmp, "py.rad")
d.write(path)
p = subprocess.run([BIN, "check", path], capture_output=True, text=True)
msg = (p.stdout + p.stderr).strip().splitlines()
check("deck_written", p.returncode == 0 and "interfaces  1" in p.stdout and text.startswith("#RADIOSS STARTER"),
      f"ricochet check exit {p.returncode}: {msg[0][:100] if msg else ''}")
shutil.rmtree(tmp, ignore_errors=True)
sys.exit(1 if failed else 0)
