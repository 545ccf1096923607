"""Problems whose extension class keeps their file's name and text (a Scene, an Assembly, a SpatialScene): the name,
the dict and what check(certificate, problem=...) compares; for an Assembly and a SpatialScene also the contact
modes from rest (`contactcert modes FILE`, listed with their accelerations only)."""

from __future__ import annotations

import json
import os
import pathlib
from collections.abc import Callable
from typing import Any, Protocol, TypeVar

from ._options import ARITHS, LONG_MAX, Arith, choice, seconds, whole_number
from ._results import Modes
from ._source import FromSource, Path


class _FileCore(Protocol):
    @property
    def name(self) -> str: ...
    @property
    def text(self) -> str: ...


class _ModesCore(_FileCore, Protocol):
    def modes(self, arith: str, time_limit: float, max_nodes: int | None, max_modes: int | None, certificate: str, /
              ) -> tuple[str, str]: ...


C = TypeVar("C", bound=_FileCore)
M = TypeVar("M", bound=_ModesCore)


class FileProblem(FromSource[C]):
    """A problem read from a file whose text the extension keeps."""

    @property
    def name(self) -> str:
        return self._core.name

    def to_dict(self) -> dict[str, Any]:
        return json.loads(self._core.text)

    def _problem_source(self) -> tuple[str, str]:
        """What `check(certificate, problem=this)` compares a certificate with (as `check --problem FILE`)."""
        return self._core.text, self.name



class ModesProblem(FileProblem[M]):
    """A file problem whose contact modes `contactcert modes FILE` lists with their accelerations only."""

    def modes(self, arith: Arith = "verified", time_limit: float = 0, max_nodes: int | None = None,
              max_modes: int | None = None, certificate: Path | None = None) -> Modes:
        """`contactcert modes FILE`: every kinematically feasible contact mode from rest, each with the accelerations
        that realise it (an assembly: s l r n per contact, the 3N accelerations body by body; a spatial scene: s, f
        and the sliding letters per contact, (a, alpha) of the body); `certificate` is the file its completeness
        proof (assembly_modes or spatial_modes) is written to. Past a budget, BudgetExceeded."""
        return self._modes(self._core.modes, arith, time_limit, max_nodes, max_modes, certificate)

    def _modes(self, run: Callable[[str, float, int | None, int | None, str], tuple[str, str]], arith: Arith,
               time_limit: float, max_nodes: int | None, max_modes: int | None, certificate: Path | None,
               svg: str = "") -> Modes:
        """modes() through `run` (the extension's modes, with what a subclass adds); `svg`: the picture's file."""
        from ._results import Certificate

        choice(arith, ARITHS, "--arith")
        time_limit = seconds(time_limit)
        max_nodes = None if max_nodes is None else whole_number(max_nodes, 1, LONG_MAX, "--max-nodes")
        max_modes = None if max_modes is None else whole_number(max_modes, 1, LONG_MAX, "--max-modes")
        path = os.fspath(certificate) if certificate is not None else ""
        data, text = run(arith, time_limit, max_nodes, max_modes, path)
        picture = (lambda: pathlib.Path(svg).read_text()) if svg else None
        return Modes(json.loads(data), picture, certificate=Certificate(text, path) if text else None)
