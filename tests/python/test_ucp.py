"""The quasistatic problem, its generators and certificates: agreement with the CLI, in both directions."""

import json

import pytest

import contactcert as cc
from conftest import SCENES, cli_json, run_cli


def without_seconds(d):
    """The report without its timings (seconds and the phases' CPU seconds)."""
    d = dict(d)
    d.pop("seconds")
    d.pop("phases")
    return d


@pytest.mark.parametrize("k", [1, 2, 3, 4])
def test_data_sets_equal_cli(k):
    f = SCENES / f"pang1994_dataset{k}.json"
    got = cc.Ucp.from_file(f).solve()
    assert without_seconds(got.to_dict()) == without_seconds(cli_json("ucp", f))
    assert got.status in ("solvable", "jammed")
    if got.status == "solvable":
        assert sum(a * b for a, b in zip(got.x, got.y)) == 0  # exact complementarity


@pytest.mark.parametrize("method,arith", [("enumerate", "exact"), ("paper", "verified"), ("complete", "float"),
                                          ("complete", "adaptive")])
def test_methods_and_ariths_equal_cli(method, arith):
    f = SCENES / "pang1994_dataset1.json"
    got = cc.Ucp.from_file(f).solve(method=method, arith=arith)
    want = cli_json("ucp", f, "--method", method, "--arith", arith)
    assert without_seconds(got.to_dict()) == without_seconds(want)


def test_generate_random_equals_cli():
    p = cc.generate_random(nc=3, mu_max="1/2", abar=1, seed=7)
    text = run_cli("ucp", "--generate", "random", "--nc", 3, "--mu-max", "1/2", "--abar", 1, "--seed", 7).stdout
    assert p.to_dict() == json.loads(text)
    r = cc.generate_reduction(rows=2, cols=5, planted=True, seed=3)
    text = run_cli("ucp", "--generate", "reduction", "--rows", 2, "--cols", 5, "--planted", "--seed", 3).stdout
    assert r.to_dict() == json.loads(text)
    assert r.solve().status == "solvable"


def test_python_certificate_checked_by_cli(tmp_path):
    path = tmp_path / "ds4.json"
    got = cc.Ucp.from_file(SCENES / "pang1994_dataset4.json").solve(certificate=path)
    assert got.status == "jammed" and got["certificate"] == str(path)
    assert cli_json("check", path)["valid"] is True
    assert cc.check(got.certificate).to_dict() == cli_json("check", path)

    st = tmp_path / "st.json"
    s = cc.Scene.from_file(SCENES / "bt2002_section7_disk.json").stability("1,-2,0", certificate=st)
    assert cli_json("check", st) == cc.check(st).to_dict() == s.certificate.check().to_dict()
    assert cc.check(st)["valid"]


def test_cli_certificate_checked_by_python(tmp_path):
    path = tmp_path / "ds4.json"
    run_cli("ucp", SCENES / "pang1994_dataset4.json", "--certificate", path)
    ds4 = cc.Ucp.from_file(SCENES / "pang1994_dataset4.json")
    assert cc.check(path, problem=ds4).valid
    assert not cc.check(path, problem=cc.Ucp.from_file(SCENES / "pang1994_dataset1.json")).valid

    st = tmp_path / "st.json"
    f = SCENES / "bt2002_section7_disk.json"
    run_cli("stability", f, "--wrench", "-1,-1,0", "--certificate", st)
    assert cc.check(st, problem=cc.Scene.from_file(f)).valid
    # a corrupted certificate is refused, as by the CLI
    cert = json.loads(st.read_text())
    cert["wrench"] = ["1", "-2", "0"]
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(cert))
    assert cc.check(bad).to_dict() == cli_json("check", bad, expect=2)
    assert not cc.check(cert).valid


def test_budget_raises_budget_exceeded():
    f = SCENES / "pang1994_dataset4.json"
    with pytest.raises(cc.BudgetExceeded) as e:
        cc.Ucp.from_file(f).solve(max_nodes=1)
    assert e.value.result.status == "unknown"
    assert str(e.value) == "budget exceeded: node budget of 1 exhausted (covered: 1 nodes, 9 pairs, 18 lps)"
    p = run_cli("ucp", f, "--max-nodes", 1, expect=3)
    assert p.stdout == "" and p.stderr == f"contactcert: {e.value}\n"  # the limit alone, in the same words
