"""`ucp --all` (issue 32) from Python: Ucp.solve(uniqueness=True) gives the CLI's --json object (timings aside),
writes the same motion_uniqueness certificate bytes that `check` verifies, raises BudgetExceeded on the prefix
tree's budget and ValueError on its options without uniqueness=True, as the CLI exits 3 and 2."""

import json
import subprocess

import pytest

import contactcert as cc
from conftest import CLI, ROOT

DS2 = ROOT / "scenes" / "pang1994_dataset2.json"
TIMINGS = ("seconds", "phases")


def cli_json(*args):
    p = subprocess.run([CLI, *map(str, args), "--json"], capture_output=True, text=True, timeout=60)
    assert p.returncode == 0, p.stderr
    return {k: v for k, v in json.loads(p.stdout).items() if k not in TIMINGS}


def test_unique_motion_and_its_certificate_match_the_cli(tmp_path):
    path = tmp_path / "u.json"
    r = cc.Ucp.from_file(DS2).solve(uniqueness=True, uniqueness_certificate=path)
    d = {k: v for k, v in r.to_dict().items() if k not in TIMINGS}
    assert d["uniqueness"]["status"] == "unique"
    assert d["uniqueness"]["motions"] == [d["physical"]["q_dot"]]
    assert d["uniqueness"]["certificate"] == str(path)
    written = path.read_bytes()
    assert d == cli_json("ucp", DS2, "--all", "--uniqueness-certificate", path)
    assert path.read_bytes() == written
    check = subprocess.run([CLI, "check", path], capture_output=True, text=True, timeout=60)
    assert check.returncode == 0 and "VALID" in check.stdout, check.stdout


def test_without_uniqueness_the_answer_has_none():
    assert "uniqueness" not in cc.Ucp.from_file(DS2).solve().to_dict()


def test_budget_and_options():
    problem = cc.Ucp.from_file(DS2)
    with pytest.raises(cc.BudgetExceeded):
        problem.solve(uniqueness=True, max_modes=2)
    with pytest.raises(ValueError, match="--max-modes"):
        problem.solve(max_modes=2)
    with pytest.raises(ValueError, match="--all"):
        problem.solve(uniqueness=True, arith="float")
