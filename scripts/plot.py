#!/usr/bin/env python3
"""Turn a ricochet results file (netCDF-4, docs/output-format.md) into PNG plots.

    python3 scripts/plot.py OUT.nc [PREFIX]

writes PREFIX_trajectory.png (positions of the free bodies vs time),
PREFIX_force.png (normal force vs time with the impacts shaded and their
peaks from the impacts table, the events summarised by kind, the first,
largest and last impacts enlarged, force-penetration loops; only when the
model has contact interfaces) and PREFIX_energy.png (the energy_* variables
vs time, the dissipated energies in a panel of their own), and prints the names of the files written.
PREFIX defaults to OUT.nc without its extension. Labels and units come from
the file's attributes. A file marked incomplete is plotted with a warning.

    python3 scripts/plot.py OUT.nc --panels z,force,energy --png OUT.png

writes instead one picture of the chosen quantities, one panel each
against time (the gallery of cases/ uses it). Panels: x, y, z (centre of
mass of the free bodies), vx, vy, vz, speed, angle (rotation angle of the
free bodies from their start), force (normal force per interface),
friction (friction force magnitude per interface), pen (penetration per
interface), loop (normal force against penetration), coupling (coupling
force), gap (coupling length: the smallest face distance of a contact
coupling), stop (moment or force of the joint stops), energy (total,
kinetic, potential, dissipated). --bodies and --inters pick the /RBODY
and /INTER ids drawn, --tmax ends the time axis, --title replaces the
file's title, --width the picture's width in pixels (800).

Dependencies: Debian's python3-netcdf4, python3-numpy, python3-matplotlib.
"""
import argparse
import os
import sys

try:
    import numpy as np
    import netCDF4
    import matplotlib
except ImportError as exc:  # not Debian's interpreter: run again with it
    from debian_python import reexec_or_exit
    reexec_or_exit(exc, "plot.py")

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the backend)

MAX_CURVES = 10  # bodies or interfaces drawn per plot


def values(ds, name):
    """Variable as a float array, missing (fill) values as NaN."""
    return np.ma.filled(np.ma.asarray(ds.variables[name][:], dtype=float), np.nan)


def units(ds, name):
    """The units of a variable; of the time axis without its reference date
    ("seconds since ..." -> "s")."""
    u = getattr(ds.variables[name], "units", "?")
    if " since " in u:
        u = u.split(" since ")[0]
        u = {"seconds": "s"}.get(u, u)
    return u


def label(ds, name, text=None):
    """'long name [units]' of a variable (or `text` with its units)."""
    var = ds.variables[name]
    return f"{text or getattr(var, 'long_name', name)} [{units(ds, name)}]"


def title(ds, what):
    run = getattr(ds, "title", "") or os.path.basename(ds.filepath())
    if getattr(ds, "complete", "no") != "yes":
        what += f" ({getattr(ds, 'status', 'incomplete')})"
    return f"{run}: {what}"


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


DISSIPATION = ("energy_damping", "energy_hysteresis", "energy_friction", "energy_coupling_damping")
ZOOMS = 3  # impacts drawn enlarged


def impacts(ds):
    """Rows of the impacts table as dicts (empty for files without one)."""
    if "impact_close_time" not in ds.variables or len(ds.dimensions.get("impact", [])) == 0:
        return []
    cols = {n[len("impact_"):]: values(ds, n) for n in ds.variables if n.startswith("impact_")}
    return [{k: v[r] for k, v in cols.items()} for r in range(len(cols["close_time"]))]


def event_summary(ds):
    """'kind count, ...' of the events table, most frequent first."""
    if "event_kind" not in ds.variables or len(ds.dimensions["event"]) == 0:
        return "no events"
    kinds, counts = np.unique(np.asarray(ds.variables["event_kind"][:], dtype=str), return_counts=True)
    order = np.argsort(-counts)
    return "events: " + ", ".join(f"{kinds[k]} {counts[k]}" for k in order)


def plot_force(ds, prefix, written):
    """Normal force against time (impacts shaded, their peaks from the
    impacts table marked, events summarised in one line instead of one line
    each), the first, largest and last impacts enlarged, and the
    force-penetration loops."""
    if "inter_force_normal" not in ds.variables:
        print("plot.py: no contact interfaces, no force plot")
        return
    t = values(ds, "time")
    f = values(ds, "inter_force_normal")  # (time, inter)
    p = values(ds, "inter_penetration")
    ids = list(ds.variables["inter_id"][:])
    at_event = values(ds, "at_event") == 1
    rows = impacts(ds)
    fig = plt.figure(figsize=(13, 8))
    gs = fig.add_gridspec(2, 3, height_ratios=[1.15, 1])
    ax_t = fig.add_subplot(gs[0, :2])
    ax_p = fig.add_subplot(gs[0, 2])
    colors = {}
    for i in range(min(len(ids), MAX_CURVES)):
        name = f"/INTER {ids[i]}"
        line, = ax_t.plot(t, f[:, i], lw=1, label=name)
        colors[ids[i]] = line.get_color()
        # loops: only records in the contact zone (P >= 0), flights masked
        inz = p[:, i] >= 0
        ax_p.plot(np.where(inz, p[:, i], np.nan), np.where(inz, f[:, i], np.nan), color=line.get_color(),
                  lw=1, label=name)
        sel = at_event & inz
        ax_p.plot(p[sel, i], f[sel, i], "o", ms=2.5, color=line.get_color())
    for k, r in enumerate(rows):
        end = r["open_time"] if np.isfinite(r["open_time"]) else t[-1]
        ax_t.axvspan(r["close_time"], end, color=colors.get(int(r["inter"]), "grey"), alpha=0.15, lw=0)
        ax_t.plot(r["peak_force_time"], r["peak_force"], "v", ms=5, color="black",
                  label="impact peaks (every step)" if k == 0 else None)
    ax_t.set_xlabel(label(ds, "time"))
    ax_t.set_ylabel(label(ds, "inter_force_normal"))
    ax_t.set_title(title(ds, f"normal force, {len(rows)} impacts (shaded)"))
    summary = event_summary(ds)
    if len(summary) > 150:
        summary = summary[:147] + "..."
    ax_t.text(0.01, 0.98, summary, transform=ax_t.transAxes, va="top", fontsize="x-small",
              bbox=dict(boxstyle="round", fc="white", alpha=0.8))
    ax_p.set_xlabel(label(ds, "inter_penetration"))
    ax_p.set_ylabel(label(ds, "inter_force_normal"))
    ax_p.set_title("force-penetration in contact\n(dots: records at events)", fontsize="medium")
    ax_p.ticklabel_format(axis="x", style="sci", scilimits=(-2, 3))
    for ax in (ax_t, ax_p):
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="small", loc="upper right")
    # enlarged impacts: the first, the largest peak force, the last
    picks = []
    if rows:
        big = int(np.nanargmax([r["peak_force"] for r in rows]))
        for k in (0, big, len(rows) // 2, len(rows) - 1):
            if k not in picks:
                picks.append(k)
    picks = sorted(picks[:ZOOMS])
    for z in range(ZOOMS):
        ax = fig.add_subplot(gs[1, z])
        if z >= len(picks):
            ax.axis("off")
            if z == 0:
                ax.text(0.5, 0.5, "no impacts", ha="center", va="center")
            continue
        r = rows[picks[z]]
        i = ids.index(int(r["inter"])) if int(r["inter"]) in ids else 0
        t0 = r["close_time"]
        dur = r["duration"] if np.isfinite(r["duration"]) else (t[-1] - t0)
        lo, hi = t0 - 0.25 * dur, t0 + 1.25 * dur
        sel = (t >= lo) & (t <= hi)
        scale, unit = (1e3, "ms") if dur < 0.1 else (1.0, "s")
        ax.plot((t[sel] - t0) * scale, f[sel, i], ".-", ms=3, lw=1, color=colors.get(int(r["inter"]), None),
                label=f"records ({sel.sum()})")
        ax.plot((r["peak_force_time"] - t0) * scale, r["peak_force"], "v", color="black",
                label=f"peak {r['peak_force']:.4g}")
        ax.set_xlim((lo - t0) * scale, (hi - t0) * scale)
        ax.set_xlabel(f"time since closing at {t0:.6g} s [{unit}]")
        if z == 0:
            ax.set_ylabel(label(ds, "inter_force_normal"))
        e = r.get("restitution", np.nan)
        ax.set_title(f"impact {picks[z] + 1}: /INTER {int(r['inter'])}, {dur * scale:.3g} {unit}"
                     + (f", e = {e:.3f}" if np.isfinite(e) else ""), fontsize="medium")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="x-small", loc="upper right")
    save(fig, f"{prefix}_force.png", written)


def plot_energy(ds, prefix, written):
    """Top: the energy_* series that are not identically zero except the
    dissipations, the total (constant in exact arithmetic) thick and black.
    Bottom: the dissipated energies (damping, hysteresis, friction, coupling
    dampers) and their sum, on their own scale."""
    t = values(ds, "time")
    names = [n for n, v in ds.variables.items()
             if n.startswith("energy_") and v.dimensions == ("time",)
             and np.any(values(ds, n) != 0)]
    diss = [n for n in names if n in DISSIPATION]
    rest = [n for n in names if n not in DISSIPATION]
    fig, (ax, ax_d) = plt.subplots(2, 1, sharex=True, figsize=(10, 7.5), height_ratios=[1.4, 1])
    colors = plt.cm.tab10(np.linspace(0, 1, 10))
    k = 0
    for n in rest:
        short = n[len("energy_"):]
        if n == "energy_total":
            ax.plot(t, values(ds, n), color="black", lw=2, label="total")
        else:
            ax.plot(t, values(ds, n), color=colors[k % 10], label=short)
            k += 1
    unit = units(ds, names[0]) if names else "J"
    ax.set_ylabel(f"energy [{unit}]")
    ax.set_title(title(ds, "energy ledger (series that are not all zero)"))
    total = np.zeros_like(t)
    for n in diss:
        v = values(ds, n)
        total = total + v
        ax_d.plot(t, v, color=colors[k % 10], label=n[len("energy_"):])
        k += 1
    if len(diss) > 1:
        ax_d.plot(t, total, color="black", lw=1.5, ls="--", label="dissipated, total")
    if not diss:
        ax_d.text(0.5, 0.5, "nothing dissipated", ha="center", va="center", transform=ax_d.transAxes)
    ax_d.set_ylabel(f"dissipated [{unit}]")
    ax_d.set_title("dissipation (cumulative)", fontsize="medium")
    ax_d.set_xlabel(label(ds, "time"))
    for a in (ax, ax_d):
        a.grid(True, alpha=0.3)
        if a.get_legend_handles_labels()[0]:
            a.legend(fontsize="small", loc="center left", bbox_to_anchor=(1.01, 0.5))
    fig.tight_layout()
    save(fig, f"{prefix}_energy.png", written)


PANELS = ("x", "y", "z", "vx", "vy", "vz", "speed", "angle", "force", "friction", "pen", "loop",
          "coupling", "gap", "stop", "energy")


def plot_panels(ds, panels, png, args):
    """One picture: the chosen panels stacked, each against time (loop:
    force against penetration)."""
    t = values(ds, "time")
    keep = np.ones_like(t, dtype=bool) if args.tmax is None else t <= args.tmax
    t = t[keep]
    ids = list(ds.variables["body_id"][:])
    free = [b for b in range(len(ids)) if not ds.variables["body_fixed"][b]]
    if args.bodies:
        want = [int(v) for v in args.bodies.split(",")]
        free = [b for b in free if ids[b] in want]
    inters = list(ds.variables["inter_id"][:]) if "inter_id" in ds.variables else []
    isel = list(range(len(inters)))
    if args.inters:
        want = [int(v) for v in args.inters.split(",")]
        isel = [i for i in isel if inters[i] in want]
    width = args.width / 100.0
    fig, axes = plt.subplots(len(panels), 1, figsize=(width, 0.55 * width * len(panels) / 1.6 + 0.6),
                             squeeze=False)
    tl = label(ds, "time")

    def need(name):
        if name not in ds.variables:
            sys.exit(f"plot.py: panel needs {name}, absent from {args.file}")
        return values(ds, name)[keep]

    for ax, what in zip(axes[:, 0], panels):
        ax.grid(True, alpha=0.3)
        ax.set_xlabel(tl)
        if what in ("x", "y", "z", "vx", "vy", "vz", "speed"):
            var = "body_position" if what in ("x", "y", "z") else "body_velocity"
            a = need(var)
            for b in free:
                if what == "speed":
                    v = np.linalg.norm(a[:, b, :], axis=1)
                else:
                    v = a[:, b, "xyz".index(what[-1])]
                ax.plot(t, v, lw=1.2, label=f"body {ids[b]}")
            if what == "speed":
                ax.set_ylabel(f"speed [{units(ds, var)}]")
            else:
                kind = "position" if var == "body_position" else "velocity"
                ax.set_ylabel(f"{what[-1]} {kind} [{units(ds, var)}]")
        elif what == "angle":
            q = need("body_quaternion")
            for b in free:
                # rotation from the start: q(t) q(0)^-1, angle 2 atan2(|v|, |w|)
                q0 = q[0, b, :] * np.array([1, -1, -1, -1])
                w = q[:, b, 0] * q0[0] - np.sum(q[:, b, 1:] * q0[1:], axis=1)
                v = (q[:, b, 0:1] * q0[1:] + q0[0] * q[:, b, 1:] + np.cross(q[:, b, 1:], q0[1:]))
                ang = 2 * np.degrees(np.arctan2(np.linalg.norm(v, axis=1), np.abs(w)))
                ax.plot(t, ang, lw=1.2, label=f"body {ids[b]}")
            ax.set_ylabel("rotation from start [deg]")
        elif what in ("force", "pen", "friction"):
            var = {"force": "inter_force_normal", "pen": "inter_penetration",
                   "friction": "inter_force_friction"}[what]
            a = need(var)
            for i in isel:
                v = np.linalg.norm(a[:, i, :], axis=1) if what == "friction" else a[:, i]
                if what == "pen":
                    v = np.where(v >= 0, v * 1e3, np.nan)
                ax.plot(t, v, lw=1.2, label=f"/INTER {inters[i]}")
            ax.set_ylabel({"force": "normal force [N]", "pen": "penetration [mm]",
                           "friction": "friction force [N]"}[what])
        elif what == "loop":
            f, p = need("inter_force_normal"), need("inter_penetration")
            for i in isel:
                inz = p[:, i] >= 0
                ax.plot(np.where(inz, p[:, i] * 1e3, np.nan), np.where(inz, f[:, i], np.nan), lw=1.2,
                        label=f"/INTER {inters[i]}")
            ax.set_xlabel("penetration [mm]")
            ax.set_ylabel("normal force [N]")
        elif what in ("coupling", "gap"):
            var = "coupling_force" if what == "coupling" else "coupling_length"
            a = need(var)
            cids = ds.variables["coupling_id"][:]
            for c in range(a.shape[1]):
                v = a[:, c] * (1e3 if what == "gap" else 1)
                ax.plot(t, v, lw=1.2, label=f"/COUPLING {cids[c]}")
            ax.set_ylabel("coupling force [N]" if what == "coupling" else "coupling length [mm]")
        elif what == "stop":
            jt = [str(v) for v in ds.variables["joint_type"][:]]
            m, f = need("joint_stop_moment"), need("joint_stop_force")
            for j in range(m.shape[1]):
                if jt[j] == "REVOLUTE":
                    ax.plot(t, m[:, j], lw=1.2, label=f"joint {j + 1} stop moment [N m]")
                else:
                    ax.plot(t, f[:, j], lw=1.2, label=f"joint {j + 1} stop force [N]")
            ax.set_ylabel("stop moment [N m] / force [N]")
        elif what == "energy":
            ax.plot(t, need("energy_total"), color="black", lw=2, label="total")
            for n in ("energy_kinetic", "energy_potential", "energy_catenary", "energy_coupling_elastic"):
                if n in ds.variables and np.any(values(ds, n) != 0):
                    ax.plot(t, need(n), lw=1.2, label=n[len("energy_"):])
            diss = sum(need(n) for n in DISSIPATION if n in ds.variables)
            if np.any(diss != 0):
                ax.plot(t, diss, lw=1.2, ls="--", label="dissipated")
            ax.set_ylabel(f"energy [{units(ds, 'energy_total')}]")
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize="small", loc="best")
    run = args.title or getattr(ds, "title", "") or os.path.basename(args.file)
    axes[0, 0].set_title(run, fontsize="medium")
    fig.tight_layout()
    fig.savefig(png, dpi=100)
    plt.close(fig)
    try:  # a palette of 64 colours: the same picture in a third of the bytes
        from PIL import Image
        with Image.open(png) as im:
            small = im.convert("RGB").quantize(colors=64)
        small.save(png, optimize=True)
    except ImportError:
        pass
    print(png)


def main():
    ap = argparse.ArgumentParser(description="Plot a ricochet results file as PNG images.")
    ap.add_argument("file", help="netCDF results file written by ricochet")
    ap.add_argument("prefix", nargs="?", help="output prefix (default: file without .nc)")
    ap.add_argument("--panels", help="one picture of these panels, comma-separated: " + ", ".join(PANELS))
    ap.add_argument("--png", help="the picture written with --panels (default: file with .png)")
    ap.add_argument("--bodies", help="/RBODY ids drawn (default: every free body, up to %d)" % MAX_CURVES)
    ap.add_argument("--inters", help="/INTER ids drawn (default: all)")
    ap.add_argument("--tmax", type=float, help="end of the time axis [s]")
    ap.add_argument("--title", help="title of the picture (default: the run's title)")
    ap.add_argument("--width", type=int, default=800, help="width of the picture [px] (800)")
    args = ap.parse_args()
    if args.panels:
        panels = [p.strip() for p in args.panels.split(",") if p.strip()]
        bad = [p for p in panels if p not in PANELS]
        if bad or not panels:
            sys.exit(f"plot.py: unknown panel(s) {', '.join(bad) or '(none)'}; choose from {', '.join(PANELS)}")
        try:
            ds = netCDF4.Dataset(args.file, "r")
        except OSError as exc:
            sys.exit(f"plot.py: cannot read {args.file}: {exc}")
        with ds:
            plot_panels(ds, panels, args.png or os.path.splitext(args.file)[0] + ".png", args)
        return
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
