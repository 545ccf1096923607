"""Planar fixture scenes (SPEC section 3) and the Balkcom-Trinkle queries on them."""

from __future__ import annotations

import json
import os
from collections.abc import Callable, Iterable
from fractions import Fraction
from typing import Any, Literal, Union, cast

from . import _core
from ._results import Certificate
from ._numbers import Exact, ExactVector, vector_text
from ._options import ARITHS, LONG_MAX, Arith, choice, seconds, whole_number
from ._results import Cone, Finger, Insertion, Modes, Region, Stability
from ._file_problem import FileProblem
from ._source import Path


def _computed_float(value: Any, path: str) -> tuple[str, float] | None:
    """(path, x) of the first float with more than 15 significant digits in a JSON-like value, else None: a float
    of at most 15 digits is the decimal it was written as, one of 16 or 17 was computed."""
    if isinstance(value, float):
        digits = repr(value).lower().split("e")[0].replace("-", "").replace(".", "").lstrip("0")
        return (path, value) if len(digits) > 15 else None
    items: Iterable[tuple[Any, Any]] = (
        value.items() if isinstance(value, dict) else enumerate(value) if isinstance(value, list) else ()
    )
    for k, v in items:
        found = _computed_float(v, f"{path}.{k}" if isinstance(k, str) else f"{path}[{k}]")
        if found is not None:
            return found
    return None


SnapValue = Union[Fraction, tuple[Fraction, ...]]


def _exact(text: str) -> SnapValue:
    """A Fraction, or a tuple of Fractions for a point "[x, y]"."""
    if text.startswith("["):
        return tuple(Fraction(t) for t in text[1:-1].split(","))
    return Fraction(text)


class Snap:
    """One snap of Scene.from_floats: the field (JSON path), the exact value before and after (Fractions, or
    (x, y) tuples for a point) and the squared distance moved (Fraction); distance_approx its square root."""

    def __init__(self, field: str, original: str, snapped: str, distance_squared: str) -> None:
        self.field = field
        self.original = _exact(original)
        self.snapped = _exact(snapped)
        self.distance_squared = Fraction(distance_squared)

    @property
    def distance_approx(self) -> float:
        return float(self.distance_squared) ** 0.5

    def to_dict(self) -> dict[str, Any]:
        def text(v: SnapValue) -> list[str] | str:
            return [str(x) for x in v] if isinstance(v, tuple) else str(v)

        return {"field": self.field, "original": text(self.original), "snapped": text(self.snapped),
                "distance_squared": str(self.distance_squared), "distance_approx": self.distance_approx}

    def __repr__(self) -> str:
        return f"Snap({self.field}: {self.original} -> {self.snapped}, moved ~{self.distance_approx:.3g})"


class Scene(FileProblem[_core.Scene]):
    """A planar scene: a workpiece held by fixels. Queries run in C++ with the GIL released."""

    _core_type = _core.Scene

    def __init__(self, core: _core.Scene) -> None:
        super().__init__(core)
        self._oracles: dict[str, _core.Oracle] = {}

    @classmethod
    def from_dict(cls, data: dict[str, Any], name: str = "<dict>") -> Scene:
        """The scene a dict gives, every number read exactly as written. A float computed in Python (more than 15
        significant digits, e.g. 0.1 + 0.2 or cos(0.3)) is refused: read such input with from_floats."""
        computed = _computed_float(data, "$")
        if computed is not None:
            path, x = computed
            raise ValueError(f"{name}: {path}: {x!r} is a computed float, whose exact value is not what was meant; "
                             f"read float input with Scene.from_floats(data, snap=1e-9), or write the number as a "
                             f"string such as \"3/10\"")
        return cls(cls._core_type.parse(json.dumps(data), name))

    @classmethod
    def from_floats(
        cls, data: dict[str, Any] | Path, snap: float | str, name: str | None = None
    ) -> tuple[Scene, list[Snap]]:
        """`--snap TOL`: the scene a dict or a file gives with float input made exact on purpose (fixel points put
        exactly on the boundary they touch, other numbers on the simplest rational within `snap`), and the list
        of every Snap made. ValueError naming the field for what cannot be snapped within `snap`."""
        if isinstance(data, dict):
            name = name or "<dict>"
            text = json.dumps(data)
        else:
            name = name or os.fspath(data)
            text = _core.read_text(os.fspath(data))
        tol = repr(snap) if isinstance(snap, float) else str(snap)
        snapped, snaps = _core.snap_scene(text, name, tol)
        return cls(cls._core_type.parse(snapped, name)), [Snap(*s) for s in snaps]

    def cone(self, mode: str, route: Literal["paper", "project"] = "paper", arith: Arith = "verified",
             table2: Literal["strict", "printed"] = "strict", certificate: Path | None = None,
             time_limit: float = 0) -> Cone:
        """`contactcert cone FILE --mode MODE [--route R] [--table2 T] [--certificate PATH] [--time-limit S]`: the
        wrench cone of an augmented contact mode (Table 2 letters); `certificate` is the file its evidence is
        written to (a Motzkin vector for an empty cone, a witness wrench otherwise)."""
        choice(route, ("paper", "project"), "--route")
        choice(arith, ARITHS, "--arith")
        choice(table2, ("strict", "printed"), "--table2")
        path = "" if certificate is None else os.fspath(certificate)
        from ._results import Certificate

        data, text = self._core.cone(mode, route, arith, table2, path, seconds(time_limit))
        svg = None if arith == "float" else (lambda: self._core.cone_svg(mode, route, table2))
        return Cone(json.loads(data), svg, Certificate(text, path) if text else None)

    def stability(self, wrench: ExactVector, margin: bool = False, arith: Arith = "verified",
                  certificate: Path | None = None, time_limit: float = 0) -> Stability:
        """`contactcert stability FILE --wrench fx,fy,tz [--margin] [--certificate PATH] [--time-limit S]`:
        strongly stable, weakly stable or unstable; `certificate` is the file the evidence is written to. Past
        `time_limit` seconds (0 = none; the verdict and the margin together) raises BudgetExceeded."""
        from ._results import Certificate

        choice(arith, ARITHS, "--arith")
        time_limit = seconds(time_limit)
        path = os.fspath(certificate) if certificate is not None else ""
        data, text = self._core.stability(vector_text(wrench, "--wrench"), arith, bool(margin), path, time_limit)
        return Stability(json.loads(data), Certificate(text, path) if text else None)

    def stability_many(self, wrenches: Iterable[ExactVector], arith: Arith = "verified",
                       time_limit: float = 0) -> list[Stability]:
        """`contactcert stability FILE --wrenches FILE`: the verdicts for many wrenches, from a StabilityOracle
        prepared once per scene and arithmetic (within `time_limit` seconds, 0 = none, else BudgetExceeded). Each
        equals stability(g)'s except `lps`, which counts only the LPs solved for g. A result's object (to_dict()
        and every property but `verdict`) is built when first read."""
        choice(arith, ARITHS, "--arith")
        time_limit = seconds(time_limit)
        oracle = self._oracles.get(arith)
        if oracle is None:
            oracle = self._oracles[arith] = _core.Oracle(self._core, arith, time_limit)
        texts = [vector_text(w, f"wrenches[{i}]") for i, w in enumerate(wrenches)]
        return [Stability(cast("Callable[[], dict[str, Any]]", v.object), verdict=name)
                for name, v in oracle.verdicts(texts)]

    def modes(self, kinematic: bool = False, table2: Literal["strict", "printed"] = "strict", unions: bool = False,
              arith: Arith = "verified", certificate: Path | None = None, max_nodes: int | None = None,
              max_modes: int | None = None, time_limit: float = 0) -> Modes:
        """`contactcert modes FILE`: every kinematically feasible contact mode from rest (the prefix tree over the
        fixels, never the 4^k strings); `certificate` is the file its completeness proof is written to. Budgets as
        the CLI's: max_nodes prefixes, max_modes modes (None: the CLI's defaults), time_limit seconds (0: none, but
        60 with unions or table2="printed"); beyond one, BudgetExceeded."""
        choice(table2, ("strict", "printed"), "--table2")
        choice(arith, ARITHS, "--arith")
        nodes = None if max_nodes is None else whole_number(max_nodes, 1, LONG_MAX, "--max-nodes")
        count = None if max_modes is None else whole_number(max_modes, 1, LONG_MAX, "--max-modes")
        from ._results import Certificate

        path = "" if certificate is None else os.fspath(certificate)
        data, text = self._core.modes(bool(kinematic), table2, bool(unions), arith, path, nodes, count,
                                      seconds(time_limit))
        return Modes(json.loads(data), certificate=Certificate(text, path) if text else None)

    def region(self, wrench: ExactVector | None = None, time_limit: float = 0) -> Region:
        """`contactcert stability FILE --region [--wrench fx,fy,tz] [--time-limit S]`: the strongly stable set as
        labelled cells, with the label of `wrench` (picture: the sphere of wrench directions, `wrench` marked).
        Past `time_limit` seconds (0 = none) raises BudgetExceeded."""
        g = vector_text(wrench, "--wrench") if wrench is not None else ""
        time_limit = seconds(time_limit)
        return Region(json.loads(self._core.region(g, time_limit)), lambda: self._core.region_svg(g, time_limit))

    def finger(self, time_limit: float = 0) -> Finger:
        """`contactcert stability FILE --finger [--time-limit S]`: the boundary labelled by the verdict of a
        frictionless push. Past `time_limit` seconds (0 = none) raises BudgetExceeded."""
        time_limit = seconds(time_limit)
        return Finger(json.loads(self._core.finger(time_limit)), lambda: self._core.finger_svg(time_limit))

    def insertion(self, sweep_mu: str | Iterable[Exact] | None = None, arith: Arith = "verified",
                  time_limit: float = 0) -> Insertion:
        """`contactcert insert FILE [--sweep-mu ...]`: G_goal and the pushes that seat the workpiece from any
        contact state; `sweep_mu` (exact numbers) repeats the pushes with every fixel's mu set to each value.
        Past `time_limit` seconds (0: none), BudgetExceeded naming what was computed."""
        choice(arith, ARITHS, "--arith")
        time_limit = seconds(time_limit)
        sweep = vector_text(sweep_mu, "--sweep-mu") if sweep_mu is not None else ""
        return Insertion(json.loads(self._core.insertion(sweep, arith, time_limit)), self._core.insertion_svg)

    def __repr__(self) -> str:
        return f"Scene({self.name!r}, {self._core.fixels} fixels)"
