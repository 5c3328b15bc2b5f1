#!/usr/bin/env python3
"""Fits the auto mode's error prediction (docs/model.md eq. 4.1) to a
`shadinglab accuracy` CSV:

    log E_M = a_M + b_M log(spread) + c_M log(1 + sharpness) + d_M log(peak)

per mode (flat, gouraud, phong), on the CPU rows with area-weighted normals,
by least squares; the margin is the 95th percentile of the residuals (the
conservative prediction adds it). Prints the C++ constants for
plugin/render/src/AutoMode.cpp and the fit's quality.

usage: scripts/fit-auto-mode.py accuracy.csv [PERCENTILE]"""
import csv
import math
import sys


def solve(rows, n):
    # Normal equations of an n-parameter linear least squares (no numpy).
    ata = [[0.0] * n for _ in range(n)]
    atb = [0.0] * n
    for x, y in rows:
        for i in range(n):
            atb[i] += x[i] * y
            for j in range(n):
                ata[i][j] += x[i] * x[j]
    # Gaussian elimination with partial pivoting.
    m = [ata[i] + [atb[i]] for i in range(n)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(m[r][c]))
        m[c], m[p] = m[p], m[c]
        for r in range(n):
            if r != c and m[c][c] != 0:
                f = m[r][c] / m[c][c]
                m[r] = [a - f * b for a, b in zip(m[r], m[c])]
    return [m[i][n] / m[i][i] for i in range(n)]


rows = list(csv.DictReader(open(sys.argv[1])))
# Errors below this (1/255) are at the floor of 8-bit rounding: they say
# nothing about interpolation and would pull the power law down.
FLOOR = 0.02
# The margin: this percentile of the training residuals. 0.95 makes the
# training set's own predictions safe 95% of the time.
PERCENTILE = float(sys.argv[2]) if len(sys.argv) > 2 else 0.95
out = {}
for mode in ("flat", "gouraud", "phong"):
    data = []
    for r in rows:
        if r["backend"] != "cpu" or r["normals"] != "area" or r["mode"] != mode:
            continue
        e = float(r["mean_255"])
        spread = math.radians(float(r["normal_spread_deg"]))
        if e < FLOOR or spread <= 0:
            continue
        data.append(([1.0, math.log(spread), math.log1p(float(r["sharpness"])),
                      math.log(float(r["peak"]))], math.log(e)))
    a, b, c, d = solve(data, 4)
    res = sorted(y - (a + b * x[1] + c * x[2] + d * x[3]) for x, y in data)
    margin = res[int(PERCENTILE * (len(res) - 1))]
    mean = sum(y for _, y in data) / len(data)
    ss = sum((y - mean) ** 2 for _, y in data)
    r2 = 1 - sum(v * v for v in res) / ss
    out[mode] = (a, b, c, d, margin)
    print("%-8s n=%3d  a=%7.3f b=%6.3f c=%6.3f d=%6.3f  margin=%.3f  R^2=%.3f" %
          (mode, len(data), a, b, c, d, margin, r2))
print()
for mode, name in (("flat", "kFlat"), ("gouraud", "kGouraud"), ("phong", "kPhong")):
    a, b, c, d, m = out[mode]
    print("constexpr Fit %s = { %.4f, %.4f, %.4f, %.4f, %.4f };" % (name, a, b, c, d, m))

# The cost model (eq. 4.2): frame_ms = a + b T/1000 + c A/1000 per mode and
# model class (0: not Cook-Torrance, 1: Cook-Torrance dielectric, 2:
# Cook-Torrance conductor, whose per-evaluation complex Fresnel costs ~4x),
# T triangles, A front-facing screen area. Least squares on the relative
# error (weights 1/frame_ms^2): the choice compares modes by their ratio, and
# unweighted, the few 1M-triangle rows of 10-50 ms set the fit, leaving the
# common 1 ms frames mispredicted (Gouraud with Cook-Torrance was predicted
# dearer than Phong at 320x240, where it is 30% cheaper).
def model_class(model):
    if not model.startswith("ct"):
        return 0
    return 2 if "conductor" in model else 1


def solve_weighted(rows, n):
    return solve([([math.sqrt(w) * v for v in x], math.sqrt(w) * y) for x, y, w in rows], n)


costs = {}
for mode in ("flat", "gouraud", "phong"):
    fits = []
    for k in range(3):
        data = [([1.0, float(r["triangles"]) / 1000, float(r["front_px"]) / 1000],
                 float(r["frame_ms"]), 1.0 / float(r["frame_ms"]) ** 2) for r in rows
                if r["backend"] == "cpu" and r["normals"] == "area" and r["mode"] == mode
                and model_class(r["model"]) == k]
        coef = solve_weighted(data, 3)
        rel = sorted(abs(sum(c * v for c, v in zip(coef, x)) / y - 1) for x, y, _ in data)
        print("cost %-8s class %d n=%3d  a=%.3f b=%.4f c=%.4f  relative error median %.2f p90 %.2f" %
              (mode, k, len(data), coef[0], coef[1], coef[2], rel[len(rel) // 2],
               rel[int(0.9 * (len(rel) - 1))]))
        fits.append(coef)
    costs[mode] = fits
for mode, name in (("flat", "kCostFlat"), ("gouraud", "kCostGouraud"), ("phong", "kCostPhong")):
    f = costs[mode]
    print("constexpr CostFit %s[3] = { %s };" %
          (name, ", ".join("{ %.4f, %.5f, %.5f }" % tuple(c) for c in f)))
