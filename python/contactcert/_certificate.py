"""Certificates and their independent check (`contactcert check`), shared by the scene and UCP queries: the C++
checker module (queries/check.h) decides, the CLI's `check` calls the same."""

from __future__ import annotations

import json
import os
from typing import TYPE_CHECKING, Any, Union

from . import _core
from ._results import CheckResult
from ._source import Path

if TYPE_CHECKING:
    from ._scene import Scene
    from ._ucp import Ucp


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
    """(text, name) of the problem a certificate must be about: the text a Scene or a Ucp was read from (what
    `check --problem FILE` reads)."""
    source = getattr(problem, "_problem_source", None)
    if source is None:
        raise TypeError(f"problem: expected a Scene or a Ucp, found {type(problem).__name__}")
    text, name = source()
    return text, name


def check(certificate: CertificateSource, problem: Scene | Ucp | None = None) -> CheckResult:
    """`contactcert check`: verifies the certificate from its embedded problem alone. With `problem` (a Scene
    or a Ucp) the certificate must also be about that problem, compared as `check --problem` compares them (the
    exact values, whatever their spelling). The result's `text` holds the readable lines of the evidence."""
    text, name = _certificate_text(certificate)
    problem_text, problem_name = ("", "") if problem is None else _problem_text(problem)
    data, lines = _core.check(text, name, problem_text, problem_name)
    return CheckResult(json.loads(data), lines)
