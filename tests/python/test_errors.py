"""Bad input raises ValueError with the CLI's message (exit 2 there)."""

import json

import pytest

import contactcert as cc
from conftest import SCENES, cli_error


def test_malformed_scene_same_message_as_cli(tmp_path):
    scene = json.loads((SCENES / "bt2002_section7_disk.json").read_text())
    scene["workpiece"]["mass"] = -1
    bad = tmp_path / "bad_mass.json"
    bad.write_text(json.dumps(scene))
    with pytest.raises(ValueError) as e:
        cc.Scene.from_file(bad)
    assert str(e.value) == cli_error("stability", bad, "--wrench", "0,-1,0")
    assert "mass" in str(e.value)
    with pytest.raises(ValueError, match=r"<dict>: \$\.workpiece\.mass"):
        cc.Scene.from_dict(scene)


def test_not_json(tmp_path):
    bad = tmp_path / "broken.json"
    bad.write_text("{ not json")
    with pytest.raises(ValueError) as e:
        cc.Scene.from_file(bad)
    assert str(e.value) == cli_error("cone", bad, "--mode", "nn")
    with pytest.raises(ValueError):
        cc.Ucp.from_file(bad)
    with pytest.raises(ValueError):
        cc.check(bad)


def test_missing_file():
    with pytest.raises(ValueError) as e:
        cc.Scene.from_file("no/such/scene.json")
    assert str(e.value) == cli_error("cone", "no/such/scene.json", "--mode", "nn")


def test_bad_mode_and_wrench_same_message_as_cli():
    f = SCENES / "bt2002_section4_disk.json"
    with pytest.raises(ValueError) as e:
        cc.Scene.from_file(f).cone("xq")
    assert str(e.value) == cli_error("cone", f, "--mode", "xq")
    f7 = SCENES / "bt2002_section7_disk.json"
    for w in ("1,2", "1,a,0"):
        with pytest.raises(ValueError) as e:
            cc.Scene.from_file(f7).stability(w)
        assert str(e.value) == cli_error("stability", f7, "--wrench", w)
    with pytest.raises(ValueError, match=r"wrenches\[1\]"):
        cc.Scene.from_file(f7).stability_many(["0,-1,0", "1,2"])


def test_bad_options():
    f7 = cc.Scene.from_file(SCENES / "bt2002_section7_disk.json")
    with pytest.raises(ValueError, match="--arith"):
        f7.stability("0,-1,0", arith="fast")
    with pytest.raises(ValueError) as e:
        f7.stability("0,-1,0", arith="float", certificate="x.json")
    assert str(e.value) == cli_error("stability", SCENES / "bt2002_section7_disk.json", "--wrench", "0,-1,0",
                                     "--arith", "float", "--certificate", "x.json")
    with pytest.raises(ValueError) as e:
        cc.generate_random(nc=2, abar=5)  # |abar| <= 2 nc: the generator's own check, shared with the CLI
    assert str(e.value) == cli_error("ucp", "--generate", "random", "--nc", "2", "--abar", "5")
