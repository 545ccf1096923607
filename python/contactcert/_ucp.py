"""The quasistatic contact problem (Pang-Trinkle-Lo 1994, SPEC section 2), its generators, certificates and
their independent check."""

from __future__ import annotations

import json
import os
from typing import Any, Literal, Union

from . import _core
from ._numbers import Exact, number_text
from ._options import LONG_MAX, UINT64_MAX, seconds, whole_number
from ._results import CheckResult, UcpResult
from ._scene import ARITHS, Arith, Scene, choice
from ._source import FromSource, Path

BudgetExceeded = _core.BudgetExceeded


class Certificate:
    """A certificate file's text (`contactcert check` verifies it); `path` is where it was written, if anywhere."""

    def __init__(self, text: str, path: str = "") -> None:
        self.text = text
        self.path = path

    def to_dict(self) -> dict[str, Any]:
        return json.loads(self.text)

    @property
    def kind(self) -> str:
        return self.to_dict()["kind"]

    def save(self, path: Path) -> None:
        with open(path, "w") as f:
            f.write(self.text)

    def check(self, problem: Scene | Ucp | None = None) -> CheckResult:
        return check(self, problem)

    def __repr__(self) -> str:
        return f"Certificate({self.kind}{', ' + self.path if self.path else ''})"


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
              time_limit: float = 0, certificate: Path | None = None) -> UcpResult:
        """`contactcert ucp FILE`: solvable (with the pair and its physics) or jammed. An `unknown` verdict (a
        budget ran out) raises BudgetExceeded with the result as its `result`. max_nodes (default 200000) budgets
        the complete search only, max_bases (default 100000) Step 3 (not in method enumerate), as in the CLI."""
        choice(method, ("paper", "modified", "complete", "enumerate"), "--method")
        choice(arith, ARITHS, "--arith")
        seed = whole_number(seed, 0, UINT64_MAX, "--seed")
        max_nodes = None if max_nodes is None else whole_number(max_nodes, 1, LONG_MAX, "--max-nodes")
        max_bases = None if max_bases is None else whole_number(max_bases, 1, LONG_MAX, "--max-bases")
        time_limit = seconds(time_limit)
        path = os.fspath(certificate) if certificate is not None else ""
        data, text = self._core.solve(method, arith, seed, max_nodes, max_bases, time_limit, path)
        result = UcpResult(json.loads(data), Certificate(text, path) if text else None)
        if result.status == "unknown":
            d = result.to_dict()
            covered = ", ".join(f"{d[k]} {k}" for k in ("nodes", "pairs", "lps") if k in d)
            e = BudgetExceeded(f"budget exceeded: {d['reason']} (covered: {covered})")
            e.result = result  # type: ignore[attr-defined]  # set here, not by the extension
            raise e
        return result

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


#: What check() takes: a Certificate, its dict, its JSON text or its file's path.
CertificateSource = Union[Certificate, dict[str, Any], str, "os.PathLike[str]"]


def _certificate_text(certificate: CertificateSource) -> tuple[str, str]:
    """(text, name) of a Certificate, a dict, JSON text or a file path (read as the CLI reads it: at most 32 MiB,
    never blocking on a pipe without a writer)."""
    if isinstance(certificate, Certificate):
        return certificate.text, certificate.path or "<certificate>"
    if isinstance(certificate, dict):
        return json.dumps(certificate), "<certificate>"
    if isinstance(certificate, str) and certificate.lstrip().startswith("{"):
        return certificate, "<certificate>"
    path = os.fspath(certificate)
    return _core.read_text(path), path


def _problem_text(problem: Scene | Ucp) -> tuple[str, str]:
    """(text, name) of the problem a certificate must be about: a Scene's file text or a Ucp's."""
    if isinstance(problem, Scene):
        return problem._core.text, problem.name
    if isinstance(problem, Ucp):
        return problem._core.text(), problem._core.name
    raise TypeError(f"problem: expected a Scene or a Ucp, found {type(problem).__name__}")


def check(certificate: CertificateSource, problem: Scene | Ucp | None = None) -> CheckResult:
    """`contactcert check`: verifies the certificate from its embedded problem alone. With `problem` (a Scene
    or a Ucp) the certificate must also be about that problem, compared as `check --problem` compares them (the
    exact values, whatever their spelling)."""
    text, name = _certificate_text(certificate)
    problem_text, problem_name = ("", "") if problem is None else _problem_text(problem)
    return CheckResult(json.loads(_core.check(text, name, problem_text, problem_name)))
