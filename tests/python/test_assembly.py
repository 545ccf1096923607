"""Assemblies of several bodies (issue 31): Assembly.stability() and .ucp() are `contactcert assembly [--ucp]`
(to_dict() equals --json), their certificates check, their pictures are well-formed SVG, budgets raise."""

import xml.dom.minidom
from fractions import Fraction

import pytest

import contactcert as cc
from conftest import SCENES, cli_json, run_cli

STABILITY = {"assembly_two_boxes": "strongly_stable", "assembly_two_boxes_pushed": "strongly_stable",
             "assembly_overhang": "unstable", "assembly_corbel": "strongly_stable",
             "assembly_corbel_arch": "strongly_stable", "assembly_pushed_box_weak": "weakly_stable"}


@pytest.mark.parametrize("name", sorted(STABILITY))
def test_stability_equals_cli(name, tmp_path):
    f = SCENES / f"{name}.json"
    cert = tmp_path / "c.json"
    got = cc.Assembly.from_file(f).stability(certificate=cert)
    assert got.verdict == STABILITY[name]
    assert got.to_dict() == cli_json("assembly", f, "--certificate", cert)
    assert got.certificate is not None and got.certificate.check(), got.certificate
    xml.dom.minidom.parseString(got.svg())


def test_witnesses_read_as_fractions():
    weak = cc.Assembly.from_file(SCENES / "assembly_pushed_box_weak.json").stability(arith="exact")
    assert weak.moving_mode == "rr"
    assert weak.accelerations == ((Fraction(2, 5), Fraction(0), Fraction(0)),)  # it slides right: (1 - 2/10) / 2
    strong = cc.Assembly.from_file(SCENES / "assembly_two_boxes.json").stability()
    assert strong.moving_mode is None and strong.accelerations is None
    forces = strong.resting_forces
    assert forces is not None and forces[0] + forces[1] == 4  # the ground carries both boxes (mass 2 each)


@pytest.mark.parametrize("name,status", [("assembly_pushed_boxes", "solvable"), ("assembly_pushed_boxes_wall", "jammed")])
def test_ucp_equals_cli(name, status, tmp_path):
    f = SCENES / f"{name}.json"
    cert = tmp_path / "u.json"
    got = cc.Assembly.from_file(f).ucp(certificate=cert)
    assert got.status == status
    assert got.to_dict() == cli_json("assembly", "--ucp", f, "--certificate", cert)
    assert got.certificate is not None and got.certificate.check()
    if status == "solvable":
        assert got.velocities == ((1, 0, 0), (1, 0, 0))  # both boxes slide right at the finger's speed
    xml.dom.minidom.parseString(got.svg())


def test_a_budget_raises_with_the_result():
    f = SCENES / "assembly_two_boxes_pushed.json"
    with pytest.raises(cc.BudgetExceeded) as e:
        cc.Assembly.from_file(f).stability(max_nodes=2)
    assert e.value.result.to_dict()["verdict"] == "unknown"
    # the CLI reports the limit alone (no answer), in the same words
    p = run_cli("assembly", f, "--max-nodes", 2, "--json", expect=3)
    assert p.stdout == "" and p.stderr == f"contactcert: {e.value}\n"


def test_bad_input_names_the_field():
    with pytest.raises(ValueError, match=r"\$\.bodies"):
        cc.Assembly.from_file(SCENES / "bt2002_section7_disk.json")
    a = cc.Assembly.from_file(SCENES / "assembly_two_boxes.json")
    with pytest.raises(ValueError, match="--arith"):
        a.stability(arith="float")
    with pytest.raises(ValueError, match="--max-nodes"):
        a.stability(max_nodes=0)
    assert (a.bodies, a.contacts) == (2, 4)
    assert a.to_dict()["kind"] == "planar"
    xml.dom.minidom.parseString(a.svg())
