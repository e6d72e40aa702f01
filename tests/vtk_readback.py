#!/usr/bin/env python3
"""Read a `ricochet export-vtk` series back with VTK and compare it with the
results file; render one frame off screen. The series may hold every record
or a subset (the default's output times, --dt, --every), binary or ASCII.

    python3 tests/vtk_readback.py RESULTS.nc DIR [PNG]

Prints PASS/FAIL lines (counted by scripts/check.sh through
tests/cli_test.sh); exits 0 when all pass. Needs python3-vtk9 and
python3-netcdf4; the rendering needs a display (run under xvfb-run).
"""
import math
import os
import re
import sys
import xml.etree.ElementTree as ET

import netCDF4
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts"))

fails = 0


def check(name, ok, detail):
    global fails
    print(f"{'PASS' if ok else 'FAIL'} vtk.{name}: {detail}")
    fails += 0 if ok else 1


def read(path):
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(path)
    r.Update()
    return r.GetOutput()


def strings(arr):
    return [arr.GetValue(i) for i in range(arr.GetNumberOfValues())]


def main():
    nc, out = sys.argv[1], sys.argv[2]
    png = sys.argv[3] if len(sys.argv) > 3 else None
    ds = netCDF4.Dataset(nc)
    stem = os.path.splitext(os.path.basename(nc))[0]
    t = ds["time"][:]
    nrec = len(t)
    root = ET.parse(os.path.join(out, stem + ".pvd")).getroot()
    sets = list(root.iter("DataSet"))
    # the frames: a subset of the records (export-vtk's default, --dt,
    # --every), each file named by its record's number
    recs = [int(re.search(r"_bodies_(\d+)\.vtp$", s.get("file")).group(1)) for s in sets[::2]]
    steps = np.array([float(s.get("timestep")) for s in sets[::2]])
    parts_ok = all(s.get("part") == str(i % 2) for i, s in enumerate(sets)) and all(
        sets[2 * i + 1].get("file") == f"{stem}_contacts_{k:06d}.vtp" for i, k in enumerate(recs))
    with open(os.path.join(out, sets[0].get("file")), "rb") as f:
        head = f.read(4096)
    fmt = ("appended raw binary" if b'format="appended"' in head and b'header_type="UInt64"' in head
           else "ASCII" if b'format="ascii"' in head else "unknown")
    check("pvd", len(sets) == 2 * len(recs) and parts_ok and recs == sorted(set(recs)) and len(recs) > 0
          and recs[-1] == nrec - 1 and np.array_equal(steps, t[recs]),
          f"{len(recs)} frames ({fmt}) of {nrec} records, the last included, "
          f"time steps equal to the file's time at those records")
    kinds = list(ds["surface_kind"][:])
    npts = {"SPHERE": 2 + 11 * 24, "PLANE": 4, "CYLINDER": 48, "BOX": 8}
    want_pts = sum(npts[k] for k in kinds)
    body_ids = list(ds["body"][:])
    sbody = list(ds["surface_body"][:])
    pos, vel = ds["body_position"], ds["body_velocity"]
    # frames: first, peak normal force (of the frames), last
    fn_all = ds["inter_force_normal"][:, 0] if "inter" in ds.dimensions else np.zeros(nrec)
    ipeak = int(np.argmax(np.asarray(fn_all)[recs]))
    kpeak = recs[ipeak]
    worst = {"pts": 0.0, "centre": 0.0, "vel": 0.0, "contact": 0.0}
    count_ok = True
    for i in sorted({0, ipeak, len(recs) - 1}):
        k = recs[i]
        b = read(os.path.join(out, sets[2 * i].get("file")))
        count_ok &= b.GetNumberOfPoints() == want_pts
        p = vtk_to_numpy(b.GetPoints().GetData())
        sid = vtk_to_numpy(b.GetPointData().GetArray("surface_id"))
        v = vtk_to_numpy(b.GetPointData().GetArray("velocity"))
        tv = b.GetFieldData().GetArray("TimeValue").GetValue(0)
        worst["pts"] = max(worst["pts"], abs(tv - t[k]))
        for j, kind in enumerate(kinds):
            if kind != "SPHERE" or sbody[j] < 0:
                continue
            bi = body_ids.index(sbody[j])
            sel = sid == ds["surface"][j]
            centre = p[sel].mean(axis=0)
            r = np.linalg.norm(p[sel] - centre, axis=1)
            worst["centre"] = max(worst["centre"], float(np.abs(centre - pos[k, bi, :]).max()),
                                  float(np.abs(r - ds["surface_radius"][j]).max()))
            worst["vel"] = max(worst["vel"], float(np.abs(v[sel] - vel[k, bi, :]).max()))
        c = read(os.path.join(out, sets[2 * i + 1].get("file")))
        if "inter" in ds.dimensions:
            cp = vtk_to_numpy(c.GetPoints().GetData())
            cf = vtk_to_numpy(c.GetPointData().GetArray("force_normal"))
            cv = vtk_to_numpy(c.GetPointData().GetArray("force_normal_vector"))
            worst["contact"] = max(worst["contact"],
                                   float(np.abs(cp - ds["inter_contact_point"][k]).max()),
                                   float(np.abs(cf - ds["inter_force_normal"][k]).max()),
                                   float(np.abs(np.linalg.norm(cv, axis=1) - cf).max()))
    check("bodies_points", count_ok, f"{want_pts} points per bodies file ({', '.join(kinds)})")
    check("bodies_values", worst["pts"] == 0 and worst["centre"] < 1e-12 and worst["vel"] == 0,
          f"TimeValue exact; sphere centre and radius within {worst['centre']:.1e} m of the file's; "
          f"velocity difference {worst['vel']:.1e} m/s (records 0, {kpeak} (peak force), {nrec - 1})")
    check("contacts_values", worst["contact"] == 0,
          f"contact points, normal forces and |force vector| equal to the file's "
          f"(max difference {worst['contact']:.1e})")
    # events: every row of the events table once, in order, kinds as strings
    ev_t, ev_k = [], []
    for i in range(len(recs)):
        c = read(os.path.join(out, sets[2 * i + 1].get("file")))
        fd = c.GetFieldData()
        n = fd.GetArray("event_count").GetValue(0)
        if n:
            ev_t += list(vtk_to_numpy(fd.GetArray("event_time")))
            ev_k += strings(fd.GetAbstractArray("event_kind"))
    want_t = list(ds["event_time"][:]) if "event" in ds.dimensions else []
    want_k = list(ds["event_kind"][:]) if "event" in ds.dimensions else []
    check("events", ev_t == want_t and ev_k == want_k,
          f"{len(ev_t)} events in the field data, {len(want_t)} in the file, times and kinds equal")
    if png:
        import vtk_frame
        b = read(os.path.join(out, sets[2 * ipeak].get("file")))
        c = read(os.path.join(out, sets[2 * ipeak + 1].get("file")))
        vtk_frame.render(b, c, png, (400, 300), None, f"t = {t[kpeak]:.6g} s")
        r = vtk.vtkPNGReader()
        r.SetFileName(png)
        r.Update()
        img = vtk_to_numpy(r.GetOutput().GetPointData().GetScalars())
        dims = r.GetOutput().GetDimensions()
        distinct = len(np.unique(img.reshape(len(img), -1), axis=0)) if len(img) else 0
        check("render", dims[0] == 400 and dims[1] == 300 and distinct > 10,
              f"record {kpeak} rendered off screen to a {dims[0]}x{dims[1]} PNG with {distinct} colours")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
