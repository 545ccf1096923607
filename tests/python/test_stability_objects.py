"""stability_many builds each result's object from its verdict in C++ (python/stability_objects.cpp), not from the
--json text: the same object as a single call's, key order and types included, on every planar paper scene."""

import json

import pytest

import contactcert as cc
from conftest import SCENES

WRENCHES = ["1,-2,0", "-1,-1,0", "0,-1,0", "0,1,0", "1/3,-7/5,1/10", "3,-5,1", "0,0,1"]
COUNTS = ("lps", "mode_tree", "modes_kinematically_feasible")  # the oracle's counts differ from a single call's


def without_counts(d):
    return {k: v for k, v in d.items() if k not in COUNTS}


@pytest.mark.parametrize("name", sorted(p.name for p in SCENES.glob("bt2002_*.json")))
@pytest.mark.parametrize("arith", ["verified", "exact", "float"])
def test_batch_objects_are_the_single_calls(name, arith):
    scene = cc.Scene.from_file(SCENES / name)
    for w, batch in zip(WRENCHES, scene.stability_many(WRENCHES, arith=arith)):
        single = scene.stability(w, arith=arith)
        b = batch.to_dict()
        assert list(b) == list(single.to_dict())  # the members in --json's order
        # json.dumps keeps the order of every nested member, and tells a str from a number
        assert json.dumps(without_counts(b)) == json.dumps(without_counts(single.to_dict()))
        assert batch.contacts == single.contacts and batch.moving_contacts == single.moving_contacts
        assert batch.acceleration == single.acceleration and batch.resting_forces == single.resting_forces
