"""The quasistatic contact problem (Pang-Trinkle-Lo 1994, SPEC section 2), its generators, certificates and
their independent check."""

import json
import os

from . import _core
from ._numbers import number_text
from ._results import CheckResult, UcpResult
from ._scene import ARITHS, Scene, choice
from ._source import FromSource

BudgetExceeded = _core.BudgetExceeded


class Certificate:
    """A certificate file's text (`contactcert check` verifies it); `path` is where it was written, if anywhere."""

    def __init__(self, text, path=""):
        self.text = text
        self.path = path

    def to_dict(self):
        return json.loads(self.text)

    @property
    def kind(self):
        return self.to_dict()["kind"]

    def save(self, path):
        with open(path, "w") as f:
            f.write(self.text)

    def check(self, problem=None):
        return check(self, problem)

    def __repr__(self):
        return f"Certificate({self.kind}{', ' + self.path if self.path else ''})"


class Ucp(FromSource):
    """A quasistatic (or plain UCP) problem."""

    _core_type = _core.Ucp

    def to_json(self):
        """The problem file's text (what `ucp --generate` writes)."""
        return self._core.text()

    def to_dict(self):
        return json.loads(self._core.text())

    def solve(self, method="complete", arith="verified", seed=1, max_nodes=200000, max_bases=100000, time_limit=0,
              certificate=None):
        """`contactcert ucp FILE`: solvable (with the pair and its physics) or jammed. An `unknown` verdict (a
        budget ran out) raises BudgetExceeded with the result as its `result`."""
        choice(method, ("paper", "modified", "complete", "enumerate"), "--method")
        choice(arith, ARITHS, "--arith")
        if max_nodes < 1 or max_bases < 1 or time_limit < 0:
            raise ValueError("--max-nodes/--max-bases/--time-limit: expected max-nodes, max-bases >= 1, time-limit >= 0")
        path = os.fspath(certificate) if certificate is not None else ""
        data, text = self._core.solve(method, arith, seed, max_nodes, max_bases, float(time_limit), path)
        result = UcpResult(json.loads(data), Certificate(text, path) if text else None)
        if result.status == "unknown":
            d = result.to_dict()
            covered = ", ".join(f"{d[k]} {k}" for k in ("nodes", "pairs", "lps") if k in d)
            e = BudgetExceeded(f"budget exceeded: {d['reason']} (covered: {covered})")
            e.result = result
            raise e
        return result

    def __repr__(self):
        return f"Ucp({self._core.name!r})"


def generate_random(nc=3, mu_max=1, abar=0, seed=1):
    """`contactcert ucp --generate random`: a random quasistatic problem of section 5."""
    return Ucp(_core.generate("random", seed, nc, number_text(mu_max, "--mu-max"), abar, 2, 6, False))


def generate_reduction(rows=2, cols=6, planted=False, seed=1):
    """`contactcert ucp --generate reduction`: Proposition 2's UCP of a random 0-1 problem."""
    return Ucp(_core.generate("reduction", seed, 3, "1", 0, rows, cols, planted))


def _certificate_text(certificate):
    """(text, name) of a Certificate, a dict, JSON text or a file path."""
    if isinstance(certificate, Certificate):
        return certificate.text, certificate.path or "<certificate>"
    if isinstance(certificate, dict):
        return json.dumps(certificate), "<certificate>"
    if isinstance(certificate, str) and certificate.lstrip().startswith("{"):
        return certificate, "<certificate>"
    path = os.fspath(certificate)
    with open(path) as f:
        return f.read(), path


def check(certificate, problem=None):
    """`contactcert check`: verifies the certificate from its embedded problem alone. With `problem` (a Scene
    or a Ucp) the certificate must also be about that problem."""
    text, name = _certificate_text(certificate)
    result = CheckResult(json.loads(_core.check(text, name)))
    if problem is None or not result.valid:
        return result
    cert = json.loads(text)
    if isinstance(problem, Scene):
        same = "scene" in cert and json.loads(cert["scene"]) == problem.to_dict()
    else:
        same = cert.get("problem") == problem.to_dict()
    if same:
        return result
    return CheckResult({"valid": False, "kind": result.kind, "reason": "the certificate is about another problem"})
