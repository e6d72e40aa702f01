#!/usr/bin/env python3
"""Plot the measured against the fitted signals of `ricochet fit`
(docs/calibration.md).

    python3 scripts/plot_fit.py FITTED.csv [-o OUT.png] [--title TEXT]

FITTED.csv is the file `ricochet fit` writes (--fitted; default: the data
file's stem + _fit.csv): `t [UNIT]`, then per signal a measured and a
fitted column (`measured body 1 z [mm], fitted body 1 z [mm]`; blank where
nothing was measured). One panel per signal, measured as points and
fitted as a line, each with a panel of the residuals (measured - fitted)
below it, in the data's units. OUT.png defaults to FITTED.csv with .png.
Prints the name of the file written.

Dependencies: Debian's python3-numpy, python3-matplotlib.
"""
import argparse
import os
import re
import sys

import numpy as np


def main(argv=None):
    ap = argparse.ArgumentParser(description="measured against fitted signals of ricochet fit")
    ap.add_argument("fitted", help="the fitted-signals CSV of ricochet fit")
    ap.add_argument("-o", "--output", help="PNG to write (default: FITTED with .png)")
    ap.add_argument("--title", help="the picture's title (default: the file's name)")
    a = ap.parse_args(argv)
    try:
        with open(a.fitted) as f:
            header = [h.strip() for h in f.readline().split(",")]
        d = np.genfromtxt(a.fitted, delimiter=",", skip_header=1, ndmin=2)
    except OSError as e:
        sys.exit(f"plot_fit: {a.fitted}: {e.strerror}")
    pairs = []
    for k in range(1, len(header) - 1, 2):
        m = re.match(r"^measured (.*)$", header[k])
        if not m or header[k + 1] != "fitted " + m.group(1):
            sys.exit(f"plot_fit: {a.fitted}: column {k + 1}: expected 'measured NAME' then 'fitted NAME', "
                     f"got '{header[k]}', '{header[k + 1]}' (is it a file of ricochet fit?)")
        pairs.append((m.group(1), k))
    if not header[0].startswith("t [") or not pairs or d.shape[1] != len(header):
        sys.exit(f"plot_fit: {a.fitted}: expected 't [UNIT]' then measured and fitted columns")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    n = len(pairs)
    fig, ax = plt.subplots(2 * n, 1, figsize=(7, 3.6 * n), sharex=True,
                           gridspec_kw={"height_ratios": [3, 1] * n}, squeeze=False)
    t = d[:, 0]
    for i, (name, k) in enumerate(pairs):
        top, bot = ax[2 * i, 0], ax[2 * i + 1, 0]
        top.plot(t, d[:, k], ".", ms=3, label="measured")
        top.plot(t, d[:, k + 1], "-", lw=1, label="fitted")
        top.set_ylabel(name)
        top.legend(loc="best")
        unit = re.search(r"\[([^]]*)\]$", name)
        res = d[:, k] - d[:, k + 1]
        ok = np.isfinite(res)
        bot.plot(t[ok], res[ok], ".", ms=3)
        bot.axhline(0.0, color="0.6", lw=0.8)
        bot.set_ylabel(f"residual [{unit.group(1)}]" if unit else "residual")
    ax[-1, 0].set_xlabel(header[0])
    ax[0, 0].set_title(a.title or os.path.basename(a.fitted))
    fig.tight_layout()
    out = a.output or os.path.splitext(a.fitted)[0] + ".png"
    fig.savefig(out, dpi=80)
    print(out)


if __name__ == "__main__":
    main()
