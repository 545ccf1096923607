#!/usr/bin/env python3
"""Contact modes of a spatial scene by the float 3-D peer, beside contactcert's list (driver of bench/spatial_peer.sh).

    bench/spatial_peer.py PEER_DIR PYHULL_DIR SCENE OURS_JSON RUNS

PEER_DIR is a copy of the 3-D contact-mode enumerator of Huang, Cheng and Mason (the contact_modes repository:
python/src/contact_modes/modes_3d.py), PYHULL_DIR a built copy of pyhull (its qhull wrapper, not packaged by
Debian). Neither is part of this repository. SCENE is a contactcert spatial scene (docs/formats.md, section 3b),
OURS_JSON the output of `contactcert modes SCENE --json`.

The peer's model. Twists xi = (v, omega) of the body; contact i moves by J_i xi, J_i = [I, -hat(r_i)],
r_i = p_i - com (the peer takes the body frame's origin; any origin gives the same sign vectors). Its rows:
A = -n_i^T J_i (A xi <= 0 is non-penetration) and, per contact, num_sliding_planes rows -w^T J_i, w the normals
of lines through the origin of the tangent plane; a mode is the sign vector of the twist's normal and tangential
velocities (sliding in an open sector between two lines or along one, sticking at 0). Our square pyramid (any
pyramid with 4 edges d_0..d_3 and d_{j+2} = -d_j) ties its edges on two such lines: d_j . a = d_{j+1} . a on
w_0 = d_0 - d_1 and w_1 = d_1 - d_2, so giving the peer w_0, w_1 makes its 9 tangential sign pairs exactly our
letters f, A..H (each pair is mapped by the edges that minimise d_j . a at a point of its cell). From rest our
accelerations obey the same linear map, so both sides enumerate the faces of one arrangement restricted by the
non-penetration cone. The peer's code reads its signs two ways (its sampler negates the twist, its
one-dimensional branch does not); on the scenes of bench/spatial_peer.sh each of its lists per
contacting/separating mode is a whole central arrangement, closed under negating every sign, so the comparison is
the same under either reading.

The peer's call: `enum_sliding_sticking_3d_proj(A, b, T, bt)` (contacting/separating modes by the face lattice of
the polar of the non-penetration cone through qhull, `enumerate_contact_separating_3d`, then per
contacting/separating mode the faces of the tangential arrangement projected onto the null space of its contacting
rows, as zonotope vertices through qhull). Its debug prints are replaced by a no-op in its module (printing the
arrays would be timed otherwise); `quadprog` (used only by a function this call does not reach) is a stub. CPU
seconds (time.process_time) of the call, best of RUNS, start-up and imports excluded.

Prints one line: our modes and contacting/separating patterns, the peer's modes as listed, distinct, its
contacting/separating modes, its CPU seconds and agree: `yes` when the peer's modes mapped to our letters are
exactly our list, else `no:-MISSING+EXTRA` (ours the peer lacks, the peer's we lack), `peer_error:NAME` when the
peer's call raised, `-` when a pyramid is not the peer's model; then the first differences, one per line.
"""
import contextlib
import importlib
import io
import json
import sys
import time
import types
import warnings
from fractions import Fraction

import numpy as np


def load_peer(peer_dir, pyhull_dir):
    """modes_3d of the peer, imported without its package's __init__ (which needs the viewer's OpenGL stack)."""
    sys.path.insert(0, pyhull_dir)
    stub = types.ModuleType("quadprog")

    def solve_qp(*_args, **_kwargs):
        raise NotImplementedError("quadprog is a stub here")

    stub.solve_qp = solve_qp
    sys.modules.setdefault("quadprog", stub)
    package = types.ModuleType("contact_modes")
    package.__path__ = [peer_dir + "/python/src/contact_modes"]
    sys.modules["contact_modes"] = package
    helpers = importlib.import_module("contact_modes.helpers")
    package.lexographic_combinations = helpers.lexographic_combinations  # arrangements.py imports it from the package
    modes_3d = importlib.import_module("contact_modes.modes_3d")
    modes_3d.print = lambda *args, **kwargs: None
    return modes_3d


def number(x):
    return float(Fraction(x)) if isinstance(x, str) else float(x)


def vector(xs):
    return np.array([number(x) for x in xs])


def default_frame(n):
    """docs/formats.md 3b: j the first axis of the largest |n_j|, t1 = n_j e_{j+1} - n_{j+1} e_j, t2 = n x t1."""
    j = int(np.argmax(np.abs(n)))
    t1 = np.zeros(3)
    t1[(j + 1) % 3] = n[j]
    t1[j] = -n[(j + 1) % 3]
    return t1, np.cross(n, t1)


def contact_model(scene, contact):
    """(p, n, t1, t2, edges as 2-vectors in (t1, t2)) of one contact."""
    n = vector(contact["normal"])
    t1, t2 = (vector(t) for t in contact["tangent"]) if "tangent" in contact else default_frame(n)
    if "edges" in contact:
        edges = [vector(e) for e in contact["edges"]]
    else:
        mu = number(contact.get("mu", scene.get("mu")))
        edges = [np.array(e) * mu for e in ((1, 0), (0, 1), (-1, 0), (0, -1))]
    return vector(contact["point"]), n, t1, t2, edges


def letters_of_signs(edges, w):
    """Our letter for each of the peer's sign pairs (sign w_0 . a, sign w_1 . a), a in (t1, t2) coordinates."""
    table = {(0, 0): "f"}
    basis = np.linalg.inv(np.array(w))  # a = basis @ (s0, s1) meets w_k . a = s_k
    for s0 in (-1, 0, 1):
        for s1 in (-1, 0, 1):
            if s0 == 0 and s1 == 0:
                continue
            a = basis @ np.array([s0, s1], float)
            dots = [float(d @ a) for d in edges]
            low = [j for j, x in enumerate(dots) if abs(x - min(dots)) <= 1e-12 * max(1.0, abs(min(dots)))]
            if len(low) == 1:
                table[(s0, s1)] = chr(ord("A") + 2 * low[0])
            else:  # two adjacent edges j, j + 1 (mod 4)
                j = low[1] if low == [0, 3] else low[0]
                table[(s0, s1)] = chr(ord("A") + 2 * j + 1)
    return table


def peer_rows(scene):
    """A (k x 6), T (2k x 6) and the sign-pair tables, or None when a pyramid is not the peer's model."""
    com = vector(scene["body"]["com"])
    a_rows, t_rows, tables = [], [], []
    for contact in scene["contacts"]:
        p, n, t1, t2, edges = contact_model(scene, contact)
        if len(edges) != 4 or any(np.any(edges[j + 2] + edges[j]) for j in range(2)):
            return None
        r = p - com
        jacobian = np.hstack([np.eye(3), -np.array([[0, -r[2], r[1]], [r[2], 0, -r[0]], [-r[1], r[0], 0]])])
        frame = np.array([t1, t2])
        w = [edges[0] - edges[1], edges[1] - edges[2]]  # in (t1, t2) coordinates
        a_rows.append(-(n @ jacobian))
        t_rows.extend(-((wk @ frame) @ jacobian) for wk in w)
        tables.append(letters_of_signs(edges, w))
    return np.array(a_rows), np.array(t_rows), tables


def enumerate_peer(modes_3d, a, t, runs):
    """(the peer's answer of the last run, best CPU seconds)."""
    best = None
    for _ in range(runs):
        with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
            warnings.simplefilter("ignore")
            start = time.process_time()
            answer = modes_3d.enum_sliding_sticking_3d_proj(a, np.zeros((len(a), 1)), t, np.zeros(len(t)))
            seconds = time.process_time() - start
        best = seconds if best is None else min(best, seconds)
    return answer, best


def peer_strings(answer, tables):
    """The peer's modes as our letter strings: its groups pair in order with the contacting/separating faces it
    annotated (`ss_lattice`); per contact `s` where the face separates it, else the letter of its sign pair."""
    groups, cs_lattice, _ = answer
    faces = [face for layer in cs_lattice.L for face in layer if hasattr(face, "ss_lattice")]
    k = len(tables)
    strings = []
    for face, group in zip(faces, groups):
        for mode in np.atleast_2d(np.array(group, dtype=float)):
            signs = np.sign(mode).astype(int)
            strings.append("".join("s" if face.m[i] == "s" else tables[i][(signs[k + 2 * i], signs[k + 2 * i + 1])]
                                   for i in range(k)))
    return strings, sum(len(layer) for layer in cs_lattice.L)


LIST = 3  # differences listed


def main():
    peer_dir, pyhull_dir, scene_path, ours_path, runs = sys.argv[1:6]
    with open(scene_path) as f:
        scene = json.load(f)
    with open(ours_path) as f:
        ours = {m["mode"] for m in json.load(f)["modes"]}
    ours_cs = len({"".join("s" if c == "s" else "c" for c in m) for m in ours})
    rows = peer_rows(scene)
    if rows is None:
        print(len(ours), ours_cs, "- - - - -")
        return
    a, t, tables = rows
    try:
        answer, seconds = enumerate_peer(load_peer(peer_dir, pyhull_dir), a, t, int(runs))
    except Exception as e:  # the peer's own failure (e.g. numpy's LinAlgError) is a result of the comparison
        while e.__cause__ is not None or e.__context__ is not None:
            e = e.__cause__ or e.__context__
        print(len(ours), ours_cs, "- - - -", "peer_error:" + type(e).__name__)
        return
    strings, cs = peer_strings(answer, tables)
    theirs = set(strings)
    missing, extra = sorted(ours - theirs), sorted(theirs - ours)
    agree = "yes" if not missing and not extra else "no:-%d+%d" % (len(missing), len(extra))
    print(len(ours), ours_cs, len(strings), len(theirs), cs, "%.4f" % seconds, agree)
    for m in missing[:LIST]:
        print("  contactcert only:", m)
    for m in extra[:LIST]:
        print("  peer only:", m)


if __name__ == "__main__":
    main()
