"""Fixture design (`contactcert design`) and cone conversion (`contactcert convert`), in-process."""

from __future__ import annotations

import json
import os
import pathlib
from collections.abc import Iterable
from fractions import Fraction
from typing import TYPE_CHECKING, Any, Literal

from . import _core
from ._numbers import Exact, ExactVector, number_text, vector_text
from ._options import LONG_MAX, Arith, seconds, whole_number
from ._results import Result
from ._source import Path

if TYPE_CHECKING:
    from ._scene import Scene


class Design(Result):
    """The best placements of `design`: to_dict() is the CLI's --json object (rank, candidates, points,
    figure, verdicts with their certificate files, the goal's certificates, the picture's file); _repr_svg_ is
    the picture (design.svg)."""

    @property
    def top(self) -> list[dict[str, Any]]:
        return self.to_dict()["top"]

    @property
    def figures(self) -> tuple[Fraction, ...]:
        """The rank's figure of each reported placement, best first."""
        return tuple(Fraction(p["figure"]) for p in self._data["top"])

    def __repr__(self) -> str:
        return f"Design({len(self._data['top'])} placements of {self._data['placements']}, by {self._data['rank']})"


def _wrench_set(value: str | Iterable[ExactVector], cone: bool) -> str:
    """--stable-under's text: a text as the CLI reads it, or wrenches (a list, or a cone's generators)."""
    if isinstance(value, str):
        return value
    text = ";".join(vector_text(w, f"stable_under[{i}]") for i, w in enumerate(value))
    return ("cone:" if cone else "") + text


def design(scene: Scene, candidates: int | Path | None = None, *, lattice: Exact | None = None, fixels: int = 3,
           stable_under: str | Iterable[ExactVector] | None = None, cone: bool = False, insertable: bool = False,
           goal_push: bool = False, goal_wrench: ExactVector | None = None,
           rank: Literal["margin", "goal-fraction"] | None = None, top: int = 5, out: Path = "contactcert-design",
           checkpoint: Path | None = None, chunk_size: int = 16, push_points: int = 120,
           max_placements: int = 100000000, arith: Arith = "verified", time_limit: float = 0) -> Design:
    """`contactcert design FILE ...` on one process: the best `top` placements of `fixels` fixels among the
    candidate points (`candidates` N equally spaced, a candidates file, or `lattice` PITCH), strongly stable
    under `stable_under` (wrenches; `cone`: their cone) and/or insertable, their scenes and certificates written
    under `out`. A budget raises BudgetExceeded with what was covered (resume with the same `checkpoint`)."""
    a = _core.DesignOptions()
    if isinstance(candidates, (str, os.PathLike)):
        a.candidates = os.fspath(candidates)
    elif candidates is not None:
        a.candidates = str(whole_number(candidates, 2, 100000, "--candidates"))
    if lattice is not None:
        a.lattice = number_text(lattice, "--lattice")
    a.fixels = whole_number(fixels, 2, 3, "--fixels")
    if stable_under is not None:
        a.stable_under = _wrench_set(stable_under, cone)
    a.insertable = bool(insertable)
    a.goal_push = bool(goal_push)
    if goal_wrench is not None:
        a.goal_wrench = vector_text(goal_wrench, "--goal-wrench")
    a.top = whole_number(top, 1, 1000, "--top")
    a.out = os.fspath(out)
    a.checkpoint = "" if checkpoint is None else os.fspath(checkpoint)
    a.chunk_size = whole_number(chunk_size, 1, 1000000000, "--chunk-size")
    a.push_points = whole_number(push_points, 1, 100000, "--push-points")
    a.max_placements = whole_number(max_placements, 1, LONG_MAX, "--max-placements")
    a.time_limit = seconds(time_limit)
    a.arith = arith
    a.rank = rank or None
    data = json.loads(_core.design(scene._core, a))
    return Design(data, lambda: pathlib.Path(data["svg"]).read_text())


class Converted(Result):
    """A cone's other form (`contactcert convert`): to_dict() is the CLI's --json object."""

    def __repr__(self) -> str:
        return f"Converted({self._data.get('input')} form in)"


def convert(cone: dict[str, Any] | Path, arith: Arith = "exact", time_limit: float = 0) -> Converted:
    """`contactcert convert FILE`: span <-> face conversion of a cone given as a dict or a file
    (docs/formats.md section 4)."""
    if isinstance(cone, dict):
        text, name = json.dumps(cone), "<dict>"
    else:
        name = os.fspath(cone)
        text = _core.read_text(name)
    return Converted(json.loads(_core.convert(text, name, arith, seconds(time_limit))))
