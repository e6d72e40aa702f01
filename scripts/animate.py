#!/usr/bin/env python3
"""Animate a ricochet results file (netCDF-4, docs/output-format.md): the
bodies moving, in a 2-D projection, as a GIF or an MP4.

    python3 scripts/animate.py OUT.nc [-o FILE.gif|FILE.mp4] [--fps N]
                               [--view xz|xy|yz] [--every N | --dt T]
                               [--width PX] [--max-frames N]

Each body is drawn with its shape as far as the file describes it (the
surface variables): spheres as circles (with a radius line that turns with
the body), boxes as their projected outline (a rotated rectangle when an
axis of the box is along the view), cylinders as the outline of their
side and ends, segment surfaces (/SURF/SEG, /SURF/PART) as their projected
segments, planes as the section of the plane through the middle of the
bodies (a line, the solid side shaded); a body without a surface as a
dot. Moving bodies are coloured by body, fixed bodies and surfaces fixed
in space grey. Axes in the file's length unit (m for a deck that names its
units), equal aspect, the view box fitted to the whole motion; each frame
is labelled with its time in s and its record number.

Frames (as `ricochet export-vtk`):
  default       the records at the output times (/RUN Dt_out, at_event = 0);
                when there are more than --max-frames (300) of them, one
                per dt, dt the smallest 1, 2 or 5 x 10^k s that gives at most
                that many (the first output time at or after each multiple
                of dt); the last record always
  --dt T        one frame per T [s]: the first record (any kind) at or after
                each multiple of T, and the last
  --every N     records 0, N, 2N, ... of the file, event records included

Output: -o FILE.mp4 needs ffmpeg on PATH; -o FILE.gif needs Pillow (Debian's
python3-pil, which matplotlib depends on). Without -o: OUT.mp4 when ffmpeg
exists, OUT.gif otherwise (next to OUT.nc). Without Pillow and ffmpeg the
frames are written as PNG files into FILE_frames/ instead (said on
stdout). Prints the file written, its frames and its size.

Exit codes: 0; 2 for a wrong option or a missing file or one that is not a
ricochet results file; 4 when the animation cannot be written.
Dependencies: Debian's python3-netcdf4, python3-numpy, python3-matplotlib.
"""
import argparse
import math
import os
import shutil
import subprocess
import textwrap
import sys
import time as wallclock

try:
    import numpy as np
    import netCDF4
    import matplotlib
except ImportError as exc:  # not Debian's interpreter: run again with it
    from debian_python import reexec_or_exit
    reexec_or_exit(exc, "animate.py")

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the backend)
from matplotlib.collections import EllipseCollection, LineCollection, PolyCollection  # noqa: E402

try:
    from PIL import Image
except ImportError:  # pragma: no cover
    Image = None

MAX_FRAMES = 300
VIEWS = {"xz": (0, 2, 1), "xy": (0, 1, 2), "yz": (1, 2, 0)}  # (horizontal, vertical, depth)
GREY = (0.62, 0.62, 0.62)


def fail(msg, code=2):
    print(f"animate.py: {msg}", file=sys.stderr)
    sys.exit(code)


def values(ds, name):
    return np.ma.filled(np.ma.asarray(ds.variables[name][:], dtype=float), np.nan)


def strings(ds, name):
    return [str(s) for s in ds.variables[name][:]]


def rotations(q):
    """Rotation matrices (..., 3, 3), body to global, of unit quaternions (..., 4) (w, x, y, z)."""
    q = q / np.linalg.norm(q, axis=-1, keepdims=True)
    w, x, y, z = (q[..., k] for k in range(4))
    r = np.empty(q.shape[:-1] + (3, 3))
    r[..., 0, 0] = 1 - 2 * (y * y + z * z)
    r[..., 0, 1] = 2 * (x * y - w * z)
    r[..., 0, 2] = 2 * (x * z + w * y)
    r[..., 1, 0] = 2 * (x * y + w * z)
    r[..., 1, 1] = 1 - 2 * (x * x + z * z)
    r[..., 1, 2] = 2 * (y * z - w * x)
    r[..., 2, 0] = 2 * (x * z - w * y)
    r[..., 2, 1] = 2 * (y * z + w * x)
    r[..., 2, 2] = 1 - 2 * (x * x + y * y)
    return r


def hull(p):
    """Convex hull (counter-clockwise) of 2-D points (n, 2): Andrew's monotone chain."""
    pts = sorted(set(map(tuple, np.round(p, 12))))
    if len(pts) <= 2:
        return np.array(pts)

    def half(seq):
        out = []
        for q in seq:
            while len(out) >= 2 and ((out[-1][0] - out[-2][0]) * (q[1] - out[-2][1])
                                     - (out[-1][1] - out[-2][1]) * (q[0] - out[-2][0])) <= 0:
                out.pop()
            out.append(q)
        return out[:-1]
    return np.array(half(pts) + half(reversed(pts)))


def select_frames(t, at_event, dt_out, args):
    """Record indices of the frames and a sentence saying how they were chosen."""
    n = len(t)
    last = n - 1
    if args.every:
        idx = list(range(0, n, args.every))
        return idx, f"every {args.every} records"
    if args.dt:
        pool, how = np.arange(n), f"one per {args.dt:g} s"
        dt = args.dt
    else:
        pool = np.flatnonzero(at_event == 0)
        if len(pool) == 0:
            pool = np.arange(n)
        if len(pool) > 1:  # the interval of the records themselves (a --dt-out override included)
            dt_out = float(np.median(np.diff(t[pool])))
        if len(pool) <= args.max_frames:
            idx = sorted(set(pool.tolist()) | {last})
            what = f"Dt_out {dt_out:g} s" if dt_out else "the output times"
            return idx, f"every output time ({what})"
        span = t[pool[-1]] - t[pool[0]]
        dt = None
        for k in range(-9, 10):
            for m in (1, 2, 5):
                c = m * 10.0 ** k
                if c >= (dt_out or 0) and span / c + 1 <= args.max_frames:
                    dt = c
                    break
            if dt:
                break
        dt = dt or span
        how = (f"one per {dt:g} s (output interval {dt_out:g} s, {len(pool)} output times, "
               f"at most {args.max_frames} frames)")
    tp = t[pool]
    t0 = tp[0]
    kmax = int(math.floor((tp[-1] - t0) / dt * (1 + 1e-12) + 1e-9))
    marks = t0 + dt * np.arange(kmax + 1)
    at = np.searchsorted(tp, marks - 1e-9 * dt, side="left")
    at = at[at < len(pool)]
    idx = sorted(set(pool[at].tolist()) | {last})
    return idx, how


class Scene:
    """The shapes of a results file, placed record by record in 2-D."""

    def __init__(self, ds, view):
        self.h, self.v, self.d = VIEWS[view]
        self.pos = values(ds, "body_position")          # (time, body, 3)
        self.quat = values(ds, "body_quaternion")       # (time, body, 4)
        self.ids = [int(i) for i in ds.variables["body_id"][:]]
        nb = len(self.ids)
        fixed = ds.variables["body_fixed"][:] if "body_fixed" in ds.variables else np.zeros(nb)
        self.fixed = [bool(f) for f in fixed]
        cmap = plt.get_cmap("tab10")
        colours, k = [], 0
        for b in range(nb):
            if self.fixed[b]:
                colours.append(GREY)
            else:
                colours.append(cmap(k % 10)[:3])
                k += 1
        self.colour = colours
        self.index = {i: b for b, i in enumerate(self.ids)}
        self.spheres, self.boxes, self.cyls, self.segs, self.planes = [], [], [], [], []
        shaped = set()
        v = ds.variables
        if "surface_kind" in v:
            kinds = strings(ds, "surface_kind")
            sbody = [int(x) for x in v["surface_body"][:]]
            point = values(ds, "surface_point")
            normal = values(ds, "surface_normal")
            radius = values(ds, "surface_radius")
            par = values(ds, "surface_parameters")
            nodes = values(ds, "segment_node_position") if "segment_node_position" in v else None
            corners = np.asarray(v["segment_corners"][:], dtype=int) if "segment_corners" in v else None
            fnode = np.asarray(v["surface_first_node"][:], dtype=int) if "surface_first_node" in v else None
            fseg = np.asarray(v["surface_first_segment"][:], dtype=int) if "surface_first_segment" in v else None
            for s, kind in enumerate(kinds):
                b = self.index.get(sbody[s], -1)  # -1: fixed in space
                if b >= 0:
                    shaped.add(b)  # a body carrying only a plane is drawn as its plane
                if kind == "SPHERE":
                    self.spheres.append((b, point[s], radius[s]))
                elif kind == "BOX":
                    h = par[s, 0:3]
                    axes = par[s, 3:12].reshape(3, 3)  # rows u, v, w
                    signs = np.array([[i, j, k] for i in (-1, 1) for j in (-1, 1) for k in (-1, 1)], float)
                    self.boxes.append((b, point[s] + (signs * h) @ axes))
                elif kind == "CYLINDER":
                    self.cyls.append((b, point[s], normal[s], radius[s], par[s, 0], par[s, 1] > 0.5))
                elif kind == "PLANE":
                    self.planes.append((b, point[s], normal[s]))
                elif kind == "SEGMENTS" and nodes is not None and corners is not None:
                    n0 = fnode[s]
                    n1 = fnode[s + 1] if s + 1 < len(kinds) else len(nodes)
                    g0 = fseg[s]
                    g1 = fseg[s + 1] if s + 1 < len(kinds) else len(corners)
                    if n1 > n0 and g1 > g0:
                        self.segs.append((b, nodes[n0:n1], corners[g0:g1]))
                    elif b >= 0:
                        shaped.discard(b)
        self.dots = [b for b in range(nb) if b not in shaped]
        # the depth of the plane sections: the middle of the bodies
        p = self.pos[:, :, self.d]
        self.depth = float(np.nanmean(p)) if p.size and not np.all(np.isnan(p)) else 0.0

    def place(self, r, b, local):
        """Global points of body-frame points (n, 3) of body b at record r (b -1: fixed in space)."""
        if b < 0:
            return local
        return self.pos[r, b] + local @ rotations(self.quat[r, b]).T

    def turn(self, r, b, vec):
        return vec if b < 0 else rotations(self.quat[r, b]) @ vec

    def proj(self, p):
        return p[..., [self.h, self.v]]

    def frame(self, r):
        """The shapes at record r: circles (centres, radii), radius lines,
        polygons, dots, each as arrays (colours in self.*_colours)."""
        centres = np.array([self.proj(self.place(r, b, c[None, :])[0]) for b, c, _ in self.spheres]).reshape(-1, 2)
        radii = np.array([rad for _, _, rad in self.spheres])
        lines = []
        for (b, c, rad), cc in zip(self.spheres, centres):
            e = self.turn(r, b, np.array([1.0, 0.0, 0.0]))
            lines.append([cc, cc + rad * self.proj(e)])
        polys = []
        for b, pts in self.boxes:
            polys.append(hull(self.proj(self.place(r, b, pts))))
        th = np.linspace(0, 2 * np.pi, 64, endpoint=False)
        for b, c, ax, rad, half, rounded in self.cyls:
            cg = self.place(r, b, c[None, :])[0]
            a = self.turn(r, b, ax)
            a = a / (np.linalg.norm(a) or 1.0)
            ends = np.array([cg - half * a, cg + half * a])
            if rounded:
                ring = rad * np.stack([np.cos(th), np.sin(th)], axis=1)
                pts = np.concatenate([self.proj(e) + ring for e in ends])
            else:
                u = np.cross(a, [1.0, 0, 0] if abs(a[0]) < 0.9 else [0, 1.0, 0])
                u /= np.linalg.norm(u)
                w = np.cross(a, u)
                ring = rad * (np.cos(th)[:, None] * u + np.sin(th)[:, None] * w)
                pts = self.proj(np.concatenate([e + ring for e in ends]))
            polys.append(hull(pts))
        for b, nodes, corners in self.segs:
            g = self.proj(self.place(r, b, nodes))
            polys.extend(g[q] for q in corners)
        dots = self.proj(self.pos[r, self.dots]).reshape(-1, 2)
        return centres, radii, lines, polys, dots

    def colours(self):
        """Colours of the circles, polygons and dots, in the order of frame()."""
        col = lambda b: GREY if b < 0 else self.colour[b]  # noqa: E731
        circ = [col(b) for b, _, _ in self.spheres]
        poly = [col(b) for b, _ in self.boxes] + [col(c[0]) for c in self.cyls]
        for b, _, corners in self.segs:
            poly.extend([col(b)] * len(corners))
        dots = [self.colour[b] for b in self.dots]
        return circ, poly, dots

    def plane_lines(self, r):
        """Per plane: (a point of its section, unit direction, unit in-view normal) or None
        when the plane is (nearly) parallel to the view."""
        out = []
        for b, p, n in self.planes:
            pg = self.place(r, b, p[None, :])[0]
            ng = self.turn(r, b, n)
            n2 = self.proj(ng)
            ln = np.linalg.norm(n2)
            if ln < 1e-6:
                out.append(None)
                continue
            # the section at depth: n2 . q = n2 . p2 - n_d (depth - p_d)
            c = n2 @ self.proj(pg) - ng[self.d] * (self.depth - pg[self.d])
            q0 = n2 * c / ln ** 2
            out.append((q0, np.array([-n2[1], n2[0]]) / ln, n2 / ln))
        return out


def palette_of(frames):
    """A 256-colour palette image from a few RGB frames (one palette for all:
    no flicker)."""
    mosaic = Image.fromarray(np.concatenate(frames, axis=0))
    return mosaic.quantize(colors=255, method=Image.Quantize.MEDIANCUT)


def main():
    ap = argparse.ArgumentParser(
        prog="animate.py", description=__doc__.split("\n\n")[0].replace("\n", " "),
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="\n\n".join(__doc__.split("\n\n")[2:]))
    ap.add_argument("results", metavar="RESULTS.nc", help="a results file of ricochet run")
    ap.add_argument("-o", "--output", metavar="FILE",
                    help="FILE.gif or FILE.mp4 (default: RESULTS.mp4 with ffmpeg, else RESULTS.gif)")
    ap.add_argument("--fps", type=float, default=25.0, help="frames per second of the animation (25)")
    ap.add_argument("--view", choices=sorted(VIEWS), default="xz",
                    help="the projection: horizontal and vertical axes (xz)")
    grp = ap.add_mutually_exclusive_group()
    grp.add_argument("--every", type=int, metavar="N", help="records 0, N, 2N, ... (event records included)")
    grp.add_argument("--dt", type=float, metavar="T", help="one frame per T seconds of simulated time")
    ap.add_argument("--width", type=int, default=640, metavar="PX", help="width in pixels (640)")
    ap.add_argument("--max-frames", type=int, default=MAX_FRAMES, metavar="N",
                    help=f"most frames of the default choice ({MAX_FRAMES})")
    a = ap.parse_args()
    if a.every is not None and a.every < 1:
        ap.error("--every N: expected an integer >= 1")
    if a.dt is not None and not (a.dt > 0 and math.isfinite(a.dt)):
        ap.error("--dt T: expected a positive number of seconds")
    if not (a.fps > 0 and math.isfinite(a.fps)):
        ap.error("--fps N: expected a positive number")
    if not 64 <= a.width <= 4096:
        ap.error("--width PX: expected 64 to 4096 pixels")
    if a.max_frames < 2:
        ap.error("--max-frames N: expected at least 2")
    if not os.path.exists(a.results):
        fail(f"{a.results}: no such file")
    ffmpeg = shutil.which("ffmpeg")
    out = a.output or os.path.splitext(a.results)[0] + (".mp4" if ffmpeg else ".gif")
    ext = os.path.splitext(out)[1].lower()
    if ext not in (".gif", ".mp4"):
        fail(f"-o {out}: expected a .gif or .mp4 file name")
    if ext == ".mp4" and not ffmpeg:
        fail(f"-o {out}: writing MP4 needs ffmpeg, which is not on PATH; write a .gif instead")
    png_dir = None
    if ext == ".gif" and Image is None:
        if ffmpeg and not a.output:
            out, ext = os.path.splitext(out)[0] + ".mp4", ".mp4"
        else:
            png_dir = os.path.splitext(out)[0] + "_frames"
    if os.path.realpath(out) == os.path.realpath(a.results):
        fail(f"-o {out}: the output would replace the results file")

    start = wallclock.monotonic()
    try:
        ds = netCDF4.Dataset(a.results)
    except OSError as exc:
        fail(f"{a.results}: not a readable netCDF file ({exc})")
    with ds:
        need = ("time", "body_position", "body_quaternion", "body_id")
        missing = [n for n in need if n not in ds.variables]
        if missing:
            fail(f"{a.results}: not a ricochet results file (no {', '.join(missing)})")
        t = values(ds, "time")
        if len(t) == 0:
            fail(f"{a.results}: no records", 2)
        at_event = (np.asarray(ds.variables["at_event"][:], dtype=int) if "at_event" in ds.variables
                    else np.zeros(len(t), dtype=int))
        dt_out = float(getattr(ds, "dt_out", 0.0) or 0.0)
        run_title = getattr(ds, "title", "") or os.path.basename(a.results)
        complete = getattr(ds, "complete", "yes") == "yes"
        unit = getattr(ds.variables["body_position"], "units", "m")
        scene = Scene(ds, a.view)
    if not complete:
        print(f"animate.py: {a.results} is marked incomplete; animating the records it has")
    idx, how = select_frames(t, at_event, dt_out, a)

    # geometry of every frame first: the view box is fitted to all of it
    geo = [scene.frame(r) for r in idx]
    lo, hi = np.full(2, np.inf), np.full(2, -np.inf)
    for centres, radii, lines, polys, dots in geo:
        for arr in [centres - radii[:, None], centres + radii[:, None], dots] + polys:
            if len(arr):
                lo = np.fmin(lo, np.nanmin(arr, axis=0))
                hi = np.fmax(hi, np.nanmax(arr, axis=0))
    if not np.all(np.isfinite(lo)):
        lo, hi = np.zeros(2), np.ones(2)
    span = hi - lo
    size = max(float(span.max()), 1e-9)
    pad = 0.08 * size
    span = np.maximum(span, 0.25 * size)  # a flat motion still gets some height
    mid = (lo + hi) / 2
    lo, hi = mid - span / 2 - pad, mid + span / 2 + pad

    # figure: width as asked, height from the box's aspect (within 0.4..1.25 of the width)
    width = a.width - a.width % 2
    aspect = (hi[1] - lo[1]) / (hi[0] - lo[0])
    height = int(round(width * min(max(aspect * 0.9 + 0.1, 0.4), 1.25)))
    height -= height % 2
    dpi = 100
    fig = plt.figure(figsize=(width / dpi, height / dpi), dpi=dpi)
    ax = fig.add_subplot(1, 1, 1)
    names = "xyz"
    ax.set_xlabel(f"{names[scene.h]} [{unit}]")
    ax.set_ylabel(f"{names[scene.v]} [{unit}]")
    heading = textwrap.fill(f"{run_title} ({a.view} view)", max(20, width // 8))
    ax.set_title(heading, fontsize="medium", pad=22)
    ax.grid(True, alpha=0.25)
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    fig.tight_layout()
    # equal scales: widen the range of the axis with room to spare (never shrink one)
    box = ax.get_position()
    wpx, hpx = box.width * width, box.height * height
    per_px = max((hi[0] - lo[0]) / wpx, (hi[1] - lo[1]) / hpx)
    mid = (lo + hi) / 2
    half = np.array([wpx, hpx]) * per_px / 2
    lo, hi = mid - half, mid + half
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])

    circ_c, poly_c, dot_c = scene.colours()
    big = 100 * size
    plane_moves = any(b >= 0 and not scene.fixed[b] for b, _, _ in scene.planes)
    planes = PolyCollection([], facecolors=[(0.85, 0.85, 0.85)], edgecolors=[(0.35, 0.35, 0.35)],
                            linewidths=1.2, zorder=1, animated=plane_moves)
    ax.add_collection(planes)
    polys = PolyCollection([], facecolors=[c + (0.45,) for c in poly_c], edgecolors=poly_c,
                           linewidths=1.0, zorder=2, animated=True)
    ax.add_collection(polys)
    circles = EllipseCollection(widths=[], heights=[], angles=[], units="xy", offsets=np.zeros((0, 2)),
                                offset_transform=ax.transData, facecolors=[c + (0.45,) for c in circ_c],
                                edgecolors=circ_c, linewidths=1.2, zorder=3, animated=True)
    if scene.spheres:
        r2 = 2 * np.array([rad for _, _, rad in scene.spheres])
        circles = EllipseCollection(widths=r2, heights=r2, angles=np.zeros(len(r2)), units="xy",
                                    offsets=geo[0][0], offset_transform=ax.transData,
                                    facecolors=[c + (0.45,) for c in circ_c], edgecolors=circ_c,
                                    linewidths=1.2, zorder=3, animated=True)
        ax.add_collection(circles)
    radials = LineCollection([], colors=circ_c, linewidths=1.0, zorder=4, animated=True)
    ax.add_collection(radials)
    dots = ax.scatter(np.zeros(len(dot_c)), np.zeros(len(dot_c)), s=30, c=dot_c if dot_c else None,
                      zorder=5, animated=True)
    label = ax.text(0.0, 1.015, "", transform=ax.transAxes, va="bottom", ha="left", zorder=6,
                    fontsize="medium", family="monospace", animated=True, clip_on=False)
    ndig = 3
    if len(idx) > 1:
        step = np.min(np.diff(t[idx])) if np.any(np.diff(t[idx]) > 0) else 1.0
        ndig = min(max(3, int(math.ceil(-math.log10(max(step, 1e-12)))) + 1), 9)

    def set_planes(r):
        verts = []
        for pl in scene.plane_lines(r):
            if pl is None:
                continue
            q0, tan, nrm = pl
            verts.append([q0 - big * tan, q0 + big * tan, q0 + big * tan - big * nrm, q0 - big * tan - big * nrm])
        planes.set_verts(verts)

    set_planes(idx[0])
    skipped = sum(1 for pl in scene.plane_lines(idx[0]) if pl is None)
    if skipped:
        print(f"animate.py: {skipped} plane(s) parallel to the {a.view} view not drawn")
    fig.canvas.draw()  # the static part: axes, ticks, fixed planes
    background = fig.canvas.copy_from_bbox(fig.bbox)
    animated = ([planes] if plane_moves else []) + [polys] + ([circles] if scene.spheres else []) + [
        radials, dots, label]

    def render(k):
        r = idx[k]
        centres, radii, lines, pl, dt_ = geo[k]
        fig.canvas.restore_region(background)
        if plane_moves:
            set_planes(r)
        polys.set_verts(pl)
        if scene.spheres:
            circles.set_offsets(centres)
        radials.set_segments(lines)
        dots.set_offsets(dt_ if len(dt_) else np.zeros((0, 2)))
        label.set_text(f"t = {t[r]:.{ndig}f} s   record {r}")
        for art in animated:
            ax.draw_artist(art)
        buf = np.asarray(fig.canvas.buffer_rgba())
        return buf[:, :, :3].copy()

    nframes = len(idx)
    try:
        if png_dir:
            os.makedirs(png_dir, exist_ok=True)
            for k in range(nframes):
                plt.imsave(os.path.join(png_dir, f"frame_{k:05d}.png"), render(k))
            written, nbytes = png_dir, sum(os.path.getsize(os.path.join(png_dir, f))
                                           for f in os.listdir(png_dir))
            print("animate.py: neither Pillow (python3-pil) nor ffmpeg found: PNG frames written")
        elif ext == ".mp4":
            h_, w_ = render(0).shape[:2]
            cmd = [ffmpeg, "-y", "-loglevel", "error", "-f", "rawvideo", "-pix_fmt", "rgb24",
                   "-s", f"{w_}x{h_}", "-r", f"{a.fps:g}", "-i", "-", "-c:v", "libx264",
                   "-pix_fmt", "yuv420p", "-crf", "20", "-movflags", "+faststart", out]
            proc = subprocess.Popen(cmd, stdin=subprocess.PIPE)
            try:
                for k in range(nframes):
                    proc.stdin.write(render(k).tobytes())
                proc.stdin.close()
            except BrokenPipeError:
                pass
            if proc.wait() != 0:
                fail(f"{out}: ffmpeg failed (exit {proc.returncode})", 4)
            written, nbytes = out, os.path.getsize(out)
        else:
            pal = palette_of([render(k) for k in sorted({0, nframes // 2, nframes - 1})])
            dither = Image.Dither.NONE

            def frames():
                for k in range(1, nframes):
                    yield Image.fromarray(render(k)).quantize(palette=pal, dither=dither)
            first = Image.fromarray(render(0)).quantize(palette=pal, dither=dither)
            first.save(out, save_all=True, append_images=frames(), duration=int(round(1000 / a.fps)),
                       loop=0, optimize=False)
            written, nbytes = out, os.path.getsize(out)
    except OSError as exc:
        fail(f"{out}: cannot write the animation ({exc})", 4)
    plt.close(fig)
    span_t = t[idx[-1]] - t[idx[0]]
    print(f"{written}: {nframes} frames ({how}), {nframes / a.fps:.3g} s at {a.fps:g} fps for "
          f"{span_t:.6g} s simulated, {a.view} view, {nbytes / 1e6:.3g} MB, "
          f"in {wallclock.monotonic() - start:.2g} s")


if __name__ == "__main__":
    main()
