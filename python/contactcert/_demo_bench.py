"""The papers' worked examples (`contactcert demo`) and speed against error on hard cases (`contactcert bench`),
in-process: the same queries (queries/demo_query.h, queries/bench_query.h) writing the same report files."""

from __future__ import annotations

import json
import os
from typing import Literal, get_args

from . import _core
from ._options import choice, seconds
from ._results import Result
from ._source import Path

Suite = Literal["all", "paper", "parallel", "boundary", "lever", "degenerate", "reduction", "large"]
SUITES: tuple[str, ...] = get_args(Suite)


class Demo(Result):
    """Each worked example's result: to_dict() is `contactcert demo --json`'s object (the wrench cones, the
    stability verdicts with their checked certificates, the region and finger pushes, the insertion sweep, Data
    Sets 1-4, Table 1, every other scene of the folder, the report's path); `text` the report the CLI prints."""

    def __init__(self, data: dict[str, object], text: str) -> None:
        super().__init__(data)
        self.text = text

    @property
    def report(self) -> str:
        """The path of the HTML report (index.html)."""
        return str(self._data["report"])

    def __repr__(self) -> str:
        return f"Demo({self._data['scenes']!r}, report {self._data['report']!r})"


class Bench(Result):
    """A bench run: to_dict() is `contactcert bench --json`'s object (the rungs, totals, a summary per family and
    rung, every instance); `text` the report the CLI prints."""

    def __init__(self, data: dict[str, object], text: str) -> None:
        super().__init__(data)
        self.text = text

    def __repr__(self) -> str:
        rungs = ", ".join(r["name"] for r in self._data["rungs"])
        return f"Bench({self._data['suite']}, {len(self._data['instances'])} instances, rungs {rungs})"


def demo(scenes: Path | None = None, out: Path = "contactcert-out", time_limit: float = 0) -> Demo:
    """`contactcert demo`: both papers' worked examples on the scenes of `scenes` (default: the bundled ones), and
    every other scene in it; the HTML report and its pictures written under `out`. The time limit, tested between
    worked examples, raises BudgetExceeded."""
    data, text = _core.demo("" if scenes is None else os.fspath(scenes), os.fspath(out),
                            seconds(time_limit))
    return Demo(json.loads(data), text)


def bench(suite: Suite = "all", quick: bool = False, rungs: str = "float,verified,adaptive,exact",
          out: Path = "contactcert-bench", time_limit: float = 0) -> Bench:
    """`contactcert bench`: the hard-case families (`suite`: all, or one) on the rungs of the arithmetic ladder
    (comma-separated, exact always added), the report files written under `out`. The time limit, tested between
    instances, raises BudgetExceeded."""
    data, text = _core.bench(choice(suite, SUITES, "--suite"), bool(quick), rungs, os.fspath(out),
                             seconds(time_limit))
    return Bench(json.loads(data), text)
