"""Several bodies in a motion scene (issue 32): Motion.simulate of the bundled four-box row agrees with `contactcert
simulate --json`, its steps give each body's q_dot, and every step's certificate (the assembly's) checks."""

from fractions import Fraction

import pytest

import contactcert as cc
from conftest import SCENES, cli_json, run_cli, without_seconds

ROW = SCENES / "motion_pushed_row.json"


@pytest.mark.parametrize("args,kwargs", [
    (("--uniqueness", "off"), {"uniqueness": False}),
    (("--steps", 3, "--compare", "--uniqueness", "off"), {"steps": 3, "compare": True, "uniqueness": False}),
    (("--steps", 3, "--arith", "float"), {"steps": 3, "arith": "float"}),
])
def test_row_run_equals_cli(args, kwargs):
    got = cc.Motion.from_file(ROW).simulate(**kwargs)
    assert without_seconds(got.to_dict()) == without_seconds(cli_json("simulate", ROW, *args))


def test_row_steps_give_each_body_and_certificates_check(tmp_path):
    run = cc.Motion.from_file(ROW).simulate(steps=3, uniqueness=False, certificates=tmp_path)
    steps = list(run)
    # Box 0 alone moves until it reaches box 1 at t = 1/2 (the step from 1/3 is cut there); then boxes 0 and 1.
    assert [s.time for s in steps] == [0, Fraction(1, 3), Fraction(1, 2)]
    assert steps[0].q_dots == {"box 0": (1, 0, 0), "box 1": (0, 0, 0), "box 2": (0, 0, 0), "box 3": (0, 0, 0)}
    assert steps[2].q_dots["box 1"] == (1, 0, 0)
    assert steps[2].made == ["box 1 vertex 0 on box 0 edge 1"]
    with pytest.raises(ValueError, match="q_dots"):
        steps[0].q_dot
    for k in range(3):
        assert "VALID" in run_cli("check", tmp_path / f"step-{k}.json").stdout


def test_row_picture_shows_every_body(tmp_path):
    run = cc.Motion.from_file(ROW).simulate(steps=2, uniqueness=False, svg=tmp_path / "row.svg")
    first_frame = run.svg().split("<animate")[1].split("</g>")[0]
    assert first_frame.count('fill="lightsteelblue"') == 4
