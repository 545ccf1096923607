"""`assembly FILE --ucp --all` (issue 32) from Python: Assembly.ucp(uniqueness=True) gives the CLI's --json object
and writes the same motion_uniqueness certificate bytes that `check` verifies; a jammed assembly, like a jammed problem
file, answers `no_motion` (0 LPs, no certificate written); the prefix tree's budget raises BudgetExceeded and --all's
options without uniqueness=True raise ValueError, as the CLI exits 3 and 2."""

import pytest

import contactcert as cc
from conftest import SCENES, cli_json, run_cli

ROW = SCENES / "assembly_pushed_boxes.json"
NO_MOTION = {"status": "no_motion", "motions": [], "modes": [], "solution_modes": [], "unbounded": False, "lps": 0}


def test_unique_motion_of_the_row_and_its_certificate_match_the_cli(tmp_path):
    path = tmp_path / "u.json"
    d = cc.Assembly.from_file(ROW).ucp(uniqueness=True, uniqueness_certificate=path).to_dict()
    u = d["uniqueness"]
    assert u["status"] == "unique" and u["certificate"] == str(path)
    assert u["motions"] == [[q for b in d["bodies"] for q in b["q_dot"]]] == [["1", "0", "0", "1", "0", "0"]]
    written = path.read_bytes()
    assert d == cli_json("assembly", ROW, "--ucp", "--all", "--uniqueness-certificate", path)
    assert path.read_bytes() == written
    assert "motion_uniqueness certificate is VALID" in run_cli("check", path).stdout


def test_jammed_assembly_and_problem_file_have_no_motion(tmp_path):
    path = tmp_path / "u.json"
    overhang = SCENES / "assembly_overhang.json"
    d = cc.Assembly.from_file(overhang).ucp(uniqueness=True, uniqueness_certificate=path).to_dict()
    assert d["status"] == "jammed" and d["uniqueness"] == NO_MOTION
    assert not path.exists()
    assert d == cli_json("assembly", overhang, "--ucp", "--all")
    jammed = cc.Ucp.from_file(SCENES / "pang1994_dataset4.json").solve(uniqueness=True)
    assert jammed.to_dict()["uniqueness"] == NO_MOTION
    assert "uniqueness" not in cc.Assembly.from_file(overhang).ucp().to_dict()


def test_budget_and_options():
    row = cc.Assembly.from_file(ROW)
    with pytest.raises(cc.BudgetExceeded, match="--max-modes 5"):
        row.ucp(uniqueness=True, max_modes=5)
    with pytest.raises(ValueError, match="--max-modes"):
        row.ucp(max_modes=5)
    with pytest.raises(ValueError, match="--uniqueness-certificate"):
        row.ucp(uniqueness_certificate="u.json")
    with pytest.raises(ValueError, match="--max-modes"):
        row.ucp(uniqueness=True, max_modes=0)
