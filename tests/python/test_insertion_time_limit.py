"""Scene.insertion honours time_limit as `insert --time-limit` does: past it, BudgetExceeded naming what was
computed (the query's deadline, checked before G_goal and between the values of sweep_mu)."""

import pytest

import contactcert as cc
from conftest import SCENES


def test_insertion_past_its_time_limit_raises_budget_exceeded() -> None:
    scene = cc.Scene.from_file(SCENES / "bt2002_fig10_pentagon_insert.json")
    mus = ",".join(f"{i}/100" for i in range(1, 201))
    with pytest.raises(cc.BudgetExceeded, match="time limit of 1e-09 s reached"):
        scene.insertion(sweep_mu=mus, time_limit=1e-9)


def test_insertion_within_its_time_limit_answers() -> None:
    scene = cc.Scene.from_file(SCENES / "bt2002_fig10_pentagon_insert.json")
    assert scene.insertion(time_limit=600).to_dict() == scene.insertion().to_dict()


def test_a_negative_time_limit_is_refused() -> None:
    scene = cc.Scene.from_file(SCENES / "bt2002_fig10_pentagon_insert.json")
    with pytest.raises(ValueError, match="time"):
        scene.insertion(time_limit=-1)
