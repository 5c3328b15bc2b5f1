#!/usr/bin/python3
"""Writes a torus of about N triangles in one of the formats scans come in.

    bench/make_scan.py TRIANGLES OUT.{ply,stl,obj,off} [--ascii] [--big-endian]

The torus is a closed grid of n x n quads split into two triangles each
(n = round(sqrt(TRIANGLES / 2))), major radius 1, minor 0.35. Binary PLY is
written as scanners write it: `float x y z` and `uchar` count + `int`
indices. Used by bench/load_bench.py and the reader tests; NumPy only.
"""
import argparse
import math
import sys

import numpy as np


def torus(triangles):
    n = max(3, int(round(math.sqrt(triangles / 2.0))))
    u = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
    uu, vv = np.meshgrid(u, u, indexing='ij')
    r = 1.0 + 0.35 * np.cos(vv)
    pts = np.stack([r * np.cos(uu), r * np.sin(uu), 0.35 * np.sin(vv)], axis=-1)
    pts = pts.reshape(-1, 3).astype(np.float32)
    i = np.arange(n)
    ii, jj = np.meshgrid(i, i, indexing='ij')
    a = ii * n + jj
    b = ((ii + 1) % n) * n + jj
    c = ((ii + 1) % n) * n + (jj + 1) % n
    d = ii * n + (jj + 1) % n
    tris = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3),
                           np.stack([a, c, d], -1).reshape(-1, 3)])
    return pts, tris.astype(np.int32)


def write_ply(path, pts, tris, ascii_, big):
    fmt = 'ascii' if ascii_ else ('binary_big_endian' if big else 'binary_little_endian')
    head = ('ply\nformat %s 1.0\nelement vertex %d\nproperty float x\nproperty float y\n'
            'property float z\nelement face %d\nproperty list uchar int vertex_indices\n'
            'end_header\n' % (fmt, len(pts), len(tris)))
    with open(path, 'wb') as f:
        f.write(head.encode())
        if ascii_:
            np.savetxt(f, pts, fmt='%.7g')
            np.savetxt(f, np.hstack([np.full((len(tris), 1), 3), tris]), fmt='%d')
            return
        e = '>' if big else '<'
        f.write(pts.astype(e + 'f4').tobytes())
        rec = np.zeros(len(tris), dtype=[('n', 'u1'), ('i', e + 'i4', 3)])
        rec['n'] = 3
        rec['i'] = tris
        f.write(rec.tobytes())


def write_stl(path, pts, tris, ascii_):
    p = pts[tris]
    nrm = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    nrm /= np.maximum(np.linalg.norm(nrm, axis=1, keepdims=True), 1e-30)
    if ascii_:
        with open(path, 'w') as f:
            f.write('solid torus\n')
            for k in range(len(tris)):
                f.write(' facet normal %.7g %.7g %.7g\n  outer loop\n' % tuple(nrm[k]))
                for v in p[k]:
                    f.write('   vertex %.7g %.7g %.7g\n' % tuple(v))
                f.write('  endloop\n endfacet\n')
            f.write('endsolid torus\n')
        return
    rec = np.zeros(len(tris), dtype=[('n', '<f4', 3), ('v', '<f4', (3, 3)), ('a', '<u2')])
    rec['n'] = nrm
    rec['v'] = p
    with open(path, 'wb') as f:
        f.write(b'binary torus'.ljust(80, b' '))
        f.write(np.uint32(len(tris)).tobytes())
        f.write(rec.tobytes())


def write_text(path, pts, tris, off):
    with open(path, 'wb') as f:
        if off:
            f.write(b'OFF\n%d %d 0\n' % (len(pts), len(tris)))
            np.savetxt(f, pts, fmt='%.7g')
            np.savetxt(f, np.hstack([np.full((len(tris), 1), 3), tris]), fmt='%d')
        else:
            np.savetxt(f, pts, fmt='v %.7g %.7g %.7g')
            np.savetxt(f, tris + 1, fmt='f %d %d %d')


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('triangles', type=int)
    ap.add_argument('out')
    ap.add_argument('--ascii', action='store_true')
    ap.add_argument('--big-endian', action='store_true')
    a = ap.parse_args()
    if a.triangles < 18 or a.triangles > 2**31 // 2:
        print('make_scan: triangles must be in [18, 2^30] (got %d)' % a.triangles, file=sys.stderr)
        return 2
    pts, tris = torus(a.triangles)
    ext = a.out.rsplit('.', 1)[-1].lower()
    if ext == 'ply':
        write_ply(a.out, pts, tris, a.ascii, a.big_endian)
    elif ext == 'stl':
        write_stl(a.out, pts, tris, a.ascii)
    elif ext in ('obj', 'off'):
        write_text(a.out, pts, tris, ext == 'off')
    else:
        print('make_scan: unknown extension .%s (ply, stl, obj, off)' % ext, file=sys.stderr)
        return 2
    return 0


if __name__ == '__main__':
    sys.exit(main())
