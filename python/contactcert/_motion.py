"""Quasistatic time-stepping of a motion scene (docs/motion.md): `contactcert simulate` in-process."""

from __future__ import annotations

import os
import json
from collections.abc import Iterator
from fractions import Fraction
from typing import Any

from . import _core
from ._numbers import Exact, exact, number_text
from ._options import ARITHS, LONG_MAX, Arith, choice, seconds, whole_number
from ._results import Result, Vector
from ._source import FromSource, Path

BudgetExceeded = _core.BudgetExceeded


class Step(Result):
    """One step of a trajectory: the step's object in the CLI's --json "steps" (exact values as Fractions; on the
    float path only the `_approx` views exist)."""

    index = property(lambda self: self._data["index"])
    verdict = property(lambda self: self._data["verdict"])

    @property
    def time(self) -> Fraction:
        return Fraction(self._data["time"])

    @property
    def q_dot(self) -> Vector:
        """The body's velocity (v_x, v_y, omega) at the world origin, exactly (a scene of one body; q_dots for
        several)."""
        if "q_dot" not in self._data:
            raise ValueError("a step of several bodies has one q_dot per body: use q_dots")
        return exact(self._data["q_dot"])

    @property
    def q_dots(self) -> dict[str, Vector]:
        """Each body's velocity (v_x, v_y, omega) at the world origin by the body's name, exactly (one body: its name
        is "body")."""
        if "bodies" in self._data:
            return {b["name"]: exact(b["q_dot"]) for b in self._data["bodies"]}
        return {"body": exact(self._data["q_dot"])}

    @property
    def modes(self) -> str:
        """One letter per contact: s separate, r roll, + / - slide, ? (no solution)."""
        return "".join(c["mode"] for c in self._data["contacts"])

    @property
    def made(self) -> list[str]:
        return list(self._data["events"]["made"])

    @property
    def broken(self) -> list[str]:
        return list(self._data["events"]["broken"])

    @property
    def unique(self) -> bool | None:
        """Whether every solution of the step has this motion (None: not decided)."""
        u = self._data.get("uniqueness")
        return None if u is None or u["status"] == "unknown" else u["status"] == "unique"

    def __repr__(self) -> str:
        return f"Step({self.index}, {self.verdict}, modes {self.modes})"


class Simulation(Result):
    """A whole run: the CLI's --json object; iterating yields its Steps in order."""

    def __init__(self, core: _core.Simulation) -> None:
        super().__init__(json.loads(core.json()), core.svg)

    status = property(lambda self: self._data["status"])
    reason = property(lambda self: self._data["reason"])

    def __iter__(self) -> Iterator[Step]:
        return (Step(s) for s in self._data["steps"])

    def __len__(self) -> int:
        return len(self._data["steps"])

    def svg(self) -> str:
        """The animated picture (SVG with SMIL), as `simulate --svg` writes it."""
        return self._svg() if self._svg else ""

    def __repr__(self) -> str:
        return f"Simulation({self.status}, {len(self)} steps)"


class Motion(FromSource[_core.Motion]):
    """A motion scene: one convex body, obstacles, fingers with schedules, a step size and count."""

    _core_type = _core.Motion

    @property
    def name(self) -> str:
        return self._core.name

    def to_dict(self) -> dict[str, Any]:
        return json.loads(self._core.text)

    def __repr__(self) -> str:
        return f"Motion({self.name!r})"

    def _start(self, steps: int | None, dt: Exact | None, arith: Arith, compare: bool, uniqueness: bool,
               max_nodes: int | None, max_modes: int | None, time_limit: float, certificates: Path | None,
               svg: Path | None) -> _core.Run:
        """The run started, its options checked as the CLI checks them (ValueError naming the option)."""
        choice(arith, ARITHS, "--arith")
        steps = None if steps is None else whole_number(steps, 1, 1000000, "--steps")
        dt_text = "" if dt is None else number_text(dt, "--dt")
        max_nodes = None if max_nodes is None else whole_number(max_nodes, 1, LONG_MAX, "--max-nodes")
        max_modes = None if max_modes is None else whole_number(max_modes, 1, LONG_MAX, "--max-modes")
        return self._core.start(steps, dt_text, arith, bool(compare), bool(uniqueness), max_nodes, max_modes,
                                seconds(time_limit), "" if certificates is None else os.fspath(certificates),
                                "" if svg is None else os.fspath(svg))

    def simulate(self, steps: int | None = None, dt: Exact | None = None, arith: Arith = "verified",
                 compare: bool = False, uniqueness: bool = True, max_nodes: int | None = None,
                 max_modes: int | None = None, time_limit: float = 0, certificates: Path | None = None,
                 svg: Path | None = None) -> Simulation:
        """`contactcert simulate FILE [--steps N] [--dt H] ...`: the whole run, iterable step by step. A run stopped
        by a budget or the time limit raises BudgetExceeded with the Simulation (the steps done) as its `result`."""
        run = self._start(steps, dt, arith, compare, uniqueness, max_nodes, max_modes, time_limit, certificates, svg)
        return _checked(Simulation(run.finish()))

    def steps(self, steps: int | None = None, dt: Exact | None = None, arith: Arith = "verified",
              uniqueness: bool = True, max_nodes: int | None = None, max_modes: int | None = None,
              time_limit: float = 0, certificates: Path | None = None) -> Iterator[Step]:
        """A generator of the run's Steps, each made when it is asked for (stop early by not asking; the time limit
        counts from this call). Options as simulate's; a run stopped by a budget raises BudgetExceeded after its
        last step."""
        run = self._start(steps, dt, arith, False, uniqueness, max_nodes, max_modes, time_limit, certificates, None)

        def generate() -> Iterator[Step]:
            while (text := run.next()) is not None:
                yield Step(json.loads(text))
            _checked(Simulation(run.finish()))

        return generate()


def _checked(run: Simulation) -> Simulation:
    """The run, unless a budget stopped it: then BudgetExceeded with the run as its `result`."""
    if run.status != "unknown":
        return run
    stopped = BudgetExceeded(f"budget exceeded: {run.reason} (covered: {run['steps_done']} steps)")
    stopped.result = run  # type: ignore[attr-defined]  # set here, not by the extension
    raise stopped
