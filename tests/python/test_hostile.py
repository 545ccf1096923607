"""Hostile arguments and files (issue 29): the CLI's option rules, its bounded reader and its check --problem."""

import json
import os
import subprocess
import threading

import pytest

import contactcert as cc
from conftest import CLI, SCENES, cli_error

DS1 = SCENES / "pang1994_dataset1.json"
DISK = SCENES / "bt2002_section7_disk.json"


def within(seconds, f, *args, **kwargs):
    """f(*args, **kwargs) run in a thread that must end within `seconds` (a hang fails, not blocks, the test)."""
    out = {}

    def run():
        try:
            out["value"] = f(*args, **kwargs)
        except BaseException as e:  # noqa: BLE001 - handed to the test
            out["error"] = e

    t = threading.Thread(target=run, daemon=True)
    t.start()
    t.join(seconds)
    assert not t.is_alive(), f"{f.__name__} did not end within {seconds} s"
    if "error" in out:
        raise out["error"]
    return out["value"]


@pytest.mark.parametrize("limit", [1e10, float("nan"), -1, float("inf"), -0.5, 10**400, True, "5", None])
def test_time_limit_refused_as_by_cli(limit):
    ucp = cc.Ucp.from_file(DS1)
    with pytest.raises(ValueError, match=r"^--time-limit: expected a number of seconds from 0 to 1e7, found "):
        ucp.solve(time_limit=limit)


def test_time_limit_in_range_solves():
    ucp = cc.Ucp.from_file(DS1)
    assert ucp.solve(time_limit=1e7).status == "solvable"  # the largest limit: no overflow, no instant timeout
    assert ucp.solve(time_limit=30).status == "solvable"


@pytest.mark.parametrize("option,value", [("max_nodes", 0), ("max_nodes", 2**63), ("max_bases", -1),
                                          ("max_bases", 1.5), ("max_nodes", "16"), ("max_nodes", True),
                                          ("seed", -1), ("seed", 2**64), ("seed", 1.0)])
def test_integer_budgets_refused(option, value):
    flag = "--" + option.replace("_", "-")
    with pytest.raises(ValueError, match="^" + flag + ": expected a decimal integer from "):
        cc.Ucp.from_file(DS1).solve(**{option: value})


def test_integer_bounds_accepted():
    assert cc.Ucp.from_file(DS1).solve(seed=2**64 - 1, max_nodes=2**63 - 1, max_bases=2**63 - 1).status == "solvable"


@pytest.mark.parametrize("kwargs,flag", [({"nc": 0}, "--nc"), ({"nc": 1001}, "--nc"), ({"abar": -1}, "--abar"),
                                         ({"abar": 2.0}, "--abar"), ({"seed": 2**64}, "--seed")])
def test_generate_random_options_refused(kwargs, flag):
    with pytest.raises(ValueError, match="^" + flag + ": expected a decimal integer from "):
        cc.generate_random(**kwargs)


@pytest.mark.parametrize("kwargs,flag", [({"rows": 0}, "--rows"), ({"cols": 61}, "--cols"),
                                         ({"rows": 2**70}, "--rows")])
def test_generate_reduction_options_refused(kwargs, flag):
    with pytest.raises(ValueError, match="^" + flag + ": expected a decimal integer from "):
        cc.generate_reduction(**kwargs)


def test_check_dev_zero_is_bounded():
    with pytest.raises(ValueError, match=r"^/dev/zero: larger than the input limit of 32 MiB$"):
        within(20, cc.check, "/dev/zero")
    with pytest.raises(ValueError, match="larger than the input limit"):
        within(20, cc.Scene.from_file, "/dev/zero")


def test_fifo_without_writer_does_not_block(tmp_path):
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    for load in (cc.check, cc.Scene.from_file, cc.Ucp.from_file):
        with pytest.raises(ValueError, match=r"fifo: \$: malformed JSON: no JSON text"):
            within(20, load, fifo)
    assert str(pytest.raises(ValueError, within, 20, cc.check, fifo).value) == cli_error("check", fifo)


def test_deep_nesting_refused(tmp_path):
    deep = tmp_path / "deep.json"
    deep.write_text("[" * 100000 + "]" * 100000)
    for load in (cc.check, cc.Scene.from_file, cc.Ucp.from_file):
        with pytest.raises(ValueError, match=r"deep\.json: \$(\[0\]){64}: nesting deeper than 64 levels"):
            load(deep)
    assert str(pytest.raises(ValueError, cc.check, deep).value) == cli_error("check", deep)


def scene_with_mu(mu, reorder=False):
    scene = {"kind": "planar",
             "workpiece": {"shape": {"type": "disk", "center": [0, 0], "radius": 1}},
             "fixels": [{"position": [0, -1]}, {"position": [1, 0]}, {"position": [-1, 0]}],
             "mu_s": mu}
    if reorder:
        scene = {k: scene[k] for k in reversed(list(scene))}
    return scene


def test_check_problem_compares_exact_values(tmp_path):
    cert = tmp_path / "st.json"
    cc.Scene.from_dict(scene_with_mu("1.2")).stability("0,-1,0", certificate=cert)
    near = cc.Scene.from_dict(scene_with_mu("1.2000000000000000001"))
    respelt = cc.Scene.from_dict(scene_with_mu("6/5", reorder=True))
    assert not cc.check(cert, problem=near).valid
    assert "about another problem" in cc.check(cert, problem=near).reason
    assert cc.check(cert, problem=respelt).valid
    # the CLI says the same about the same files
    for problem, want in ((near, False), (respelt, True)):
        path = tmp_path / "problem.json"
        path.write_text(problem._core.text)
        got = subprocess.run([CLI, "check", str(cert), "--problem", str(path), "--json"], capture_output=True,
                             text=True, timeout=60)
        assert json.loads(got.stdout)["valid"] is want
        assert cc.check(cert, problem=cc.Scene.from_file(path)).to_dict() == json.loads(got.stdout)


def test_check_problem_ucp_respelt(tmp_path):
    cert = tmp_path / "ds1.json"
    cc.Ucp.from_file(DS1).solve(certificate=cert)
    data = json.loads(DS1.read_text())
    data["source"] = "respelt"
    respelt = cc.Ucp.from_dict({k: data[k] for k in reversed(list(data))})
    assert cc.check(cert, problem=respelt).valid
    with pytest.raises(TypeError, match="expected a Scene, a Ucp or an Assembly"):
        cc.check(cert, problem=str(DS1))


def cli_check(path):
    """The CLI's answer on a certificate file: ("json", its --json object) or ("error", its message)."""
    p = subprocess.run([CLI, "check", str(path), "--json"], capture_output=True, text=True, timeout=60)
    assert p.returncode in (0, 2), p.stderr
    if p.stdout.strip():
        return "json", json.loads(p.stdout)
    assert p.stderr.startswith("contactcert: ")
    return "error", p.stderr.strip()[len("contactcert: "):]


def python_check(path):
    try:
        return "json", cc.check(path).to_dict()
    except ValueError as e:
        return "error", str(e)


def forgeries(tmp_path):
    """Genuine certificates of every kind the CLI and Python write, and forged copies of each."""
    made = []
    runs = {"jam.json": ["ucp", SCENES / "pang1994_dataset4.json"], "sol.json": ["ucp", DS1],
            "st.json": ["stability", DISK, "--wrench", "0,-1,0"], "modes.json": ["modes", DISK],
            "cone.json": ["cone", DISK, "--mode", "ss"]}
    for name, args in runs.items():
        path = tmp_path / name
        subprocess.run([CLI, *map(str, args), "--certificate", str(path)], capture_output=True, timeout=120, check=True)
        made.append(path)
        text = path.read_text()
        edits = [("problem_sha256\":\"", "problem_sha256\":\"0"), ("\"kind\":\"", "\"kind\":\"x"),
                 ("\"format\":", "\"format\":1"), ("\"1\"", "\"2\""), ("\"0\"", "\"-1\""), ("}", ",\"extra\":1}"),
                 ("[", "[["), ("\"", "'")]
        for k, (old, new) in enumerate(edits):
            if old in text:
                forged = tmp_path / f"{path.stem}_forged{k}.json"
                forged.write_text(text.replace(old, new, 1))
                made.append(forged)
    return made


def test_python_and_cli_check_agree_on_forgeries(tmp_path):
    paths = forgeries(tmp_path)
    assert len(paths) >= 30
    for path in paths:
        assert python_check(path) == cli_check(path), path.name


def test_ignored_options_refused_as_by_cli():
    disk = cc.Scene.from_file(DISK)
    with pytest.raises(ValueError) as e:
        disk.stability("0,-1,0", margin=True, arith="float")
    assert str(e.value) == cli_error("stability", DISK, "--wrench", "0,-1,0", "--margin", "--arith", "float")


def test_insertion_error_names_the_file():
    one = SCENES.parent / "tests" / "cli" / "hostile" / "one_fixel.json"
    with pytest.raises(ValueError) as e:
        cc.Scene.from_file(one).insertion()
    assert str(e.value) == cli_error("insert", one)


@pytest.mark.parametrize("method,kwargs,flag", [("paper", {"max_nodes": 5}, "--max-nodes"),
                                                ("enumerate", {"max_nodes": 5}, "--max-nodes"),
                                                ("enumerate", {"max_bases": 5}, "--max-bases")])
def test_ignored_budgets_refused_as_by_cli(method, kwargs, flag):
    with pytest.raises(ValueError) as e:
        cc.Ucp.from_file(DS1).solve(method=method, **kwargs)
    assert str(e.value) == cli_error("ucp", DS1, "--method", method, flag, 5)
