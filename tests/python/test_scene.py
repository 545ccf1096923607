"""Every Scene query on the bundled scenes agrees exactly with the CLI's --json."""

import xml.etree.ElementTree as ET
from fractions import Fraction

import pytest

import contactcert as cc
from conftest import SCENES, cli_error, cli_json

BT2002 = sorted(p.name for p in SCENES.glob("bt2002_*.json"))
MODES = {"bt2002_section4_disk.json": ["na", "ns", "ss"], "bt2002_section7_disk.json": ["ss", "sl", "nn"],
         "bt2002_fig10_pentagon_insert.json": ["nnn", "snl"]}


def mode_of(name):
    """The mode named in a Figure 4 scene's file name (bt2002_fig4a_lla.json: lla)."""
    return name.rsplit("_", 1)[1].split(".")[0]


def cone_cases():
    for name in BT2002:
        for mode in MODES.get(name, [mode_of(name)] if name.startswith("bt2002_fig4") else []):
            yield name, mode


@pytest.mark.parametrize("name,mode", list(cone_cases()))
def test_cone_equals_cli(name, mode):
    scene = cc.Scene.from_file(SCENES / name)
    cone = scene.cone(mode)
    assert cone.to_dict() == cli_json("cone", SCENES / name, "--mode", mode)
    assert cone.mode == mode
    assert ET.fromstring(cone._repr_svg_()).tag.endswith("svg")
    assert repr(cone).startswith("Cone(mode=")


def test_cone_float_and_project_routes_equal_cli():
    f = SCENES / "bt2002_section4_disk.json"
    scene = cc.Scene.from_file(f)
    assert scene.cone("na", arith="float").to_dict() == cli_json("cone", f, "--mode", "na", "--arith", "float")
    assert scene.cone("na", route="project").to_dict() == cli_json("cone", f, "--mode", "na", "--route", "project")
    assert scene.cone("na", arith="float").rays_approx.shape[1] == 3


WRENCHES = ["1,-2,0", "-1,-1,0", "0,-1,0", "0,1,0", "1/3,-7/5,1/10"]


@pytest.mark.parametrize("wrench", WRENCHES)
@pytest.mark.parametrize("arith", ["verified", "exact", "float"])
def test_stability_equals_cli(wrench, arith):
    f = SCENES / "bt2002_section7_disk.json"
    got = cc.Scene.from_file(f).stability(wrench, arith=arith)
    assert got.to_dict() == cli_json("stability", f, "--wrench", wrench, "--arith", arith)


def test_stability_margin_equals_cli():
    f = SCENES / "bt2002_section7_disk.json"
    got = cc.Scene.from_file(f).stability([1, -2, 0], margin=True)
    assert got.to_dict() == cli_json("stability", f, "--wrench", "1,-2,0", "--margin")
    assert got.verdict == "strongly_stable" and got.squared_margin > 0


def test_stability_many_equals_single_verdicts():
    # A batch reuses a system's certificate from an earlier wrench in place of its LP (mixed wrenches, each twice)
    # and builds a result's object when first read: the verdicts, witnesses and counts are the single calls'.
    scene = cc.Scene.from_file(SCENES / "bt2002_section7_disk.json")
    wrenches = WRENCHES + [[i % 7 - 3, -5 + i % 3, i % 5 - 2] for i in range(60)] * 2
    many = scene.stability_many(wrenches)
    verdicts = [s.verdict for s in many]  # read before any object is built
    for w, batch, verdict in zip(wrenches, many, verdicts):
        single = scene.stability(w).to_dict()
        b = batch.to_dict()
        assert verdict == b["verdict"] and batch == scene.stability_many([w])[0]
        # The oracle's LP count leaves out its preparation, and a single verdict walks the mode tree only until
        # a mode moves: the counts differ, the answers do not.
        for key in ("lps", "mode_tree", "modes_kinematically_feasible"):
            del single[key], b[key]
        assert b == single
    assert [s.verdict for s in scene.stability_many(WRENCHES, arith="float")] == verdicts[:len(WRENCHES)]


def test_stability_many_results_outlive_their_scene():
    # A batch's results build their objects from the batch's oracle, which they keep alive.
    import gc

    f = SCENES / "bt2002_fig10_pentagon_insert.json"
    many = cc.Scene.from_file(f).stability_many(WRENCHES)
    gc.collect()
    assert [s.to_dict() for s in many] == [s.to_dict() for s in cc.Scene.from_file(f).stability_many(WRENCHES)]


@pytest.mark.parametrize("name", ["bt2002_section7_disk.json", "bt2002_fig10_pentagon_insert.json"])
def test_region_and_finger_equal_cli(name):
    scene = cc.Scene.from_file(SCENES / name)
    region = scene.region()
    assert region.to_dict() == cli_json("stability", SCENES / name, "--region")
    assert ET.fromstring(region._repr_svg_()).tag.endswith("svg")
    finger = scene.finger()
    assert finger.to_dict() == cli_json("stability", SCENES / name, "--finger")
    assert ET.fromstring(finger._repr_svg_()).tag.endswith("svg")
    assert repr(region).startswith("Region(") and repr(finger).startswith("Finger(")


def test_insertion_equals_cli():
    f = SCENES / "bt2002_fig10_pentagon_insert.json"
    ins = cc.Scene.from_file(f).insertion()
    assert ins.to_dict() == cli_json("insert", f)
    assert 0 < ins.goal_boundary_fraction < 1
    assert ET.fromstring(ins._repr_svg_()).tag.endswith("svg")
    swept = cc.Scene.from_file(f).insertion(sweep_mu=["0.01", Fraction(1, 5), 0])
    assert swept.to_dict() == cli_json("insert", f, "--sweep-mu", "0.01,1/5,0")
    assert [mu for mu, _ in swept.sweep] == [Fraction(1, 100), Fraction(1, 5), 0]
    with pytest.raises(ValueError) as e:
        cc.Scene.from_file(f).insertion(sweep_mu=["-1"])
    assert str(e.value) == cli_error("insert", f, "--sweep-mu", "-1")


def test_scene_from_json_and_dict_equal_from_file():
    f = SCENES / "bt2002_section7_disk.json"
    a = cc.Scene.from_file(f)
    b = cc.Scene.from_json(f.read_text())
    c = cc.Scene.from_dict(a.to_dict())
    verdicts = {s.stability("1,-2,0").to_dict()["verdict"] for s in (a, b, c)}
    assert verdicts == {"strongly_stable"}
    assert repr(a) == f"Scene({str(f)!r}, 2 fixels)"


@pytest.mark.parametrize("name", BT2002)
def test_modes_equal_cli(name):
    scene = cc.Scene.from_file(SCENES / name)
    assert scene.modes().to_dict() == cli_json("modes", SCENES / name)
    assert scene.modes(kinematic=True, table2="printed").to_dict() == cli_json(
        "modes", SCENES / name, "--kinematic", "--table2", "printed")


def test_modes_certificate_checked_by_cli(tmp_path):
    f = SCENES / "bt2002_section7_disk.json"
    cert = tmp_path / "modes.json"
    m = cc.Scene.from_file(f).modes(certificate=cert)
    assert len(m.modes) == 10 and "nn" in m.modes and m.acceleration("nn") == (0, 0, 0)
    assert cli_json("check", cert)["valid"]
