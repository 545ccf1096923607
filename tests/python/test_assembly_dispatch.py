"""Assemblies through the other entry points (issue 31): `contactcert stability` and `ucp` on an assembly file answer
as `assembly [--ucp]` does, so Assembly.stability() / .ucp() equal them too (to_dict() == --json); Python keeps
Assembly as its own class (Scene.stability takes a wrench, an assembly's loads are in its file: the CLI's wrench
options are refused on an assembly for the same reason); check(cert, problem=Assembly) compares the certificate
with the assembly as `check --problem FILE` does."""

import pytest

import contactcert as cc
from conftest import SCENES, cli_json


@pytest.mark.parametrize("name", ["assembly_two_boxes", "assembly_overhang", "assembly_pushed_box_weak"])
def test_stability_command_equals_assembly(name):
    f = SCENES / f"{name}.json"
    assert cc.Assembly.from_file(f).stability().to_dict() == cli_json("stability", f)


def test_ucp_command_equals_assembly_ucp():
    f = SCENES / "assembly_pushed_boxes_wall.json"
    assert cc.Assembly.from_file(f).ucp().to_dict() == cli_json("ucp", f)


def test_check_against_an_assembly(tmp_path):
    two = cc.Assembly.from_file(SCENES / "assembly_two_boxes.json")
    other = cc.Assembly.from_file(SCENES / "assembly_overhang.json")
    result = two.stability(certificate=tmp_path / "c.json")
    assert result.certificate is not None
    ok = cc.check(result.certificate, problem=two)
    assert ok.valid and ok.kind == "assembly_stability"
    assert ok.to_dict()["problem"] == two.name
    wrong = cc.check(tmp_path / "c.json", problem=other)
    assert not wrong.valid and "another problem" in wrong.reason
    assert result.certificate.check(problem=two)


def test_check_refuses_a_non_problem():
    with pytest.raises(TypeError, match="a Scene, a Ucp or an Assembly"):
        cc.check({"kind": "modes"}, problem=42)  # type: ignore[arg-type]


def test_modes_of_an_assembly_equal_cli(tmp_path):
    f = SCENES / "assembly_two_boxes.json"
    a = cc.Assembly.from_file(f)
    got = a.modes(certificate=tmp_path / "m.json")
    assert got.to_dict() == cli_json("modes", f, "--certificate", tmp_path / "m.json")
    assert len(got.modes) == 100 and got.counts["mixed"] == 94
    assert len(got.acceleration("ssnn")) == 6  # vdot of both bodies
    assert got.certificate is not None and got.certificate.kind == "assembly_modes"
    assert cc.check(got.certificate, problem=a)
    with pytest.raises(cc.BudgetExceeded):
        a.modes(max_nodes=5)
