"""Frames as written (docs/formats.md section 3): contact forces are stated against the normal the scene writes."""

from fractions import Fraction

import contactcert as cc


def ladder(mu, normal=(0, 1)):
    """A 3-4-5 ladder against a frictionless wall, its floor contact's normal written as `normal`."""
    return cc.Scene.from_dict({
        "kind": "planar",
        "workpiece": {"shape": {"type": "polygon", "vertices": [[3, 0], [2, "5/2"], [0, 4]]}, "com": ["3/2", 2]},
        "fixels": [{"point": [3, 0], "normal": list(normal), "gap": 0, "mu_s": mu, "mu_k": mu},
                   {"point": [0, 4], "normal": [1, 0], "gap": 0, "mu_s": "0", "mu_k": "0"}]})


def test_the_ladder_reads_c_n_1_along_the_written_normal():
    floor, wall = ladder("1/2").stability("0,-1,0").contacts
    assert (floor.normal, floor.c_n, floor.c_t) == ((0, 1), 1, Fraction(3, 8))
    assert (wall.normal, wall.c_n, wall.c_t) == ((1, 0), Fraction(3, 8), 0)
    for c in (floor, wall):
        assert c.force == tuple(c.c_n * n + c.c_t * t for n, t in zip(c.normal, c.tangent))


def test_a_longer_written_normal_scales_the_components_not_the_force():
    short, long = (ladder("1/2", n).stability("0,-1,0").contacts[0] for n in ((0, 1), (0, 4)))
    assert long.normal == (0, 4) and long.c_n == short.c_n / 4 and long.force == short.force


def test_below_the_threshold_the_moving_contacts():
    r = ladder("1/4").stability("0,-1,0")
    assert r.verdict == "unstable" and r.contacts is None and r.moving_contacts
