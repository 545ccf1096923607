"""Scene.cone, Scene.modes and Scene.insertion run the CLI's queries (queries/cone_query.h, modes_query.h,
insert_query.h): on every bundled planar scene, to_dict() equals `--json` of `cone` (every feasible mode the scene
lists, an empty one, and each route, arithmetic and Table 2 reading), `modes` (each option) and `insert`, the
certificates written are the same files, and budgets and bad input end the same way."""

import json
import subprocess

import pytest

import contactcert as cc
from conftest import CLI, SCENES, cli_error, cli_json, run_cli

PLANAR = sorted(p.name for p in SCENES.glob("*.json") if json.loads(p.read_text())["kind"] == "planar"
                and "bodies" not in json.loads(p.read_text()))


def feasible_modes(name):
    return [m["mode"] for m in cli_json("modes", SCENES / name, "--kinematic")["modes"]]


def rolling_mode(name):
    """Every touching fixel rolling, every gap fixel approaching (a mode whose cone is empty on some scenes)."""
    k = cli_json("modes", SCENES / name)["fixels"]
    report = run_cli("cone", SCENES / name, "--mode", "s" * k).stdout
    return "".join("n" if "touching at" in line else "a" for line in report.splitlines() if "  fixel " in line)


@pytest.mark.parametrize("name", PLANAR)
def test_cone_equals_cli_on_every_listed_mode(name):
    f = SCENES / name
    scene = cc.Scene.from_file(f)
    modes = feasible_modes(name)
    for mode in modes:
        assert scene.cone(mode).to_dict() == cli_json("cone", f, "--mode", mode), mode
    for mode in modes[:3]:
        for options in (dict(route="project"), dict(arith="float"), dict(arith="exact", table2="printed"),
                        dict(arith="adaptive", time_limit=100)):
            args = [a for k, v in options.items() for a in (f"--{k.replace('_', '-')}", v)]
            assert scene.cone(mode, **options).to_dict() == cli_json("cone", f, "--mode", mode, *args), (mode, args)


@pytest.mark.parametrize("name", PLANAR)
def test_cone_certificates_equal_cli(name, tmp_path):
    f = SCENES / name
    path = tmp_path / "cone.json"
    for mode in (feasible_modes(name)[-1], rolling_mode(name)):
        want = cli_json("cone", f, "--mode", mode, "--certificate", path)
        EMPTY.add(want["empty"])
        written = path.read_text()
        path.unlink()
        cone = cc.Scene.from_file(f).cone(mode, certificate=path)
        assert cone.to_dict() == want, mode
        assert path.read_text() == written == cone.certificate.text
        assert cone.certificate.check()


EMPTY = set()


def test_cone_certificates_cover_both_kinds():
    """After the test above: a Motzkin vector (empty cone) and a witness (non-empty) were both compared."""
    assert EMPTY == {True, False}


@pytest.mark.parametrize("name", PLANAR)
def test_modes_equal_cli(name, tmp_path):
    f = SCENES / name
    scene = cc.Scene.from_file(f)
    for options, args in ((dict(), []), (dict(kinematic=True), ["--kinematic"]),
                          (dict(table2="printed"), ["--table2", "printed"]), (dict(unions=True), ["--unions"]),
                          (dict(unions=True, table2="printed", time_limit=100),
                           ["--unions", "--table2", "printed", "--time-limit", "100"]),
                          (dict(arith="exact", max_nodes=10**6, max_modes=1000),
                           ["--arith", "exact", "--max-nodes", "1000000", "--max-modes", "1000"])):
        assert scene.modes(**options).to_dict() == cli_json("modes", f, *args), args
    path = tmp_path / "modes.json"
    want = cli_json("modes", f, "--certificate", path)
    written = path.read_text()
    path.unlink()
    modes = scene.modes(certificate=path)
    assert modes.to_dict() == want
    assert path.read_text() == written == modes.certificate.text
    assert scene.modes().certificate is None


@pytest.mark.parametrize("option,value", [("max_nodes", 2), ("max_modes", 1)])
def test_modes_budgets_end_as_in_the_cli(option, value):
    f = SCENES / "bt2002_fig4a_lla.json"
    err = run_cli("modes", f, f"--{option.replace('_', '-')}", value, expect=3).stderr.strip()
    with pytest.raises(cc.BudgetExceeded) as e:
        cc.Scene.from_file(f).modes(**{option: value})
    assert "contactcert: " + str(e.value) == err


@pytest.mark.parametrize("name", PLANAR)
def test_insertion_equals_cli(name):
    f = SCENES / name
    scene = cc.Scene.from_file(f)
    if subprocess.run([CLI, "insert", str(f)], capture_output=True, timeout=60).returncode == 2:  # not a goal scene
        with pytest.raises(ValueError) as e:
            scene.insertion()
        assert str(e.value) == cli_error("insert", f)
        return
    assert scene.insertion().to_dict() == cli_json("insert", f)
    assert scene.insertion(["1/100", "1/5"], arith="exact").to_dict() == cli_json(
        "insert", f, "--sweep-mu", "0.01,0.2", "--arith", "exact")


def test_bad_options_are_refused_as_in_the_cli():
    f = SCENES / "bt2002_fig4a_lla.json"
    scene = cc.Scene.from_file(f)
    for call, args in ((lambda: scene.cone("lla", certificate="x.json", arith="float"),
                        ["cone", f, "--mode", "lla", "--certificate", "x.json", "--arith", "float"]),
                       (lambda: scene.cone("llx"), ["cone", f, "--mode", "llx"]),
                       (lambda: scene.modes(arith="float"), ["modes", f, "--arith", "float"]),
                       (lambda: scene.insertion(arith="float"), ["insert", f, "--arith", "float"]),
                       (lambda: scene.insertion("-1"), ["insert", f, "--sweep-mu", "-1"])):
        with pytest.raises(ValueError) as e:
            call()
        assert str(e.value) == cli_error(*args), args
    with pytest.raises(ValueError, match="--max-nodes"):
        scene.modes(max_nodes=0)
    with pytest.raises(ValueError, match="--time-limit"):
        scene.cone("lla", time_limit=-1)
