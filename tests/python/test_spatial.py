"""A body in space from Python (issue 34): SpatialScene.modes() is `contactcert modes FILE` on a spatial scene
(to_dict() == --json), its certificate checks against the scene, and bad input raises ValueError naming the field."""

import pytest

import contactcert as cc
from conftest import SCENES, cli_json

BOX = SCENES / "spatial_box_on_plane.json"


def test_modes_equal_the_cli():
    m = cc.SpatialScene.from_file(BOX).modes()
    assert m.to_dict() == cli_json("modes", BOX)
    assert len(m.modes) == 340 and m.counts["all_touching"] == 99
    assert m.acceleration("ssss")[2] > 0


def test_certificate_checks_against_the_scene(tmp_path):
    box = cc.SpatialScene.from_file(BOX)
    m = box.modes(certificate=tmp_path / "c.json")
    assert m.certificate is not None
    ok = cc.check(m.certificate, problem=box)
    assert ok.valid and ok.kind == "spatial_modes"
    corner = cc.SpatialScene.from_file(SCENES / "spatial_box_in_corner.json")
    assert not cc.check(tmp_path / "c.json", problem=corner).valid


def test_bad_input_names_the_field():
    data = cc.SpatialScene.from_file(BOX).to_dict()
    data["contacts"][0]["normal"] = [0, 0, 0]
    with pytest.raises(ValueError, match=r"\$\.contacts\[0\]\.normal"):
        cc.SpatialScene.from_dict(data)


def test_budget_raises():
    with pytest.raises(cc.BudgetExceeded, match="node budget of 5"):
        cc.SpatialScene.from_file(BOX).modes(max_nodes=5)
