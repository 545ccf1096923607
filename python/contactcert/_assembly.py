"""Assemblies of several bodies (docs/formats.md section 3a): stability from rest under the bodies' loads and Pang,
Trinkle and Lo's quasistatic problem for N bodies, as `contactcert assembly FILE [--ucp]` answers them."""

from __future__ import annotations

import json
import os
from typing import TYPE_CHECKING, Any

from . import _core
from ._numbers import exact
from ._options import ARITHS, LONG_MAX, Arith, choice, seconds, whole_number
from ._file_problem import ModesProblem
from ._results import Result, Vector, budget_exceeded, ucp_covered
from ._source import Path

if TYPE_CHECKING:
    from ._results import Certificate

BudgetExceeded = _core.BudgetExceeded


class AssemblyStability(Result):
    """Strongly stable, weakly stable or unstable from rest (every body under its load), with the resting contact
    forces and a moving solution where they exist; the picture draws the witness's world forces."""

    def __init__(self, data: dict[str, Any], certificate: Certificate | None, svg: str) -> None:
        super().__init__(data, lambda: svg)
        self.certificate = certificate  # a Certificate when one was written

    @property
    def verdict(self) -> str:
        return self._data["verdict"]

    @property
    def moving_mode(self) -> str | None:
        m = self._data["witness"].get("moving")
        return m["mode"] if m else None

    @property
    def accelerations(self) -> tuple[Vector, ...] | None:
        """Each body's (a_x, a_y, alpha) in the moving solution, as Fractions, or None."""
        m = self._data["witness"].get("moving")
        return tuple(exact(b["acceleration"]) for b in m["bodies"]) if m else None

    @property
    def resting_forces(self) -> Vector | None:
        """Contact forces (c_1n..c_kn, c_1t..c_kt) holding every body at rest, or None."""
        r = self._data["witness"].get("resting")
        return exact(r["forces"]) if r else None

    def svg(self) -> str:
        """The assembly with the witness's contact forces (`contactcert assembly FILE --svg F`)."""
        return self._repr_svg_() or ""

    def __repr__(self) -> str:
        extra = f", moving mode {self.moving_mode!r}" if self.moving_mode else ""
        d = self._data
        return f"AssemblyStability({d['verdict']}, {d['bodies']} bodies, {d['contacts']} contacts{extra})"


class AssemblyUcp(Result):
    """The quasistatic problem of the bodies: solvable (each body's velocity, every contact's world force) or
    jammed."""

    def __init__(self, data: dict[str, Any], certificate: Certificate | None, svg: str) -> None:
        super().__init__(data, lambda: svg)
        self.certificate = certificate

    @property
    def status(self) -> str:
        return self._data["status"]

    @property
    def velocities(self) -> tuple[Vector, ...] | None:
        """Each body's q_dot = (v_x, v_y, omega) at the world origin, as Fractions, or None."""
        b = self._data.get("bodies")
        return tuple(exact(x["q_dot"]) for x in b) if b is not None else None

    def svg(self) -> str:
        """The assembly with the solution's contact forces (`contactcert assembly FILE --ucp --svg F`)."""
        return self._repr_svg_() or ""

    def __repr__(self) -> str:
        return f"AssemblyUcp({self.status}, {self._data['reason']!r})"


class Assembly(ModesProblem[_core.Assembly]):
    """Several movable bodies, the fixed obstacles, fixels and fingers they touch, and their contacts."""

    _core_type = _core.Assembly

    @property
    def bodies(self) -> int:
        return self._core.bodies

    @property
    def contacts(self) -> int:
        return self._core.contacts

    def stability(self, arith: Arith = "verified", time_limit: float = 0, max_nodes: int | None = None,
                  certificate: Path | None = None) -> AssemblyStability:
        """`contactcert assembly FILE`: the verdict from rest with its witness; `certificate` is the file the
        evidence is written to. A budget that runs out first (max_nodes, default 2^20 prefixes, or time_limit)
        raises BudgetExceeded with the result as its `result`."""
        from ._results import Certificate

        choice(arith, ARITHS, "--arith")
        time_limit = seconds(time_limit)
        max_nodes = None if max_nodes is None else whole_number(max_nodes, 1, LONG_MAX, "--max-nodes")
        path = os.fspath(certificate) if certificate is not None else ""
        data, text, svg = self._core.stability(arith, time_limit, max_nodes, path)
        result = AssemblyStability(json.loads(data), Certificate(text, path) if text else None, svg)
        if result.verdict == "unknown":
            raise budget_exceeded(result, result["status"], result["covered"])
        return result

    def ucp(self, arith: Arith = "verified", time_limit: float = 0, max_nodes: int | None = None,
            max_bases: int | None = None, certificate: Path | None = None, uniqueness: bool = False,
            max_modes: int | None = None, uniqueness_certificate: Path | None = None) -> AssemblyUcp:
        """`contactcert assembly FILE --ucp`: solvable or jammed; an `unknown` status (a budget ran out) raises
        BudgetExceeded with the result as its `result`. uniqueness=True is `--all`: result["uniqueness"] says
        whether the bodies' motion is unique (`no_motion` when jammed; max_modes: the prefix tree's LP budget,
        `--max-modes`, whose exhaustion raises BudgetExceeded; uniqueness_certificate: the file of its
        motion_uniqueness certificate, `--uniqueness-certificate`), as Ucp.solve."""
        from ._results import Certificate

        choice(arith, ARITHS, "--arith")
        time_limit = seconds(time_limit)
        max_nodes = None if max_nodes is None else whole_number(max_nodes, 1, LONG_MAX, "--max-nodes")
        max_bases = None if max_bases is None else whole_number(max_bases, 1, LONG_MAX, "--max-bases")
        max_modes = None if max_modes is None else whole_number(max_modes, 1, LONG_MAX, "--max-modes")
        path = os.fspath(certificate) if certificate is not None else ""
        unique_path = os.fspath(uniqueness_certificate) if uniqueness_certificate is not None else ""
        data, text, svg = self._core.ucp(arith, time_limit, max_nodes, max_bases, path, bool(uniqueness), max_modes,
                                         unique_path)
        result = AssemblyUcp(json.loads(data), Certificate(text, path) if text else None, svg)
        if result.status == "unknown":
            raise budget_exceeded(result, result["reason"], ucp_covered(result.to_dict()))
        return result

    def svg(self) -> str:
        """The assembly: bodies (numbered, com marked), obstacles, fixels, fingers and each contact's normal."""
        return self._core.svg()

    def __repr__(self) -> str:
        return f"Assembly({self.name!r}, {self.bodies} bodies, {self.contacts} contacts)"
