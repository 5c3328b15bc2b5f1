#!/usr/bin/env python3
"""What a render from Python costs against the same render from C++.

    bench/python_cost.py [--build build] [--runs 5] [--out docs/python-cost.md]

One mesh of ~1.3M triangles (icosphere_4 subdivided 4 times, with its
normals, made by `shadinglab normals`), rendered at 1920x1080 by the CPU
renderer, `--runs` times each, the two interleaved:
- C++: `shadinglab render MESH --backend cpu --size 1920x1080 --stats`
  (its read, prepare and render milliseconds);
- Python: pvpython reading the same file with VTK's reader and calling
  shadinglab.render(mesh, size=(1920, 1080)) (the call's wall time and the
  renderer's own milliseconds).
Each process's peak resident memory is the kernel's (wait4's ru_maxrss).
Medians of the runs; the file is headed with the machine, date and commit.
"""
import argparse
import datetime
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

PYTHON_SIDE = r'''
import json, resource, sys, time
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
import shadinglab
imported = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
t0 = time.perf_counter()
reader = vtkXMLPolyDataReader(); reader.SetFileName(sys.argv[1]); reader.Update()
t1 = time.perf_counter()
image, stats = shadinglab.render(reader.GetOutput(), size=(1920, 1080))
t2 = time.perf_counter()
print(json.dumps({"read_ms": 1e3 * (t1 - t0), "call_ms": 1e3 * (t2 - t1),
                  "render_ms": stats["milliseconds"], "covered": stats["pixels_covered"],
                  "imported_mb": imported}))
'''


def run(command, env=None):
    """stdout, wall seconds and peak RSS (MB) of one process."""
    start = time.perf_counter()
    child = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, env=env, text=True)
    out = child.stdout.read()
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.perf_counter() - start
    if status != 0:
        raise RuntimeError(f"{command[0]} failed ({status})")
    return out, wall, usage.ru_maxrss / 1024.0


def machine():
    cpu = platform.processor() or "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip()
    return f"{cpu}, {os.cpu_count()} cores; {datetime.date.today()}; commit {commit}"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--out", default=os.path.join(ROOT, "docs", "python-cost.md"))
    args = parser.parse_args()
    exe = os.path.join(args.build, "bin", "shadinglab")
    env = dict(os.environ, PYTHONPATH=os.path.join(args.build, "lib", "python3", "dist-packages"))
    with tempfile.TemporaryDirectory() as work:
        mesh = os.path.join(work, "sphere.vtp")
        subprocess.run([exe, "normals", os.path.join(ROOT, "datasets", "icosphere_4.vtp"), "--subdivide", "4",
                        "--out", mesh], check=True, capture_output=True)
        script = os.path.join(work, "render.py")
        with open(script, "w") as f:
            f.write(PYTHON_SIDE)
        cpp, py = [], []
        for _ in range(args.runs):
            out, wall, rss = run([exe, "render", mesh, "--backend", "cpu", "--size", "1920x1080", "--stats",
                                  "--out", os.path.join(work, "cpp.png")])
            stats = json.loads(out.strip().splitlines()[-1])
            cpp.append(dict(wall=wall, rss=rss, read=stats["read_ms"], call=stats["prepare_ms"] + stats["render_ms"],
                            render=stats["render_ms"], triangles=stats["triangles"]))
            out, wall, rss = run(["pvpython", script, mesh], env=env)
            stats = json.loads(out.strip().splitlines()[-1])
            py.append(dict(wall=wall, rss=rss, read=stats["read_ms"], call=stats["call_ms"],
                           render=stats["render_ms"], own=rss - stats["imported_mb"]))
    med = lambda rows, key: statistics.median(r[key] for r in rows)
    ratio = lambda key: statistics.median(p[key] / c[key] for p, c in zip(py, cpp))
    lines = [
        "# A render from Python against the same render from C++",
        "",
        f"Measured on {machine()}. Written by `bench/python_cost.py --runs {args.runs}`; do not edit.",
        "",
        f"The CPU renderer draws {cpp[0]['triangles']:,} triangles (icosphere_4 subdivided 4 times, with",
        "normals) at 1920x1080, from the command line (C++) and from `shadinglab.render` in pvpython.",
        f"Medians of {args.runs} runs each, the two interleaved; the ratio is the median of the paired ratios.",
        "",
        "| | C++ (`shadinglab render`) | Python (`shadinglab.render`) | Python / C++ |",
        "|---|---|---|---|",
        f"| read the file (ms) | {med(cpp, 'read'):.0f} | {med(py, 'read'):.0f} | {ratio('read'):.2f} |",
        f"| prepare + render: the call (ms) | {med(cpp, 'call'):.0f} | {med(py, 'call'):.0f} | {ratio('call'):.2f} |",
        f"| of which the renderer's frame (ms) | {med(cpp, 'render'):.0f} | {med(py, 'render'):.0f} | {ratio('render'):.2f} |",
        f"| whole process, wall (s) | {med(cpp, 'wall'):.2f} | {med(py, 'wall'):.2f} | {ratio('wall'):.2f} |",
        f"| peak resident memory (MB) | {med(cpp, 'rss'):.0f} | {med(py, 'rss'):.0f} | {ratio('rss'):.2f} |",
        f"| of which above pvpython with ParaView's modules imported (MB) | | {med(py, 'own'):.0f} | |",
        "",
        "The Python call converts the vtkPolyData, renders, and copies the frame once into the output",
        "vtkImageData (display bytes and linear floats); the NumPy array is a view of that array. The",
        "whole process in Python includes starting pvpython and importing ParaView's VTK modules (most",
        "of its memory); the command line's read includes its input checks, and it writes its PNG.",
        "",
    ]
    with open(args.out, "w") as f:
        f.write("\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    sys.exit(main())
