"""demo and bench from Python (issue 33 item 5): to_dict() equals the CLI's --json but for the wall times, the text
is the CLI's report, the report files are the same, and options are refused with the CLI's message."""

import re
import shutil

import pytest

import contactcert as cc
from conftest import SCENES, cli_error, cli_json, run_cli

# Keys whose values are wall times, or follow from them (a rung repeats an instance until 0.5 s are spent).
TIMED = ("seconds", "median_seconds", "repeats")


def untimed(x):
    """x without its timed members."""
    if isinstance(x, dict):
        return {k: untimed(v) for k, v in x.items() if k not in TIMED}
    if isinstance(x, list):
        return [untimed(v) for v in x]
    return x


def without_times(text):
    """A report with its numbers blanked (times, and the ratios and column widths that follow from them)."""
    return re.sub(r" +", " ", re.sub(r"\d+(\.\d+)?(e[-+]?\d+)?", "N", text))


@pytest.fixture
def small_scenes(tmp_path):
    """The section 7 disk, Data Sets 1-4, an assembly and a file that cannot be read: every part of the demo but the
    cones and the insertion sweep, which need other scenes."""
    d = tmp_path / "scenes"
    d.mkdir()
    for name in ["bt2002_section7_disk.json", "assembly_two_boxes.json"] + [f"pang1994_dataset{i}.json"
                                                                               for i in range(1, 5)]:
        shutil.copy(SCENES / name, d / name)
    (d / "zz_bad.json").write_text('{"kind": "planar"}')
    return d


def test_demo_equals_the_cli(small_scenes, tmp_path):
    out = tmp_path / "out"
    cli = cli_json("demo", "--scenes", small_scenes, "--out", out)
    cli_html = (out / "index.html").read_text()
    text = run_cli("demo", "--scenes", small_scenes, "--out", out).stdout
    d = cc.demo(scenes=small_scenes, out=out)
    assert untimed(d.to_dict()) == untimed(cli)
    assert d.text.splitlines()[:-1] == text.splitlines()[:-1]  # the last: the report's path and the run's time
    assert without_times(d.text) == without_times(text)
    assert without_times((out / "index.html").read_text()) == without_times(cli_html)
    assert d.report == str(out / "index.html")
    assert [s["verdict"] for s in d["scenes_of_folder"]] == ["strongly_stable", "not read"]
    assert "wrench_cones" not in d.to_dict() and "insertion" not in d.to_dict()
    assert all(s["certificate_valid"] for s in d["stability"])


def test_demo_lines_are_the_answer(tmp_path):
    """The bundled scenes: the text has a line per cone, verdict and Data Set, as the answer holds them."""
    d = cc.demo(out=tmp_path)
    lines = d.text.splitlines()
    assert lines[0] == f"contactcert demo on {d['scenes']}"
    assert len([x for x in lines if x.startswith("  cone ")]) == len(d["wrench_cones"]) == 5
    assert d["wrench_cones"][0]["generators"] == [["-1", "-5", "-1"], ["1", "-5", "1"], ["1", "0", "-1"]]
    assert [x["mu"] for x in d["insertion"][:4]] == ["1/100", "1/5", "2/5", "3/5"]
    assert set(d["table1"][0]) == {"nc", "mu_max", "abar", "paper", "modified", "complete"}
    assert lines[-1].startswith(f"report: {d.report} (")


def test_bench_equals_the_cli(tmp_path):
    out = tmp_path / "bench"
    args = ["--suite", "paper", "--quick", "--rungs", "float,interval", "--out", out]
    cli = cli_json("bench", *args)
    text = run_cli("bench", *args).stdout
    b = cc.bench(suite="paper", quick=True, rungs="float,interval", out=out)
    assert untimed(b.to_dict()) == untimed(cli)
    assert without_times(b.text) == without_times(text)
    assert [r["name"] for r in b["rungs"]] == ["float", "interval", "exact"]
    assert len(b["instances"]) == 12
    assert b.text.rstrip().endswith(str(out / "index.html"))


def test_options_refused_as_the_cli_refuses_them(tmp_path):
    with pytest.raises(ValueError, match=re.escape(cli_error("bench", "--rungs", "float,bogus", "--out", tmp_path))):
        cc.bench(rungs="float,bogus", out=tmp_path)
    with pytest.raises(ValueError, match="--suite"):
        cc.bench(suite="nope", out=tmp_path)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="--time-limit"):
        cc.demo(out=tmp_path, time_limit=-1)
    missing = tmp_path / "missing"
    with pytest.raises(ValueError, match=re.escape(cli_error("demo", "--scenes", missing, "--out", tmp_path))):
        cc.demo(scenes=missing, out=tmp_path)


def test_time_limit_stops_between_units(small_scenes, tmp_path):
    with pytest.raises(cc.BudgetExceeded, match="covered: 0 instances"):
        cc.bench(suite="paper", quick=True, out=tmp_path, time_limit=1e-9)
    with pytest.raises(cc.BudgetExceeded, match="demo: time limit"):
        cc.demo(scenes=small_scenes, out=tmp_path, time_limit=1e-9)
    err = run_cli("bench", "--suite", "paper", "--out", tmp_path, "--time-limit", "1e-9", expect=3).stderr
    assert "covered: 0 instances" in err
