"""`contactcert check` on a certificate given as a Certificate, a dict, JSON text or a file: the C++ checker module
(queries/check.h) decides, as the CLI's `check` does (the Certificate class and the call: _results.py)."""

from __future__ import annotations

import json
import os
from typing import Any, Union

from . import _core
from ._results import Certificate, CheckResult, Problem, check_text

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


def check(certificate: CertificateSource, problem: Problem | None = None) -> CheckResult:
    """`contactcert check`: verifies the certificate from its embedded problem alone. With `problem` (a Scene,
    a Ucp or an Assembly) the certificate must also be about that problem, compared as `check --problem` compares them (the
    exact values, whatever their spelling). The result's `text` holds the readable lines of the evidence."""
    return check_text(*_certificate_text(certificate), problem)
