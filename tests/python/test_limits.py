"""A query's limit reaches Python as before: contactcert.BudgetExceeded (a RuntimeError) whose message is the CLI's
("budget exceeded: WHAT (covered: ...)"), now mapped from the query's status in one place (python/bindings.h)."""

import pytest

import contactcert as cc
from conftest import ROOT, SCENES, run_cli

DISK = SCENES / "bt2002_section7_disk.json"


def raised(call):
    with pytest.raises(cc.BudgetExceeded) as e:
        call()
    assert type(e.value).__module__ == "contactcert._core" and isinstance(e.value, RuntimeError)
    return str(e.value)


@pytest.mark.parametrize("kwargs,cli_args,message", [
    ({"max_nodes": 1}, ["--max-nodes", 1],
     "budget exceeded: mode enumeration: node budget of 1 prefixes exhausted (covered: 1 prefixes visited, "
     "0 feasible modes found)"),
    ({"unions": True, "max_modes": 10}, ["--unions", "--max-modes", 10],
     "budget exceeded: mode enumeration: output budget of 10 modes exhausted (covered: 18 prefixes visited, "
     "10 feasible modes found)"),
])
def test_modes_budget_message_as_before_and_as_the_cli(kwargs, cli_args, message):
    assert raised(lambda: cc.Scene.from_file(DISK).modes(**kwargs)) == message
    assert run_cli("modes", DISK, *cli_args, expect=3).stderr == f"contactcert: {message}\n"


def test_design_budget_message_as_before(tmp_path):
    pawl = SCENES / "design_ratchet_pawl.json"
    what = (f"design {pawl}: placement budget --max-placements reached (covered: 16 of 1313400 placements in 1 of "
            "82088 chunks; evaluated 16, accepted 0, symmetric_duplicate 0, not_weakly_stable 16, "
            "not_strongly_stable 0, cone_meets_moving_mode 0, not_insertable 0, goal_misses_wrench 0, "
            "no_push_in_goal 0, LPs 0)")
    assert raised(lambda: cc.design(cc.Scene.from_file(pawl), 200, stable_under="0,-1,0", max_placements=3,
                                    out=tmp_path / "py")) == f"budget exceeded: {what}"
    err = run_cli("design", pawl, "--candidates", 200, "--stable-under", "0,-1,0", "--max-placements", 3, "--out",
                  tmp_path / "cli", expect=3).stderr
    assert err == f"contactcert: {what}\n"  # the CLI names the command's own stop without "budget exceeded: "


TREE = ("budget exceeded: mode enumeration: time limit of 1e-09 s reached (covered: 0 prefixes visited, 0 feasible "
        "modes found)")


# A time limit of 1e-9 s has passed before the first unit of work: nothing covered, whatever the machine's load.
@pytest.mark.parametrize("call,message", [
    (lambda s: s.region(time_limit=1e-9), TREE),
    (lambda s: s.finger(time_limit=1e-9), TREE),
    (lambda s: s.stability((0, -1, 0), margin=True, time_limit=1e-9), TREE),
    (lambda s: s.stability((0, -1, 0), arith="float", time_limit=1e-9), TREE),
    (lambda s: s.stability_many([(0, -1, 0)], time_limit=1e-9), TREE),
    (lambda s: s.modes(time_limit=1e-9), TREE),
    (lambda s: s.cone("nn", arith="float", time_limit=1e-9),
     "budget exceeded: double description: time limit of 1e-09 s reached (covered: 0 of 4 rows paired)"),
    (lambda s: cc.convert(ROOT / "tests" / "cli" / "convert" / "paper_span.json", time_limit=1e-9),
     "budget exceeded: double description: time limit of 1e-09 s reached (covered: 0 of 4 rows paired)"),
], ids=["region", "finger", "margin", "float", "oracle", "modes", "cone", "convert"])
def test_time_limit_message_as_before(call, message):
    assert raised(lambda: call(cc.Scene.from_file(DISK))) == message
