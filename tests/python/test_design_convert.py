"""design and convert in-process: to_dict() is the CLI's --json for the same query; limits and bad input as the CLI."""

import pytest

import contactcert as cc
from conftest import ROOT, SCENES, cli_error, cli_json

PENTAGON = SCENES / "bt2002_fig10_pentagon_insert.json"
DISK = SCENES / "bt2002_section7_disk.json"
CONES = ROOT / "tests" / "cli" / "convert"


@pytest.mark.parametrize("scene, args, kwargs", [
    (PENTAGON, ["--candidates", "10", "--stable-under", "0,-1,0", "--goal-wrench", "0,-1,0", "--top", "1"],
     dict(candidates=10, stable_under=[(0, -1, 0)], goal_wrench=(0, -1, 0), top=1)),
    (PENTAGON, ["--candidates", "10", "--goal-push", "--push-points", "12", "--top", "1"],
     dict(candidates=10, goal_push=True, push_points=12, top=1)),
    (DISK, ["--fixels", "2", "--candidates", "12", "--stable-under", "cone:0,-1,0;1,-4,0", "--top", "2"],
     dict(candidates=12, fixels=2, stable_under=[(0, -1, 0), (1, -4, 0)], cone=True, top=2)),
])
def test_design_equals_the_cli(tmp_path, scene, args, kwargs):
    out = tmp_path / "out"
    want = cli_json("design", scene, *args, "--out", out)
    got = cc.design(cc.Scene.from_file(scene), out=out, **kwargs)
    assert got.to_dict() == want
    assert got.figures == tuple(cc.Design(want).figures)
    assert (out / "design.svg").read_text().startswith("<svg")


def test_design_budget_and_bad_input(tmp_path):
    scene = cc.Scene.from_file(PENTAGON)
    with pytest.raises(cc.BudgetExceeded, match="covered: 3 of 120 placements"):
        cc.design(scene, 10, stable_under="0,-1,0", max_placements=3, chunk_size=1, out=tmp_path)
    want = cli_error("design", PENTAGON, "--candidates", "10", "--out", tmp_path)
    with pytest.raises(ValueError) as e:
        cc.design(scene, 10, out=tmp_path)
    assert str(e.value) == want
    with pytest.raises(ValueError, match="--fixels"):
        cc.design(scene, 10, fixels=4, insertable=True, out=tmp_path)


@pytest.mark.parametrize("name", ["paper_span", "paper_open_face", "punctured_octant"])
@pytest.mark.parametrize("arith", ["exact", "float"])
def test_convert_equals_the_cli(name, arith):
    path = CONES / f"{name}.json"
    assert cc.convert(path, arith).to_dict() == cli_json("convert", path, "--arith", arith)


def test_convert_bad_input_names_the_field():
    path = CONES / "bad_ragged.json"
    with pytest.raises(ValueError) as e:
        cc.convert(path)
    assert str(e.value) == cli_error("convert", path)
