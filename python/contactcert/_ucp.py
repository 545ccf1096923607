"""The quasistatic contact problem (Pang-Trinkle-Lo 1994, SPEC section 2) and its generators (certificates and
their check: _certificate.py)."""

from __future__ import annotations

import json
import os
from typing import Any, Literal

from . import _core
from ._results import Certificate
from ._numbers import Exact, number_text
from ._options import ARITHS, LONG_MAX, UINT64_MAX, Arith, choice, seconds, whole_number
from ._results import UcpResult, budget_exceeded, ucp_covered
from ._source import FromSource, Path

BudgetExceeded = _core.BudgetExceeded


class Ucp(FromSource[_core.Ucp]):
    """A quasistatic (or plain UCP) problem."""

    _core_type = _core.Ucp

    def to_json(self) -> str:
        """The problem file's text (what `ucp --generate` writes)."""
        return self._core.text()

    def to_dict(self) -> dict[str, Any]:
        return json.loads(self._core.text())

    def solve(self, method: Literal["paper", "modified", "complete", "enumerate"] = "complete",
              arith: Arith = "verified", seed: int = 1, max_nodes: int | None = None, max_bases: int | None = None,
              time_limit: float = 0, certificate: Path | None = None, uniqueness: bool = False,
              max_modes: int | None = None, uniqueness_certificate: Path | None = None) -> UcpResult:
        """`contactcert ucp FILE`: solvable (with the pair and its physics) or jammed. An `unknown` verdict (a
        budget ran out) raises BudgetExceeded with the result as its `result`. max_nodes (default 200000) budgets
        the complete search only, max_bases (default 100000) Step 3 (not in method enumerate), as in the CLI.
        uniqueness=True is `--all`: result["uniqueness"] says whether the motion q_dot is unique (`no_motion`
        for a jammed problem; max_modes: the prefix tree's LP budget, `--max-modes`; uniqueness_certificate: the file of its
        motion_uniqueness certificate, `--uniqueness-certificate`)."""
        choice(method, ("paper", "modified", "complete", "enumerate"), "--method")
        choice(arith, ARITHS, "--arith")
        seed = whole_number(seed, 0, UINT64_MAX, "--seed")
        max_nodes = None if max_nodes is None else whole_number(max_nodes, 1, LONG_MAX, "--max-nodes")
        max_bases = None if max_bases is None else whole_number(max_bases, 1, LONG_MAX, "--max-bases")
        time_limit = seconds(time_limit)
        max_modes = None if max_modes is None else whole_number(max_modes, 1, LONG_MAX, "--max-modes")
        path = os.fspath(certificate) if certificate is not None else ""
        unique_path = os.fspath(uniqueness_certificate) if uniqueness_certificate is not None else ""
        data, text = self._core.solve(method, arith, seed, max_nodes, max_bases, time_limit, path, bool(uniqueness),
                                      max_modes, unique_path)
        result = UcpResult(json.loads(data), Certificate(text, path) if text else None)
        if result.status == "unknown":
            raise budget_exceeded(result, result["reason"], ucp_covered(result.to_dict()))
        return result

    def _problem_source(self) -> tuple[str, str]:
        """The text it was read from and its name (check's problem)."""
        return self._core.file_text, self._core.name

    def __repr__(self) -> str:
        return f"Ucp({self._core.name!r})"


def generate_random(nc: int = 3, mu_max: Exact = 1, abar: int = 0, seed: int = 1) -> Ucp:
    """`contactcert ucp --generate random`: a random quasistatic problem of section 5."""
    seed = whole_number(seed, 0, UINT64_MAX, "--seed")
    nc = whole_number(nc, 1, 1000, "--nc")
    abar = whole_number(abar, 0, 2000, "--abar")
    return Ucp(_core.generate("random", seed, nc, number_text(mu_max, "--mu-max"), abar, 2, 6, False))


def generate_reduction(rows: int = 2, cols: int = 6, planted: bool = False, seed: int = 1) -> Ucp:
    """`contactcert ucp --generate reduction`: Proposition 2's UCP of a random 0-1 problem."""
    seed = whole_number(seed, 0, UINT64_MAX, "--seed")
    rows = whole_number(rows, 1, 1000, "--rows")
    cols = whole_number(cols, 1, 60, "--cols")
    return Ucp(_core.generate("reduction", seed, 3, "1", 0, rows, cols, bool(planted)))
