"""Quasistatic time-stepping (issue 32): Motion.simulate agrees with `contactcert simulate --json`, yields its steps
in order, and refuses what the CLI refuses."""

from fractions import Fraction

import pytest

import contactcert as cc
from conftest import SCENES, cli_error, cli_json, run_cli, without_seconds

BOX = SCENES / "motion_pushed_box.json"
WALL = SCENES / "motion_block_wall.json"


@pytest.mark.parametrize("args,kwargs", [
    ((), {}),
    (("--steps", 2, "--dt", "1/20", "--arith", "exact"), {"steps": 2, "dt": "1/20", "arith": "exact"}),
    (("--steps", 3, "--arith", "float"), {"steps": 3, "arith": "float"}),
    (("--steps", 2, "--compare", "--uniqueness", "off"), {"steps": 2, "compare": True, "uniqueness": False}),
])
def test_run_equals_cli(args, kwargs):
    got = cc.Motion.from_file(BOX).simulate(**kwargs)
    assert without_seconds(got.to_dict()) == without_seconds(cli_json("simulate", BOX, *args))


def test_jammed_run_and_its_certificates_equal_cli(tmp_path):
    run = cc.Motion.from_file(WALL).simulate(certificates=tmp_path)
    want = cli_json("simulate", WALL, "--certificates", tmp_path)
    assert without_seconds(run.to_dict()) == without_seconds(want)
    assert run.status == "jammed" and len(run) == 4
    assert [s.verdict for s in run] == ["solvable"] * 3 + ["jammed"]
    last = list(run)[-1]
    assert last.time == 1 and len(last.made) == 2  # both front corners on the wall
    assert "ucp_jammed" in run_cli("check", tmp_path / "step-3.json", "--json").stdout


def test_steps_are_yielded_in_order_with_exact_values():
    steps = list(cc.Motion.from_file(BOX).simulate(steps=3))
    assert [s.index for s in steps] == [0, 1, 2]
    assert steps[0].q_dot == (0, Fraction(4, 3), Fraction(-2, 3))  # tipping about the front corner (2, 0)
    assert steps[1].broken == ["body vertex 0 on floor edge 2"]
    assert steps[0].unique is True
    assert steps[2].time == Fraction(1, 5)


def test_picture_is_an_animated_svg(tmp_path):
    run = cc.Motion.from_file(BOX).simulate(steps=2, svg=tmp_path / "box.svg")
    assert run.svg().startswith("<svg") and "<animate" in run.svg()
    assert (tmp_path / "box.svg").read_text() == run.svg()


@pytest.mark.parametrize("kwargs,option", [
    ({"steps": 0}, "--steps"), ({"dt": 0}, "--dt"), ({"dt": 0.1}, "--dt"), ({"arith": "fast"}, "--arith"),
    ({"arith": "float", "certificates": "x"}, "--certificates"), ({"max_modes": 0}, "--max-modes"),
])
def test_bad_options_name_the_option(kwargs, option):
    with pytest.raises(ValueError, match=option):
        cc.Motion.from_file(BOX).simulate(**kwargs)


def test_bad_scene_names_the_field():
    with pytest.raises(ValueError, match=r"\$\.motion") as e:
        cc.Motion.from_file(SCENES / "bt2002_fig4a_lla.json")
    assert str(e.value) == cli_error("simulate", SCENES / "bt2002_fig4a_lla.json")


def test_time_limit_raises_with_the_steps_done():
    with pytest.raises(cc.BudgetExceeded, match="covered: 0 steps") as e:
        cc.Motion.from_file(BOX).simulate(steps=1000, time_limit=1e-9)
    assert e.value.result.status == "unknown" and len(e.value.result) == 0


def test_json_poses_are_exact_and_keep_the_pivot_fixed():
    run = cc.Motion.from_file(BOX).simulate(steps=4, uniqueness=False)
    for s in run:
        pose = s["pose_after"]
        (c, ms), (s_, c2) = (tuple(map(Fraction, row)) for row in pose["R"])
        tx, ty = map(Fraction, pose["t"])
        assert c == c2 and ms == -s_ and c * c + s_ * s_ == 1  # a rotation, exactly
        assert (2 * c + tx, 2 * s_ + ty) == (2, 0)  # the front corner (2, 0) stays exactly where it is
        assert abs(pose["angle_approx"]) > 0


def test_push_at_height_one_reports_both_motions():
    scene = cc.Motion.from_file(BOX).to_dict()
    scene["fingers"][0]["tip"] = [0, 1]
    step = next(iter(cc.Motion.from_dict(scene).simulate(steps=1)))
    assert step.unique is False
    motions = {tuple(map(Fraction, m)) for m in step["uniqueness"]["motions"]}
    assert {(1, 0, 0), (0, 2, -1)} <= motions  # sliding, and tipping about the front corner


def test_compare_reports_where_float_differs():
    d = cc.Motion.from_file(BOX).simulate(compare=True, uniqueness=False).to_dict()
    assert d["float"]["status"] == "completed"
    for x in d["divergences"]:
        assert x["kind"] == "penetration" and x["pose_distance"] < 1e-9  # rounding dips into the floor, no more


def test_generator_yields_the_cli_steps_one_at_a_time(tmp_path):
    got = [s.to_dict() for s in cc.Motion.from_file(WALL).steps(certificates=tmp_path)]
    want = without_seconds(cli_json("simulate", WALL, "--certificates", tmp_path))["steps"]
    assert [{k: v for k, v in s.items() if k != "seconds"} for s in got] == want
    # Lazy: the first step of a million-step run comes at once, and nothing more is made.
    gen = cc.Motion.from_file(BOX).steps(steps=1000000, dt="1/1000000", uniqueness=False)
    assert next(gen).index == 0 and next(gen).index == 1
    with pytest.raises(ValueError, match="--steps"):
        cc.Motion.from_file(BOX).steps(steps=0)  # checked at the call, not at the first step
