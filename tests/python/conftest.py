"""Shared fixtures: the bundled scenes and the built CLI (CONTACTCERT_CLI, set by CTest)."""

import json
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCENES = ROOT / "scenes"
CLI = os.environ.get("CONTACTCERT_CLI", str(ROOT / "build" / "cli" / "contactcert"))


def run_cli(*args, expect=0):
    """The CLI's (exit code, stdout, stderr); asserts the exit code."""
    p = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=60)
    assert p.returncode == expect, p.stderr
    return p


def cli_json(*args, expect=0):
    """The CLI's --json object for the same query (`expect`: its exit code; check exits 2 on INVALID)."""
    return json.loads(run_cli(*args, "--json", expect=expect).stdout)


def without_seconds(d):
    """A trajectory (`simulate --json`, Simulation.to_dict()) without its timings (the run's and each step's)."""
    d = dict(d)
    d.pop("seconds")
    d["steps"] = [{k: v for k, v in s.items() if k != "seconds"} for s in d["steps"]]
    return d


def cli_error(*args):
    """The CLI's message for bad input (exit 2), without its "contactcert: " prefix."""
    err = run_cli(*args, expect=2).stderr.strip()
    assert err.startswith("contactcert: ")
    return err[len("contactcert: "):]


@pytest.fixture
def scenes():
    return SCENES
