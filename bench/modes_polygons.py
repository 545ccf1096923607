#!/usr/bin/env python3
"""Scenes of bench/modes_peer.sh: a convex lattice polygon whose lower chain has k edges (the k shortest primitive
directions (a, b), a > 0, by slope), one fixel at the midpoint of each chain edge, so the fixels are in convex
position. `gap`: every fixel a quarter of the edge's integer normal below its edge (all k at a gap). Writes the
contactcert scene (JSON) and, for the touching scene, the same contacts for the MATLAB peer (P points, N unit
inward normals) as an Octave script.
  bench/modes_polygons.py K {touching|gap} SCENE.json [PEER.m]"""
import math
import sys
from fractions import Fraction


def chain(k):
    dirs, r = set(), 1
    while len(dirs) < k:
        dirs = {(a, b) for a in range(1, r + 1) for b in range(-r, r + 1) if math.gcd(a, b) == 1}
        r += 1
    ds = sorted(dirs, key=lambda d: (d[0] ** 2 + d[1] ** 2, d[1] / d[0]))[:k]
    return sorted(ds, key=lambda d: d[1] / d[0])


def main():
    k, kind, scene = int(sys.argv[1]), sys.argv[2], sys.argv[3]
    ds = chain(k)
    V = [(0, 0)]
    for a, b in ds:
        V.append((V[-1][0] + a, V[-1][1] + b))
    points, normals = [], []
    for i, (a, b) in enumerate(ds):
        m = (Fraction(V[i][0] + V[i + 1][0], 2), Fraction(V[i][1] + V[i + 1][1], 2))
        n = (-b, a)  # inward: the polygon is counter-clockwise, its lower chain left to right
        if kind == "gap":
            m = (m[0] - Fraction(n[0], 4), m[1] - Fraction(n[1], 4))
        points.append(m)
        normals.append(n)
    with open(scene, "w") as f:
        f.write('{"kind":"planar","workpiece":{"shape":{"type":"polygon","vertices":[%s]}},"mu_s":"1/2","mu_k":"1/2",'
                '"fixels":[%s]}\n' % (",".join("[%d,%d]" % v for v in V),
                                      ",".join('{"position":["%s","%s"]}' % p for p in points)))
    if len(sys.argv) > 4:
        with open(sys.argv[4], "w") as f:
            f.write("P = [%s]';\n" % ";".join("%.17g,%.17g" % (float(p[0]), float(p[1])) for p in points))
            f.write("N = [%s]';\n" % ";".join("%.17g,%.17g" % (n[0] / math.hypot(*n), n[1] / math.hypot(*n))
                                             for n in normals))


main()
