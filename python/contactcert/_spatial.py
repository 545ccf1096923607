"""A body in space (docs/formats.md section 3b): its contact modes from rest, as `contactcert modes FILE` lists them
for a spatial scene (s separating, f sticking, and the sliding letters of each contact's friction pyramid)."""

from __future__ import annotations

from . import _core
from ._file_problem import ModesProblem


class SpatialScene(ModesProblem[_core.SpatialScene]):
    """One rigid body in space (mass, inertia, com) and its point contacts with friction pyramids; modes() lists its
    contact modes from rest with their proof (a spatial_modes certificate)."""

    _core_type = _core.SpatialScene

    @property
    def contacts(self) -> int:
        return self._core.contacts

    def __repr__(self) -> str:
        return f"SpatialScene({self.name!r}, {self.contacts} contacts)"
