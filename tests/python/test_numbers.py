"""Exact numbers cross as Fractions: int, str and Fraction inputs, Fraction outputs, no floats."""

from fractions import Fraction

import numpy as np
import pytest

import contactcert as cc
from conftest import SCENES


@pytest.fixture(scope="module")
def disk():
    return cc.Scene.from_file(SCENES / "bt2002_section7_disk.json")


def test_wrench_round_trips(disk):
    for w in ([Fraction(1, 3), Fraction(-7, 5), Fraction(1, 10)], ["1/3", "-1.4", "0.1"], "2/6,-14/10,1/10"):
        assert disk.stability(w).wrench == (Fraction(1, 3), Fraction(-7, 5), Fraction(1, 10))
    assert disk.stability([1, -2, 0]).wrench == (1, -2, 0)
    assert disk.stability([np.int64(1), -2, 0]).wrench == (1, -2, 0)


def test_decimal_strings_are_exact(disk):
    assert disk.stability(["0.966", "-2", "0"]).wrench[0] == Fraction(966, 1000)


def test_outputs_are_fractions(disk):
    s = disk.stability([Fraction(1, 3), -2, 0])
    c = s.resting_forces
    assert all(isinstance(x, Fraction) for x in c)
    assert [str(x) for x in c] == s.to_dict()["witness"]["resting_forces"]  # lowest terms, as the CLI writes


def test_floats_refused(disk):
    with pytest.raises(ValueError, match="float"):
        disk.stability([0.1, -2, 0])


def test_float_views_are_numpy(disk):
    s = disk.stability([-1, -1, 0])
    assert s.verdict == "weakly_stable" and s.moving_mode == "ns"
    assert isinstance(s.acceleration_approx, np.ndarray)
    assert np.allclose(s.acceleration_approx, [float(x) for x in s.acceleration])


def test_ucp_pair_is_exact():
    r = cc.Ucp.from_file(SCENES / "pang1994_dataset1.json").solve()
    assert all(isinstance(v, Fraction) for v in r.x + r.y)
    assert r.to_dict()["x"] == [str(v) for v in r.x]
