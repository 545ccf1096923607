"""Result classes: each holds the object the CLI prints with --json (to_dict() returns it unchanged), with
exact numbers as Fractions, float views as numpy arrays and, where the CLI draws one, a picture."""

from __future__ import annotations

import copy
import json
from collections.abc import Callable
from fractions import Fraction
from typing import TYPE_CHECKING, Any, NamedTuple, Protocol

from . import _core
from ._numbers import exact, floats
from ._source import Path

if TYPE_CHECKING:
    from numpy.typing import NDArray

Vector = tuple[Fraction, ...]
Directions = tuple[tuple[int, ...], ...]


class Result:
    """A result as the CLI's --json object."""

    def __init__(self, data: dict[str, Any] | Callable[[], dict[str, Any]], svg: Callable[[], str] | None = None,
                 certificate: Certificate | None = None) -> None:
        self._made = data  # the object, or the function that builds it when first read (a batch's results)
        self._svg = svg  # a function drawing the picture, or None
        self.certificate = certificate  # a Certificate when the query wrote one

    @property
    def _data(self) -> dict[str, Any]:
        made = self._made
        if not isinstance(made, dict):
            made = self._made = made()
        return made

    def to_dict(self) -> dict[str, Any]:
        """The CLI's --json object for the same query."""
        return copy.deepcopy(self._data)

    def to_json(self) -> str:
        return json.dumps(self._data)

    def __getitem__(self, key: str) -> Any:
        return self._data[key]

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Result) and type(self) is type(other) and self._data == other._data

    def _repr_svg_(self) -> str | None:
        return self._svg() if self._svg else None


def _field(key: str) -> Any:
    """A property: the --json object's member `key`."""
    return property(lambda self: self._data[key])


def _directions(form: str, key: str, doc: str) -> Any:
    """A property: the primitive integer rows `key` of the --json object's `form` as int tuples (() if absent)."""

    def get(self: Result) -> Directions:
        d = self._data.get(form)
        return tuple(tuple(int(x) for x in row) for row in d[key]) if d and key in d else ()

    return property(get, doc=doc)


class Cone(Result):
    """The wrench cone of an augmented contact mode (Balkcom-Trinkle 2002, eqs. 13-17): face form f . g <= 0
    (< 0 on strict rows, = 0 on equalities), span form of its closure (rays, lines) and the open faces."""

    mode = _field("mode")
    empty = _field("empty")

    @property
    def dimension(self) -> int | None:
        return self._data.get("dimension")

    inequalities = _directions("face", "inequalities", "Rows f of the face form with f . g <= 0.")
    strict = _directions("face", "strict", "Rows f with f . g < 0 (the open faces).")
    equalities = _directions("face", "equalities", "Rows f with f . g = 0.")
    rays = _directions("span", "rays", "Generators of the closure.")
    lines = _directions("span", "lines", "Lines (both senses) of the closure.")

    @property
    def open_faces(self) -> tuple[tuple[int, ...], ...]:
        return tuple(tuple(f) for f in self._data.get("open_faces", []))

    @property
    def K(self) -> tuple[Vector, ...] | None:
        return exact(self._data["K"]) if "K" in self._data else None

    @property
    def P(self) -> tuple[Vector, ...] | None:
        return exact(self._data["P"]) if "P" in self._data else None

    @property
    def rays_approx(self) -> NDArray[Any]:
        """The closure's generators as doubles (rows)."""
        if "span_approx" in self._data:
            return floats(self._data["span_approx"]["rays"], 3)
        return floats([list(r) for r in self.rays], 3)

    def __repr__(self) -> str:
        if self.empty:
            return f"Cone(mode={self.mode!r}, empty)"
        if "dimension" not in self._data:
            return f"Cone(mode={self.mode!r}, float, {len(self._data['span_approx']['rays'])} rays)"
        return (f"Cone(mode={self.mode!r}, dimension {self.dimension}, {len(self.rays)} rays, "
                f"{len(self.lines)} lines, {len(self.open_faces)} open faces)")


class Contact(NamedTuple):
    """One touching fixel's contact force (frames as written, docs/formats.md section 3): its point, the frame it
    is measured in (the normal as the scene writes it, t = (-n_y, n_x)), the components c_n, c_t, the world force
    c_n n + c_t t and its torque about the centre of mass. Fractions (floats on the float path)."""

    fixel: int
    point: tuple[Any, ...]
    normal: tuple[Any, ...]
    tangent: tuple[Any, ...]
    c_n: Any
    c_t: Any
    force: tuple[Any, ...]
    torque: Any


def _number(x: Any) -> Any:
    return Fraction(x) if isinstance(x, str) else x


def _contacts(items: list[dict[str, Any]] | None) -> tuple[Contact, ...] | None:
    """The --json object's per-fixel contact forces as Contacts."""
    if items is None:
        return None

    def vec(v: list[Any]) -> tuple[Any, ...]:
        return tuple(_number(x) for x in v)

    return tuple(Contact(c["fixel"], vec(c["point"]), vec(c["normal"]), vec(c["tangent"]), _number(c["c_n"]),
                         _number(c["c_t"]), vec(c["force"]), _number(c["torque"])) for c in items)


class _Witnessed(Result):
    """A verdict with a moving solution where one exists (`witness.moving`): Stability and SpatialStability."""

    @property
    def wrench(self) -> Vector:
        return exact(self._data["wrench"])

    @property
    def moving_mode(self) -> str | None:
        m = self._data["witness"].get("moving")
        return m["mode"] if m else None

    @property
    def acceleration(self) -> Vector | None:
        """The moving solution's acceleration vdot (Fractions), or None."""
        m = self._data["witness"].get("moving")
        return exact(m["acceleration"]) if m and "acceleration" in m else None


class Stability(_Witnessed):
    """Strong stability under one wrench (Balkcom-Trinkle 2002, section 7): the verdict with a resting and
    a moving solution where they exist."""

    def __init__(self, data: dict[str, Any] | Callable[[], dict[str, Any]], certificate: Certificate | None = None,
                 verdict: str | None = None) -> None:
        super().__init__(data)
        self.certificate = certificate  # a Certificate when one was written
        self._verdict = verdict  # known before the object is built (stability_many), else None

    @property
    def verdict(self) -> str:
        """strongly_stable, weakly_stable or unstable."""
        return self._verdict if self._verdict is not None else str(self._data["verdict"])

    @property
    def touching_fixels(self) -> tuple[int, ...]:
        return tuple(self._data["touching_fixels"])

    @property
    def resting_forces(self) -> tuple[Fraction, ...] | tuple[float, ...] | None:
        """Contact forces (c_n..., c_t...) balancing g at rest: Fractions (doubles on the float path), or None."""
        f = self._data["witness"].get("resting_forces")
        if f is None:
            return None
        return exact(f) if self._data["arith"] != "float" else tuple(f)

    @property
    def contacts(self) -> tuple[Contact, ...] | None:
        """The resting solution's contact forces, one Contact per touching fixel, or None."""
        return _contacts(self._data["witness"].get("resting_contacts"))

    @property
    def moving_contacts(self) -> tuple[Contact, ...] | None:
        """The moving solution's contact forces, one Contact per touching fixel, or None."""
        m = self._data["witness"].get("moving")
        return _contacts(m["contacts"]) if m else None

    @property
    def acceleration_approx(self) -> NDArray[Any] | None:
        m = self._data["witness"].get("moving")
        return floats(m["acceleration_approx"]) if m else None

    @property
    def squared_margin(self) -> Fraction | None:
        """With margin=True on a strongly stable verdict: the squared radius of the largest strongly stable
        ball around g (Fraction), else None."""
        m = self._data.get("margin")
        return exact(m["squared_radius"]) if m else None

    def __repr__(self) -> str:
        w = ", ".join(str(x) for x in self.wrench)
        extra = f", moving mode {self.moving_mode!r}" if self.moving_mode else ""
        return f"Stability({self.verdict}, wrench=({w}), {len(self.touching_fixels)} touching fixels{extra})"


class SpatialStability(_Witnessed):
    """Strong stability of a body in space under one wrench g = (force, torque about the com) (issue 34): the
    verdict with a resting and a moving solution (its acceleration is (a, alpha)) where they exist."""

    def __init__(self, data: dict[str, Any], certificate: Certificate | None = None) -> None:
        super().__init__(data)
        self.certificate = certificate  # a Certificate when one was written

    @property
    def verdict(self) -> str:
        """strongly_stable, weakly_stable or unstable."""
        return str(self._data["verdict"])

    @property
    def resting_forces(self) -> tuple[Vector, ...] | None:
        """The world contact forces balancing g at rest, one (Fraction) 3-vector per contact, or None."""
        f = self._data["witness"].get("resting_forces")
        return tuple(exact(c) for c in f) if f is not None else None

    def __repr__(self) -> str:
        extra = f", moving mode {self.moving_mode!r}" if self.moving_mode else ""
        return f"SpatialStability({self.verdict}, wrench={tuple(str(x) for x in self.wrench)}{extra})"


class Modes(Result):
    """The kinematically feasible contact modes of a scene from rest (`contactcert modes`), each with an
    acceleration that realises it and, in the dynamic list, a wrench in its cone."""

    @property
    def modes(self) -> list[str]:
        """The mode strings, one Table 2 letter per fixel, in the order of the prefix tree."""
        return [m["mode"] for m in self._data["modes"]]

    counts = _field("counts")

    def acceleration(self, mode: str) -> Vector:
        """The exact acceleration vdot listed for `mode`, as Fractions."""
        for m in self._data["modes"]:
            if m["mode"] == mode:
                return exact(m["acceleration"])
        raise KeyError(mode)

    def __repr__(self) -> str:
        t = self._data["tree"]
        return f"Modes({len(self._data['modes'])} feasible modes, {t['nodes']} prefixes, {t['dead_prefixes']} dead)"


class Region(Result):
    """The labelled cells of wrench space (section 7, Figure 5): every g is in exactly one cell."""

    @property
    def cells(self) -> list[dict[str, Any]]:
        return self._data["region"]["cells"]

    def count(self, label: str, dimension: int | None = None) -> int:
        return sum(1 for c in self.cells if c["label"] == label and dimension in (None, c["dimension"]))

    def __repr__(self) -> str:
        r = self._data["region"]
        return (f"Region({len(r['cells'])} cells, {len(r['planes'])} planes, "
                f"{self.count('strongly_stable', 3)} strongly stable open regions)")


class Finger(Result):
    """Where a frictionless finger push along the inward normal is strongly stable, weakly or unstable."""

    def __repr__(self) -> str:
        f = self._data["finger"]
        return f"Finger({len(f['edges'])} edge pieces, {len(f['arcs'])} arcs)"


class Insertion(Result):
    """G_goal (sections 8-9, eq. 21): the wrenches that seat the workpiece from any contact state."""

    @property
    def goal_boundary_fraction(self) -> float:
        return self._data["goal_boundary_fraction_approx"]

    @property
    def sweep(self) -> tuple[tuple[Fraction, float], ...]:
        """With sweep_mu: (mu, fraction of the boundary whose pushes seat the part) per value (Figure 11)."""
        return tuple((exact(e["mu"]), e["goal_boundary_fraction_approx"]) for e in self._data.get("sweep", []))

    def __repr__(self) -> str:
        return (f"Insertion({len(self._data['sets'])} contact states, "
                f"boundary fraction in G_goal ~{self.goal_boundary_fraction:.4f})")


class UcpResult(Result):
    """The quasistatic problem's verdict (Pang-Trinkle-Lo 1994): solvable with a pair x, y (x^T y = 0) and its
    physical reading, or jammed."""

    def __init__(self, data: dict[str, Any], certificate: Certificate | None = None) -> None:
        super().__init__(data)
        self.certificate = certificate

    status = _field("status")

    @property
    def x(self) -> Vector | None:
        return exact(self._data["x"]) if "x" in self._data else None

    @property
    def y(self) -> Vector | None:
        return exact(self._data["y"]) if "y" in self._data else None

    @property
    def physical(self) -> dict[str, Vector] | None:
        """c_n, c_t, v_n, v_t, q_dot, theta_dot, tau as Fractions, or None."""
        p = self._data.get("physical")
        return {k: exact(v) for k, v in p.items() if isinstance(v, list) and k != "contacts"} if p else None

    def __repr__(self) -> str:
        return f"UcpResult({self.status}, {self._data['reason']!r}, method {self._data['method']})"


def budget_exceeded(result: Result, what: str, covered: str) -> _core.BudgetExceeded:
    """The BudgetExceeded of a run that a budget or the time limit stopped, with the result as its `result`: its
    message is the CLI's report of that limit (without "contactcert: ")."""
    e = _core.BudgetExceeded(f"budget exceeded: {what} (covered: {covered})")
    e.result = result  # type: ignore[attr-defined]  # set here, not by the extension
    return e


def ucp_covered(d: dict[str, Any]) -> str:
    """What a UCP run covered before it stopped: its nodes (the complete search), pairs and LPs."""
    return ", ".join(f"{d[k]} {k}" for k in ("nodes", "pairs", "lps") if k in d)


class CheckResult(Result):
    """`contactcert check`'s answer: is the certificate valid, and why; `text` the readable lines of its evidence
    (the world forces of a witness), as the CLI prints them under a VALID verdict."""

    def __init__(self, data: dict[str, Any], text: str = "") -> None:
        super().__init__(data)
        self.text = text

    valid = _field("valid")
    kind = _field("kind")
    reason = _field("reason")

    def __bool__(self) -> bool:
        return self.valid

    def __repr__(self) -> str:
        return f"CheckResult({self.kind}, {'VALID' if self.valid else 'INVALID'}: {self.reason})"


class Problem(Protocol):
    """What a certificate can be checked against (`check --problem FILE`): a Scene, a Ucp or an Assembly, by the
    text it was read from and its name."""

    def _problem_source(self) -> tuple[str, str]: ...


def check_text(text: str, name: str, problem: Problem | None = None) -> CheckResult:
    """The checker module's verdict (queries/check.h, the one the CLI's `check` calls) on a certificate's text."""
    if problem is not None and not hasattr(problem, "_problem_source"):
        raise TypeError(f"problem: expected a Scene, a Ucp or an Assembly, found {type(problem).__name__}")
    problem_text, problem_name = ("", "") if problem is None else problem._problem_source()
    data, lines = _core.check(text, name, problem_text, problem_name)
    return CheckResult(json.loads(data), lines)


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

    def check(self, problem: Problem | None = None) -> CheckResult:
        return check_text(self.text, self.path or "<certificate>", problem)

    def __repr__(self) -> str:
        return f"Certificate({self.kind}{', ' + self.path if self.path else ''})"
