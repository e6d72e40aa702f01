#!/usr/bin/env python3
"""Turn a ricochet results file (netCDF-4, docs/output-format.md) into PNG plots.

    python3 scripts/plot.py OUT.nc [PREFIX]

writes PREFIX_trajectory.png (positions of the free bodies vs time),
PREFIX_force.png (normal force vs time and force-penetration loops, events
marked; only when the model has contact interfaces) and PREFIX_energy.png
(every energy_* variable vs time), and prints the names of the files written.
PREFIX defaults to OUT.nc without its extension. Labels and units come from
the file's attributes. A file marked incomplete is plotted with a warning.

Dependencies: Debian's python3-netcdf4, python3-numpy, python3-matplotlib.
"""
import argparse
import os
import sys

# Debian's packages live in /usr/bin/python3; another python3 first on PATH
# (pyenv, a venv) may lack them: run again with Debian's interpreter.
DEBIAN_PYTHON = "/usr/bin/python3"
try:
    import numpy as np
    import netCDF4
    import matplotlib
except ImportError as exc:
    if (os.path.exists(DEBIAN_PYTHON) and not os.environ.get("RC_PLOT_REEXEC")
            and os.path.realpath(sys.executable) != os.path.realpath(DEBIAN_PYTHON)):
        os.environ["RC_PLOT_REEXEC"] = "1"
        os.execv(DEBIAN_PYTHON, [DEBIAN_PYTHON] + sys.argv)
    sys.exit(f"plot.py: {exc}; install python3-netcdf4 python3-numpy python3-matplotlib "
             "(scripts/install-deps.sh)")

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the backend)

MAX_CURVES = 10  # bodies or interfaces drawn per plot


def values(ds, name):
    """Variable as a float array, missing (fill) values as NaN."""
    return np.ma.filled(np.ma.asarray(ds.variables[name][:], dtype=float), np.nan)


def units(ds, name):
    return getattr(ds.variables[name], "units", "?")


def label(ds, name, text=None):
    """'long name [units]' of a variable (or `text` with its units)."""
    var = ds.variables[name]
    return f"{text or getattr(var, 'long_name', name)} [{units(ds, name)}]"


def title(ds, what):
    run = getattr(ds, "title", "") or os.path.basename(ds.filepath())
    if getattr(ds, "complete", "no") != "yes":
        what += f" ({getattr(ds, 'status', 'incomplete')})"
    return f"{run}: {what}"


def event_times(ds):
    return values(ds, "event_time") if "event_time" in ds.variables else np.array([])


def save(fig, path, written):
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    written.append(path)


def plot_trajectory(ds, prefix, written):
    """z (and x, y when they change) of up to MAX_CURVES free bodies vs time."""
    t = values(ds, "time")
    pos = values(ds, "body_position")  # (time, body, 3)
    ids = ds.variables["body_id"][:]
    free = [b for b in range(len(ids)) if not ds.variables["body_fixed"][b]]
    if len(free) > MAX_CURVES:
        print(f"plot.py: {len(free)} free bodies, plotting the first {MAX_CURVES}")
        free = free[:MAX_CURVES]
    # the components that move, z always
    def moves(a):
        return a.size > 0 and not np.all(np.isnan(a)) and np.nanmax(a) > np.nanmin(a)
    moving = [c for c in (0, 1) if moves(pos[:, free, c])]
    comps = moving + [2]
    fig, axes = plt.subplots(len(comps), 1, sharex=True, figsize=(8, 2.6 * len(comps) + 0.8),
                             squeeze=False)
    for ax, c in zip(axes[:, 0], comps):
        for b in free:
            ax.plot(t, pos[:, b, c], label=f"body {ids[b]}")
        ax.set_ylabel(label(ds, "body_position", f"{'xyz'[c]} of centre of mass"))
        ax.grid(True, alpha=0.3)
    if free:
        axes[0, 0].legend(fontsize="small")
    axes[0, 0].set_title(title(ds, "trajectories"))
    axes[-1, 0].set_xlabel(label(ds, "time"))
    save(fig, f"{prefix}_trajectory.png", written)


def plot_force(ds, prefix, written):
    """Normal force vs time and vs penetration for up to MAX_CURVES interfaces."""
    if "inter_force_normal" not in ds.variables:
        print("plot.py: no contact interfaces, no force plot")
        return
    t = values(ds, "time")
    f = values(ds, "inter_force_normal")  # (time, inter)
    p = values(ds, "inter_penetration")
    ids = ds.variables["inter_id"][:]
    at_event = values(ds, "at_event") == 1
    fig, (ax_t, ax_p) = plt.subplots(1, 2, figsize=(12, 4.8))
    for i in range(min(len(ids), MAX_CURVES)):
        name = f"/INTER {ids[i]}"
        line, = ax_t.plot(t, f[:, i], label=name)
        # the loops: only records in the contact zone (P >= 0); separated
        # stretches are masked so that the loops are not joined across flights
        pz = np.where(p[:, i] >= 0, p[:, i], np.nan)
        ax_p.plot(pz, np.where(p[:, i] >= 0, f[:, i], np.nan), color=line.get_color(), label=name)
        sel = at_event & (p[:, i] >= 0)
        ax_p.plot(p[sel, i], f[sel, i], "o", ms=3, color=line.get_color())
    # events: vertical lines in time, dots on the loops (records at events)
    for k, te in enumerate(event_times(ds)):
        ax_t.axvline(te, color="grey", ls=":", lw=0.8, label="events" if k == 0 else None)
    ax_t.set_xlabel(label(ds, "time"))
    ax_t.set_ylabel(label(ds, "inter_force_normal"))
    ax_t.set_title(title(ds, "normal force"))
    ax_p.set_xlabel(label(ds, "inter_penetration"))
    ax_p.set_ylabel(label(ds, "inter_force_normal"))
    ax_p.set_title("force-penetration in contact (dots: records at events)")
    for ax in (ax_t, ax_p):
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="small")
    save(fig, f"{prefix}_force.png", written)


def plot_energy(ds, prefix, written):
    """The energy_* time series that are not identically zero; the total
    (constant in exact arithmetic) drawn thick and black."""
    t = values(ds, "time")
    names = [n for n, v in ds.variables.items()
             if n.startswith("energy_") and v.dimensions == ("time",)
             and np.any(values(ds, n) != 0)]
    fig, ax = plt.subplots(figsize=(10, 4.8))
    colors = plt.cm.tab10(np.linspace(0, 1, 10))
    k = 0
    for n in names:
        short = n[len("energy_"):]
        if n == "energy_total":
            ax.plot(t, values(ds, n), color="black", lw=2, label="total")
        else:
            ax.plot(t, values(ds, n), color=colors[k % 10], label=short)
            k += 1
    ax.set_xlabel(label(ds, "time"))
    ax.set_ylabel(f"energy [{units(ds, names[0])}]" if names else "energy")
    ax.set_title(title(ds, "energy ledger (series that are not all zero)"))
    ax.grid(True, alpha=0.3)
    if names:
        ax.legend(fontsize="small", loc="center left", bbox_to_anchor=(1.01, 0.5))
    fig.tight_layout()
    save(fig, f"{prefix}_energy.png", written)


def main():
    ap = argparse.ArgumentParser(description="Plot a ricochet results file as PNG images.")
    ap.add_argument("file", help="netCDF results file written by ricochet")
    ap.add_argument("prefix", nargs="?", help="output prefix (default: file without .nc)")
    args = ap.parse_args()
    prefix = args.prefix or os.path.splitext(args.file)[0]
    try:
        ds = netCDF4.Dataset(args.file, "r")
    except OSError as exc:
        sys.exit(f"plot.py: cannot read {args.file}: {exc}")
    with ds:
        if getattr(ds, "complete", "no") != "yes":
            print(f"plot.py: warning: {args.file} is incomplete "
                  f"({getattr(ds, 'status', 'no status')}); plotting what it holds",
                  file=sys.stderr)
        if len(ds.dimensions["time"]) == 0:
            print(f"plot.py: warning: {args.file} holds no records", file=sys.stderr)
        written = []
        plot_trajectory(ds, prefix, written)
        plot_force(ds, prefix, written)
        plot_energy(ds, prefix, written)
    for path in written:
        print(path)


if __name__ == "__main__":
    main()
