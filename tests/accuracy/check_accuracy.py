#!/usr/bin/env python3
"""Runs `shadinglab accuracy --quick` and checks what it writes: the
documented CSV columns, a Markdown table, a PNG, and the trends the docs
reads from the numbers (errors fall with tessellation; Phong beats Gouraud
and flat on a fine mesh; coverage converges)."""
import csv
import math
import os
import subprocess
import sys

exe, out = sys.argv[1], sys.argv[2]
failures = 0


def check(ok, what):
    global failures
    print(("ok   " if ok else "FAIL ") + what)
    failures += 0 if ok else 1


run = subprocess.run([exe, "accuracy", "--quick", "--backend", "cpu", "--out", out],
                     capture_output=True, text=True, timeout=240)
check(run.returncode == 0, "exit 0 (stderr tail: %s)" % run.stderr[-300:])
columns = ("shape,level,triangles,backend,mode,model,normals,width,height,threads,prepare_ms,"
           "frame_ms,mean_lin,rmse_lin,p99_lin,max_lin,mean_255,rmse_255,p99_255,max_255,"
           "coverage_mismatch,pareto,normal_spread_deg,triangle_px,sharpness,peak,front_px,view,"
           "diff_flat_255,diff_gouraud_255,diff_normals_255").split(",")
with open(os.path.join(out, "accuracy.csv")) as f:
    rows = list(csv.DictReader(f))
check(rows and list(rows[0].keys()) == columns, "CSV columns as documented")
check(len(rows) >= 30, "%d configurations" % len(rows))
# eq. 4.4's estimates: finite, non-negative, and both shrinking as the
# torus is refined (on the 6-segment torus Gouraud is farther from Phong
# than flat: it spreads a vertex's highlight over huge triangles).
diffs = [(float(r["diff_flat_255"]), float(r["diff_gouraud_255"])) for r in rows]
check(all(math.isfinite(f) and math.isfinite(g) and f >= 0 and g >= 0 for f, g in diffs),
      "mode differences finite and >= 0")
torus = sorted({(int(r["level"]), float(r["diff_flat_255"]), float(r["diff_gouraud_255"]))
                for r in rows if r["shape"] == "torus" and r["normals"] == "area"
                and r["model"] == "blinn-phong"})
check(len(torus) >= 2 and torus[0][1] > torus[-1][1] and torus[0][2] > torus[-1][2],
      "torus: mode differences fall with tessellation %s"
      % [(l, round(f, 3), round(g, 3)) for l, f, g in torus])
for r in rows:
    for k in columns[10:21]:
        v = float(r[k])
        if not (v == v and v >= 0 and v < 1e9):
            check(False, "finite, non-negative %s in %s" % (k, r))
            break


def series(shape, mode, model="blinn-phong", normals="area"):
    return sorted(((int(r["level"]), float(r["mean_255"]), float(r["coverage_mismatch"]))
                   for r in rows if r["shape"] == shape and r["mode"] == mode
                   and r["model"] == model and r["normals"] == normals))


for shape in ("sphere", "torus"):
    phong = series(shape, "phong")
    check(len(phong) >= 2 and all(a[1] > b[1] for a, b in zip(phong, phong[1:])),
          "%s: Phong's mean error falls with tessellation %s" % (shape, [p[1] for p in phong]))
    check(all(a[2] > b[2] for a, b in zip(phong, phong[1:])),
          "%s: the silhouette converges %s" % (shape, [p[2] for p in phong]))
    finest = phong[-1][0]
    gouraud = dict((l, e) for l, e, _ in series(shape, "gouraud"))
    flat = dict((l, e) for l, e, _ in series(shape, "flat"))
    check(phong[-1][1] < gouraud[finest] and phong[-1][1] < flat[finest],
          "%s at level %d: Phong %.3f < Gouraud %.3f, flat %.3f" %
          (shape, finest, phong[-1][1], gouraud[finest], flat[finest]))
    check(any(r["pareto"] == "1" for r in rows if r["shape"] == shape),
          "%s: a Pareto front" % shape)
sphere = series("sphere", "phong")
check(sphere[-1][1] < 1.0, "sphere, 128 slices, Phong: mean error %.3f/255 < 1" % sphere[-1][1])
with open(os.path.join(out, "accuracy.md")) as f:
    md = f.read()
check("## Pareto front" in md and md.count("\n|") > len(rows), "Markdown table")
with open(os.path.join(out, "accuracy.png"), "rb") as f:
    png = f.read()
check(png[:4] == b"\x89PNG" and len(png) > 20000, "PNG plot (%d bytes)" % len(png))
# The incremental scan's section: 3 quantities x 2 precisions x 10 lengths,
# every row under its bound, and its plot.
with open(os.path.join(out, "scan.csv")) as f:
    scan = list(csv.DictReader(f))
check(len(scan) == 60, "scan.csv: %d rows (60 expected)" % len(scan))
check(all(float(r["bound_ratio"]) <= 1.0 for r in scan), "scan: every row under its bound")
check("## Incremental scan" in md, "scan section in accuracy.md")
with open(os.path.join(out, "scan.png"), "rb") as f:
    check(f.read(4) == b"\x89PNG", "scan.png")
print("%d failure(s)" % failures)
sys.exit(1 if failures else 0)
