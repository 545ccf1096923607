"""A body in space (docs/formats.md section 3b): its contact modes from rest, as `contactcert modes FILE` lists them
for a spatial scene (s separating, f sticking, and the sliding letters of each contact's friction pyramid)."""

from __future__ import annotations

import json
import os
from typing import Any

from . import _core
from ._options import ARITHS, LONG_MAX, Arith, choice, seconds, whole_number
from ._results import Modes
from ._source import FromSource, Path


class SpatialScene(FromSource[_core.SpatialScene]):
    """One rigid body in space (mass, inertia, com) and its point contacts with friction pyramids."""

    _core_type = _core.SpatialScene

    @property
    def name(self) -> str:
        return self._core.name

    @property
    def contacts(self) -> int:
        return self._core.contacts

    def to_dict(self) -> dict[str, Any]:
        return json.loads(self._core.text)

    def _problem_source(self) -> tuple[str, str]:
        """What `check(certificate, problem=scene)` compares a spatial_modes certificate with."""
        return self._core.text, self.name

    def modes(self, arith: Arith = "verified", time_limit: float = 0, max_nodes: int | None = None,
              max_modes: int | None = None, certificate: Path | None = None) -> Modes:
        """`contactcert modes FILE` on a spatial scene: every kinematically feasible contact mode from rest, each
        with the body acceleration (a of the com, alpha) that realises it; `certificate` is the file its
        completeness proof (spatial_modes) is written to. Past a budget, BudgetExceeded."""
        from ._results import Certificate

        choice(arith, ARITHS, "--arith")
        time_limit = seconds(time_limit)
        max_nodes = None if max_nodes is None else whole_number(max_nodes, 1, LONG_MAX, "--max-nodes")
        max_modes = None if max_modes is None else whole_number(max_modes, 1, LONG_MAX, "--max-modes")
        path = os.fspath(certificate) if certificate is not None else ""
        data, text = self._core.modes(arith, time_limit, max_nodes, max_modes, path)
        return Modes(json.loads(data), certificate=Certificate(text, path) if text else None)

    def __repr__(self) -> str:
        return f"SpatialScene({self.name!r}, {self.contacts} contacts)"
