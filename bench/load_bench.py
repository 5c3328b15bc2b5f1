#!/usr/bin/python3
"""Big meshes end to end: the fast readers against VTK's, and the CLI's stages.

    bench/load_bench.py --build build --scratch DIR [--runs 3] [--sizes 1,4,16,64]
                        [--formats ply,ply-ascii,stl,stl-ascii,obj,off] [--json OUT]

For each format and size (millions of triangles) a torus is written by
bench/make_scan.py (kept in DIR for the next run), page cache warm, and
`shadinglab render --backend cpu --size 1920x1080 --stats` is run with the
fast readers and with SHADINGLAB_VTK_READERS=1 (the checked VTK path: the
precheck and VTK's reader, what the CLI did before the fast readers),
interleaved, `--runs` times each, in flat mode; the fast path also in
phong. Each row gives the medians of read, prepare, render and total time
and of the peak resident memory by stage (--stats' peak_rss_*). VTK's side
is skipped above --vtk-max millions of triangles (a 64M-triangle file takes
VTK's reader minutes). The ASCII formats are written only up to
--ascii-max (16M triangles of ASCII STL is 4 GB).
"""
import argparse
import json
import os
import platform
import statistics
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FORMATS = {  # name: (extension, make_scan arguments, ASCII)
    'ply': ('ply', [], False),
    'ply-ascii': ('ply', ['--ascii'], True),
    'stl': ('stl', [], False),
    'stl-ascii': ('stl', ['--ascii'], True),
    'obj': ('obj', [], True),
    'off': ('off', [], True),
}


def scan_file(scratch, fmt, millions):
    ext, extra, _ = FORMATS[fmt]
    path = os.path.join(scratch, 'torus_%dM_%s.%s' % (millions, fmt, ext))
    if not os.path.exists(path):
        subprocess.run([os.path.join(ROOT, 'bench', 'make_scan.py'), str(millions * 1000000), path] + extra,
                       check=True)
    with open(path, 'rb') as f:  # warm the page cache
        while f.read(1 << 24):
            pass
    return path


def render(build, path, mode, vtk, out_png):
    env = dict(os.environ)
    if vtk:
        env['SHADINGLAB_VTK_READERS'] = '1'
    else:
        env.pop('SHADINGLAB_VTK_READERS', None)
    out = subprocess.run([os.path.join(build, 'bin', 'shadinglab'), 'render', path, '--backend', 'cpu',
                          '--size', '1920x1080', '--mode', mode, '--stats',
                          '--out', out_png],
                         env=env, capture_output=True, text=True, check=True).stdout
    return json.loads(out.strip().splitlines()[-1])


KEYS = ('read_ms', 'prepare_ms', 'render_ms', 'total_ms', 'peak_rss_read_mb', 'peak_rss_prepare_mb',
        'peak_rss_mb')


def medians(samples):
    return {k: statistics.median(s[k] for s in samples) for k in KEYS} if samples else None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--build', default=os.path.join(ROOT, 'build'))
    ap.add_argument('--scratch', required=True)
    ap.add_argument('--runs', type=int, default=3)
    ap.add_argument('--sizes', default='1,4,16,64')
    ap.add_argument('--formats', default=','.join(FORMATS))
    ap.add_argument('--vtk-max', type=int, default=16)
    ap.add_argument('--ascii-max', type=int, default=16)
    ap.add_argument('--json')
    a = ap.parse_args()
    os.makedirs(a.scratch, exist_ok=True)
    rows = []
    for fmt in a.formats.split(','):
        for millions in (int(s) for s in a.sizes.split(',')):
            if FORMATS[fmt][2] and millions > a.ascii_max:
                continue
            path = scan_file(a.scratch, fmt, millions)
            fast, fast_phong, vtk = [], [], []
            png = os.path.join(a.scratch, 'frame.png')
            for _ in range(a.runs):
                fast.append(render(a.build, path, 'flat', False, png))
                if millions <= a.vtk_max:
                    vtk.append(render(a.build, path, 'flat', True, png))
                fast_phong.append(render(a.build, path, 'phong', False, png))
            row = {'format': fmt, 'millions': millions, 'triangles': fast[0]['polygons'],
                   'bytes': os.path.getsize(path), 'fast_flat': medians(fast),
                   'fast_phong': medians(fast_phong), 'vtk_flat': medians(vtk), 'runs': a.runs}
            rows.append(row)
            print('%-9s %3dM  read %8.0f ms (VTK %s)  flat %8.0f ms  phong %8.0f ms  peak %6.0f MB' % (
                fmt, millions, row['fast_flat']['read_ms'],
                '%.0f ms' % row['vtk_flat']['read_ms'] if vtk else '-',
                row['fast_flat']['total_ms'], row['fast_phong']['total_ms'],
                row['fast_phong']['peak_rss_mb']), file=sys.stderr, flush=True)
    result = {'machine': platform.platform(), 'rows': rows}
    text = json.dumps(result, indent=1)
    if a.json:
        with open(a.json, 'w') as f:
            f.write(text)
    else:
        print(text)
    return 0


if __name__ == '__main__':
    sys.exit(main())
