"""Python's stability queries run the CLI's (queries/stability_query.h and its siblings): on every bundled planar
scene, Scene.stability, .stability_many, .region and .finger give exactly what `contactcert stability --json`
prints for the same options, their certificates and pictures are the CLI's files, and a time limit stops both
alike (issue 30: Python's margin had run without the deadline)."""

import json
import pathlib

import pytest

import contactcert as cc
from conftest import SCENES, cli_json, run_cli

PLANAR = sorted(p.name for p in SCENES.glob("*.json") if json.loads(p.read_text()).get("kind") == "planar"
                and "bodies" not in json.loads(p.read_text()))
WRENCHES = ["0,-1,0", "1,-2,0", "-1,-1,0", "0,0,1", "1/3,-7/5,1/10"]
ARITHS = ["verified", "exact", "float", "adaptive"]
TOO_SHORT = 1e-6  # seconds: spent before the mode tree's first prefix is visited
DISK48 = pathlib.Path(__file__).resolve().parents[1] / "cli" / "budget" / "disk48.json"


def test_every_bundled_planar_scene_is_compared():
    assert len(PLANAR) == 8


@pytest.mark.parametrize("name", PLANAR)
def test_stability_equals_cli(name):
    f = SCENES / name
    scene = cc.Scene.from_file(f)
    for w in WRENCHES:
        for arith in ARITHS:
            got = scene.stability(w, arith=arith).to_dict()
            assert got == cli_json("stability", f, "--wrench", w, "--arith", arith), (w, arith)
        for arith in ("verified", "exact"):
            got = scene.stability(w, margin=True, arith=arith, time_limit=100).to_dict()
            assert got == cli_json("stability", f, "--wrench", w, "--margin", "--arith", arith,
                                   "--time-limit", "100"), (w, arith)


@pytest.mark.parametrize("name", PLANAR)
def test_stability_certificate_equals_cli(name, tmp_path):
    f = SCENES / name
    cert = tmp_path / "st.json"
    got = cc.Scene.from_file(f).stability("1,-2,0", margin=True, certificate=cert)
    python_file = cert.read_text()
    assert got.certificate.text == python_file and got.certificate.path == str(cert)
    assert got.to_dict() == cli_json("stability", f, "--wrench", "1,-2,0", "--margin", "--certificate", cert)
    assert cert.read_text() == python_file


@pytest.mark.parametrize("name", PLANAR)
def test_stability_many_equals_cli_wrenches(name, tmp_path):
    f = SCENES / name
    listed = tmp_path / "wrenches.txt"
    listed.write_text("\n".join(WRENCHES) + "\n")
    scene = cc.Scene.from_file(f)
    for arith in ARITHS:
        many = scene.stability_many(WRENCHES, arith=arith, time_limit=100)
        batch = cli_json("stability", f, "--wrenches", listed, "--arith", arith, "--time-limit", "100")
        assert [{"wrench": s.to_dict()["wrench"], "verdict": s.verdict} for s in many] == batch["wrenches"]
        assert {v: sum(s.verdict == v for s in many) for v in batch["counts"]} == batch["counts"]
        assert {s.to_dict()["arith"] for s in many} == {batch["arith"]}
        # Each verdict is `stability --wrench`'s but for the oracle's counts: its LPs leave out the preparation,
        # and the preparation walks the whole mode tree where a single verdict stops at the first mode that moves.
        for w, s in zip(WRENCHES, many):
            single = cli_json("stability", f, "--wrench", w, "--arith", arith)
            got = s.to_dict()
            for key in ("lps", "mode_tree", "modes_kinematically_feasible"):
                del single[key], got[key]
            assert got == single, (w, arith)


@pytest.mark.parametrize("name", PLANAR)
def test_region_and_finger_equal_cli(name, tmp_path):
    f = SCENES / name
    scene = cc.Scene.from_file(f)
    assert scene.region().to_dict() == cli_json("stability", f, "--region")
    svg = tmp_path / "region.svg"
    region = scene.region(wrench=[1, -2, 0], time_limit=100)
    assert region.to_dict() == cli_json("stability", f, "--region", "--wrench", "1,-2,0", "--svg", svg,
                                        "--time-limit", "100")
    assert region._repr_svg_() == svg.read_text()
    svg = tmp_path / "finger.svg"
    finger = scene.finger(time_limit=100)
    assert finger.to_dict() == cli_json("stability", f, "--finger", "--svg", svg, "--time-limit", "100")
    assert finger._repr_svg_() == svg.read_text()


def budget_message(*args):
    """The CLI's message for a run stopped by its time limit (exit 3), without its "contactcert: " prefix."""
    err = run_cli("stability", DISK48, *args, "--time-limit", str(TOO_SHORT), expect=3).stderr.strip()
    assert err.startswith("contactcert: budget exceeded: ")
    return err[len("contactcert: "):]


@pytest.mark.parametrize("query,args", [
    (lambda s: s.stability("0,-1,0", margin=True, time_limit=TOO_SHORT), ["--wrench", "0,-1,0", "--margin"]),
    (lambda s: s.stability_many(["0,-1,0"], arith="float", time_limit=TOO_SHORT),
     ["--wrenches", "WRENCHES", "--arith", "float"]),
    (lambda s: s.region(time_limit=TOO_SHORT), ["--region"]),
    (lambda s: s.finger(time_limit=TOO_SHORT), ["--finger"]),
])
def test_time_limit_stops_python_as_cli(query, args, tmp_path):
    (tmp_path / "w.txt").write_text("0,-1,0\n")
    args = [tmp_path / "w.txt" if a == "WRENCHES" else a for a in args]
    scene = cc.Scene.from_file(DISK48)
    with pytest.raises(cc.BudgetExceeded) as e:
        query(scene)
    assert str(e.value) == budget_message(*args)
