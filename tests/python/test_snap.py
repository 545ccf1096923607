"""Scene.from_floats (issue 33 item 3): float input made exact on purpose, every snap reported; from_dict refuses a
computed float and points to from_floats."""

import json
import math
from fractions import Fraction

import pytest

import contactcert as cc


def disk(angles, radius=2, centre=(1, -1), mu=0.1 + 0.2):
    return {"kind": "planar",
            "workpiece": {"shape": {"type": "disk", "center": list(centre), "radius": radius}, "mass": 1,
                          "inertia": 2},
            "fixels": [{"position": [centre[0] + radius * math.cos(a), centre[1] + radius * math.sin(a)]}
                       for a in angles],
            "mu_s": mu}


def test_disk_fixel_at_cos_sin_snapped_onto_the_circle_and_accepted():
    data = disk([0.3, 2.4, 4.5])
    computed = r"<dict>: \$\.fixels\[0\]\.position\[0\]: 2\.91.* computed float.*from_floats"
    with pytest.raises(ValueError, match=computed):
        cc.Scene.from_dict(data)
    scene, snaps = cc.Scene.from_floats(data, snap=1e-9)
    fields = [s.field for s in snaps]
    assert fields == ["$.mu_s", "$.fixels[0].position", "$.fixels[1].position", "$.fixels[2].position"]
    assert snaps[0].original == Fraction("0.30000000000000004") and snaps[0].snapped == Fraction(3, 10)
    for s in snaps[1:]:
        x, y = s.snapped
        assert (x - 1) ** 2 + (y + 1) ** 2 == 4  # exactly on the circle
        assert s.distance_squared <= Fraction(1, 10**18) and s.distance_approx <= 1e-9
    assert scene.to_dict()["mu_s"] == "3/10"
    assert scene.stability("0,-1,0")["verdict"] in ("strongly_stable", "weakly_stable", "unstable")


def test_snapped_twice_is_unchanged(tmp_path):
    scene, snaps = cc.Scene.from_floats(disk([0.3, 1.0, 5.0]), snap="1e-9")
    assert snaps
    again, more = cc.Scene.from_floats(scene.to_dict(), snap=1e-9)
    assert more == [] and again.to_dict() == scene.to_dict()
    path = tmp_path / "snapped.json"
    path.write_text(json.dumps(scene.to_dict()))
    assert cc.Scene.from_floats(path, snap=Fraction(1, 10**9))[1] == []


def test_polygon_point_projected_exactly():
    data = {"kind": "planar", "workpiece": {"shape": {"type": "polygon", "vertices": [[0, 0], [2, 0], [2, 2], [0, 2]]}},
            "fixels": [{"point": [0.7, -1e-12], "normal": [0, 1], "gap": 0}, {"position": [-3e-11, 1.25]}],
            "mu_s": "1/2"}
    scene, snaps = cc.Scene.from_floats(data, snap=1e-9)
    assert [(s.field, s.snapped) for s in snaps] == [("$.fixels[0].point", (Fraction(7, 10), 0)),
                                                     ("$.fixels[1].position", (0, Fraction(5, 4)))]
    assert snaps[0].to_dict()["snapped"] == ["7/10", "0"]


def test_unsnappable_point_refused_with_its_field():
    data = {"kind": "planar", "workpiece": {"shape": {"type": "disk", "center": [0, 0], "radius": 1}},
            "fixels": [{"position": [1, 0]}, {"point": [0.6, 0.8001], "normal": [-0.6, -0.8], "gap": 0}],
            "mu_s": "1/2"}
    with pytest.raises(ValueError, match=r"<dict>: \$\.fixels\[1\]\.point: a point within 1e-09 of the disk"):
        cc.Scene.from_floats(data, snap=1e-9)
    assert cc.Scene.from_floats(data, snap=1e-3)[1][0].field == "$.fixels[1].point"
    with pytest.raises(ValueError, match="tolerance > 0"):
        cc.Scene.from_floats(data, snap=0)


def test_from_dict_refuses_point_one_plus_point_two():
    data = {"kind": "planar", "workpiece": {"shape": {"type": "disk", "center": [0, 0], "radius": 1}},
            "fixels": [{"position": [0.6, 0.8]}, {"position": [-1, 0]}], "mu_s": 0.1 + 0.2}
    with pytest.raises(ValueError, match=r"<dict>: \$\.mu_s: 0\.30000000000000004 is a computed float"):
        cc.Scene.from_dict(data)
    scene, snaps = cc.Scene.from_floats(data, snap=1e-9)
    assert scene.to_dict()["mu_s"] == "3/10" and [s.field for s in snaps] == ["$.mu_s"]


def test_from_dict_keeps_written_decimals():
    data = {"kind": "planar", "workpiece": {"shape": {"type": "disk", "center": [0, 0], "radius": 1}},
            "fixels": [{"position": [0.6, 0.8]}, {"position": [-1, 0]}], "mu_s": 0.966}
    assert cc.Scene.from_dict(data).to_dict()["mu_s"] == 0.966
