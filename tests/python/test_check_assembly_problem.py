"""`check(certificate, problem=Assembly)` for every assembly certificate kind (issue 30): the ucp_solvable and
ucp_jammed certificates of `Assembly.ucp()` are compared with the assembly they embed, as `check --problem` does."""
from pathlib import Path

import contactcert as cc
from conftest import SCENES


def test_assembly_ucp_certificate_against_its_assembly(tmp_path: Path) -> None:
    two = cc.Assembly.from_file(SCENES / "assembly_two_boxes.json")
    other = cc.Assembly.from_file(SCENES / "assembly_corbel.json")
    result = two.ucp(certificate=tmp_path / "u.json")
    assert result.certificate is not None and result.certificate.kind == "ucp_solvable"
    ok = cc.check(result.certificate, problem=two)
    assert ok.valid and ok.to_dict()["problem"] == two.name
    wrong = cc.check(result.certificate, problem=other)
    assert not wrong.valid and "is about another problem than" in wrong.reason


def test_jammed_assembly_and_plain_ucp(tmp_path: Path) -> None:
    overhang = cc.Assembly.from_file(SCENES / "assembly_overhang.json")
    jammed = overhang.ucp(certificate=tmp_path / "j.json")
    assert jammed.certificate is not None and jammed.certificate.kind == "ucp_jammed"
    assert cc.check(jammed.certificate, problem=overhang)
    # A plain UCP certificate embeds no assembly.
    ds1 = cc.Ucp.from_file(SCENES / "pang1994_dataset1.json")
    plain = ds1.solve(certificate=tmp_path / "p.json")
    assert plain.certificate is not None
    refused = cc.check(plain.certificate, problem=overhang)
    assert not refused.valid and "it embeds no assembly" in refused.reason
    assert cc.check(plain.certificate, problem=ds1)
