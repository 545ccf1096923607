"""A body in space (docs/formats.md section 3b): its contact modes from rest, as `contactcert modes FILE` lists them
for a spatial scene (s separating, f sticking, and the sliding letters of each contact's friction pyramid), and its
strong stability under a wrench, as `contactcert stability FILE --wrench fx,fy,fz,tx,ty,tz` decides it."""

from __future__ import annotations

import json
import os

from . import _core
from ._file_problem import ModesProblem
from ._numbers import ExactVector, vector_text
from ._options import ARITHS, Arith, choice, seconds
from ._results import Certificate, Modes, Result, SpatialStability
from ._source import Path


class SpatialScene(ModesProblem[_core.SpatialScene]):
    """One rigid body in space (mass, inertia, com) and its point contacts with friction pyramids; modes() lists its
    contact modes from rest with their proof (a spatial_modes certificate)."""

    _core_type = _core.SpatialScene

    @property
    def contacts(self) -> int:
        return self._core.contacts

    def modes(self, arith: Arith = "verified", time_limit: float = 0, max_nodes: int | None = None,
              max_modes: int | None = None, certificate: Path | None = None, svg: Path | None = None) -> Modes:
        """`contactcert modes FILE [--certificate PATH] [--svg PATH]`: as ModesProblem.modes; `svg` is the file the
        picture (isometric: the body, its numbered contacts, normals and friction pyramids) is written to, which the
        result's _repr_svg_ reads."""
        picture = os.fspath(svg) if svg is not None else ""

        def run(arith: str, time_limit: float, max_nodes: int | None, max_modes: int | None,
                certificate: str) -> tuple[str, str]:
            return self._core.modes(arith, time_limit, max_nodes, max_modes, certificate, picture)

        return self._modes(run, arith, time_limit, max_nodes, max_modes, certificate, picture)

    def stability(self, wrench: ExactVector, arith: Arith = "verified", certificate: Path | None = None,
                  time_limit: float = 0) -> SpatialStability:
        """`contactcert stability FILE --wrench fx,fy,fz,tx,ty,tz [--certificate PATH] [--time-limit S]`: strongly
        stable, weakly stable or unstable under g = (force, torque about the com); `certificate` is the file the
        evidence (a spatial_stability certificate) is written to. Past `time_limit` seconds (0 = none),
        BudgetExceeded."""
        choice(arith, ARITHS, "--arith")
        time_limit = seconds(time_limit)
        path = os.fspath(certificate) if certificate is not None else ""
        data, text = self._core.stability(vector_text(wrench, "--wrench"), arith, time_limit, path)
        return SpatialStability(json.loads(data), Certificate(text, path) if text else None)

    def cone(self, mode: str, arith: Arith = "verified", time_limit: float = 0,
             certificate: Path | None = None) -> Result:
        """`contactcert cone FILE --mode M [--certificate PATH]`: the 6-D wrench cone of a contact mode (one letter
        per contact: s, f or a sliding letter of its pyramid) in both forms; to_dict()["cone"] is the cone as
        docs/formats.md section 4 writes one; `certificate` is the file its proof (a spatial_cone certificate) is
        written to. Past `time_limit` seconds (0 = none), BudgetExceeded."""
        choice(arith, ARITHS, "--arith")
        path = os.fspath(certificate) if certificate is not None else ""
        data, text = self._core.cone(mode, arith, seconds(time_limit), path)
        return Result(json.loads(data), certificate=Certificate(text, path) if text else None)

    def __repr__(self) -> str:
        return f"SpatialScene({self.name!r}, {self.contacts} contacts)"
