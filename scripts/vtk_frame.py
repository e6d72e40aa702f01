#!/usr/bin/env python3
"""Render one frame of a `ricochet export-vtk` time series to a PNG, off screen.

    python3 scripts/vtk_frame.py DIR/STEM.pvd OUT.png [--time T | --record K]
                                 [--size WxH] [--force-scale S]

Draws the bodies (coloured by body id, surfaces fixed in space grey), the
contact points and the normal contact forces on the first body of each
contact as arrows (length S x force [m/N]; default: the largest force of
the frame draws as long as the largest body), and prints
the frame drawn. --record K: the K-th frame of the series, from 0 (the
results file's record K when the series holds every record, export-vtk
--every 1); --time T: the frame nearest T [s]; neither: the frame of the
largest normal force. Needs Debian's python3-vtk9; on a machine without a display
run it under xvfb-run (package xvfb).
"""
import argparse
import os
import re
import sys
import xml.etree.ElementTree as ET

try:
    import vtk
except ImportError as exc:  # pragma: no cover
    sys.exit(f"vtk_frame.py: {exc}; install python3-vtk9 (scripts/install-deps.sh test)")


def datasets(pvd):
    """[(time, part, path)] of a .pvd collection."""
    root = ET.parse(pvd).getroot()
    base = os.path.dirname(pvd)
    return [(float(d.get("timestep")), int(d.get("part")), os.path.join(base, d.get("file")))
            for d in root.iter("DataSet")]


def read(path):
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(path)
    r.Update()
    return r.GetOutput()


def records(pvd):
    """{record index: (time, bodies path, contacts path)} in order."""
    ds = datasets(pvd)
    out = []
    for k in range(0, len(ds), 2):
        out.append((ds[k][0], ds[k][2], ds[k + 1][2]))
    return out


def peak_record(recs):
    best, fbest = 0, -1.0
    for k, (_, _, cpath) in enumerate(recs):
        arr = read(cpath).GetPointData().GetArray("force_normal")
        if arr is None:
            continue
        f = max((arr.GetValue(i) for i in range(arr.GetNumberOfTuples())), default=0.0)
        if f > fbest:
            best, fbest = k, f
    return best


def render(bodies, contacts, png, size=(800, 600), force_scale=None, title=""):
    ren = vtk.vtkRenderer()
    ren.SetBackground(1.0, 1.0, 1.0)
    # bodies: planes (body_id -1) grey and translucent, bodies by id
    bounds = bodies.GetBounds()
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputData(bodies)
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("body_id")
    ids = bodies.GetPointData().GetArray("body_id")
    lo, hi = ids.GetRange() if ids else (0, 1)
    lut = vtk.vtkLookupTable()
    lut.SetTableRange(lo, max(hi, lo + 1))
    lut.SetHueRange(0.6, 0.0)
    lut.Build()
    if lo < 0:  # surfaces fixed in space
        lut.SetTableValue(0, 0.75, 0.75, 0.75, 1.0)
    mapper.SetLookupTable(lut)
    mapper.SetScalarRange(lo, max(hi, lo + 1))
    mapper.ScalarVisibilityOn()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetEdgeVisibility(0)
    actor.GetProperty().SetOpacity(0.45)  # the force arrows run inside the bodies
    ren.AddActor(actor)
    # sizes: the largest body (its own points) and the scene (all bodies)
    size_body, size_scene = 0.0, 0.0
    pts = bodies.GetPoints()
    if pts is not None and ids is not None and pts.GetNumberOfPoints():
        from vtk.util.numpy_support import vtk_to_numpy
        xyz = vtk_to_numpy(pts.GetData())
        bid = vtk_to_numpy(ids)
        movers = xyz[bid >= 0]
        if len(movers):
            size_scene = float((movers.max(axis=0) - movers.min(axis=0)).max())
            lo3, hi3 = movers.min(axis=0), movers.max(axis=0)
            bounds = (lo3[0], hi3[0], lo3[1], hi3[1], lo3[2], hi3[2])
            for b in set(bid[bid >= 0].tolist()):
                one = xyz[bid == b]
                size_body = max(size_body, float((one.max(axis=0) - one.min(axis=0)).max()))
    # contact forces: arrows at the contact points, on the closed contacts
    fn = contacts.GetPointData().GetArray("force_normal")
    fmax = max((fn.GetValue(i) for i in range(fn.GetNumberOfTuples())), default=0.0) if fn else 0.0
    if fmax > 0:
        scale = force_scale if force_scale else (size_body or 1.0) / fmax
        contacts.GetPointData().SetActiveVectors("force_normal_vector")
        arrow = vtk.vtkArrowSource()
        glyph = vtk.vtkGlyph3D()
        glyph.SetInputData(contacts)
        glyph.SetSourceConnection(arrow.GetOutputPort())
        glyph.SetVectorModeToUseVector()
        glyph.SetScaleModeToScaleByVector()
        glyph.SetScaleFactor(scale)
        glyph.OrientOn()
        gm = vtk.vtkPolyDataMapper()
        gm.SetInputConnection(glyph.GetOutputPort())
        gm.ScalarVisibilityOff()
        ga = vtk.vtkActor()
        ga.SetMapper(gm)
        ga.GetProperty().SetColor(0.1, 0.2, 0.9)
        ren.AddActor(ga)
    dots = vtk.vtkVertexGlyphFilter()
    dots.SetInputData(contacts)
    dm = vtk.vtkPolyDataMapper()
    dm.SetInputConnection(dots.GetOutputPort())
    dm.ScalarVisibilityOff()
    da = vtk.vtkActor()
    da.SetMapper(dm)
    da.GetProperty().SetPointSize(8)
    da.GetProperty().SetColor(0.1, 0.1, 0.1)
    ren.AddActor(da)
    if title:
        txt = vtk.vtkTextActor()
        txt.SetInput(title)
        txt.GetTextProperty().SetColor(0, 0, 0)
        txt.GetTextProperty().SetFontSize(18)
        txt.SetPosition(10, 10)
        ren.AddActor2D(txt)
    win = vtk.vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.AddRenderer(ren)
    win.SetSize(*size)
    cam = ren.GetActiveCamera()
    cx, cy, cz = [(bounds[2 * c] + bounds[2 * c + 1]) / 2 for c in range(3)]
    d = max(0.9 * size_scene + 2.5 * size_body, 1e-3)
    cam.SetFocalPoint(cx, cy, cz)
    cam.SetPosition(cx + 0.9 * d, cy - 1.6 * d, cz + 0.7 * d)
    cam.SetViewUp(0, 0, 1)
    ren.ResetCameraClippingRange()
    win.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(png)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("pvd")
    ap.add_argument("png")
    ap.add_argument("--time", type=float)
    ap.add_argument("--record", type=int)
    ap.add_argument("--size", default="800x600")
    ap.add_argument("--force-scale", type=float)
    a = ap.parse_args()
    recs = records(a.pvd)
    if not recs:
        sys.exit("vtk_frame.py: no records in " + a.pvd)
    if a.record is not None:
        k = a.record
    elif a.time is not None:
        k = min(range(len(recs)), key=lambda i: abs(recs[i][0] - a.time))
    else:
        k = peak_record(recs)
    t, bpath, cpath = recs[k]
    m = re.search(r"_bodies_(\d+)\.vtp$", bpath)
    rec = int(m.group(1)) if m else k
    contacts = read(cpath)
    fn = contacts.GetPointData().GetArray("force_normal")
    fmax = max((fn.GetValue(i) for i in range(fn.GetNumberOfTuples())), default=0.0) if fn else 0.0
    w, h = (int(x) for x in a.size.split("x"))
    render(read(bpath), contacts, a.png, (w, h), a.force_scale,
           f"t = {t:.6g} s, record {rec}, largest normal force {fmax:.4g} N")
    print(f"{a.png}: frame {k}, record {rec}, t = {t:.9g} s")


if __name__ == "__main__":
    main()
