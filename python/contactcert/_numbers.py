"""Exact numbers across the boundary: inputs as int, str or Fraction (SPEC section 1 strings), outputs as
fractions.Fraction, float views as numpy arrays. numpy is imported by the first float view only: importing
contactcert and every exact result work without it."""

from __future__ import annotations

import numbers
from collections.abc import Iterable
from fractions import Fraction
from typing import TYPE_CHECKING, Any, Union

if TYPE_CHECKING:
    from numpy.typing import NDArray

#: An exact number as the API accepts it (SPEC section 1 strings: "-7/20", "0.966").
Exact = Union[int, str, Fraction]
#: A vector of exact numbers, or one string "a,b,c".
ExactVector = Union[str, Iterable[Exact]]


def number_text(x: object, what: str) -> str:
    """The exact number x as the engine's text ("-7/20", "0.966"). Floats (Python's, numpy's: every real that
    is not rational) are refused, they are not exact."""
    if isinstance(x, bool) or (isinstance(x, numbers.Real) and not isinstance(x, numbers.Rational)):
        raise ValueError(f"{what}: expected an exact number (int, str or Fraction), found the float {x!r}")
    if isinstance(x, numbers.Integral):
        return str(int(x))
    if isinstance(x, Fraction):
        return f"{x.numerator}/{x.denominator}"
    if isinstance(x, str):
        return x.strip()
    raise ValueError(f"{what}: expected an exact number (int, str or Fraction), found {type(x).__name__}")


def vector_text(v: ExactVector, what: str) -> str:
    """A vector of exact numbers as "a,b,c" (a string is taken as already written so)."""
    if isinstance(v, str):
        return v
    v = list(v)
    if all(type(x) is int for x in v):  # the common case, without the checks of number_text
        return ",".join(map(str, v))
    return ",".join(number_text(x, f"{what}[{i}]") for i, x in enumerate(v))


def exact(value: Any) -> Any:
    """The engine's exact strings ("3/4", nested in lists) as Fractions (nested in tuples)."""
    if isinstance(value, list):
        return tuple(exact(v) for v in value)
    return Fraction(value)


def _numpy() -> Any:
    """The numpy module, imported on the first float view; without it a ModuleNotFoundError saying so."""
    try:
        import numpy
    except ImportError as e:
        raise ModuleNotFoundError(
            "contactcert: the float views (*_approx) need numpy (Debian: python3-numpy); the exact results do not",
            name="numpy") from e
    return numpy


def floats(value: Any, columns: int | None = None) -> NDArray[Any]:
    """A float view (nested lists of numbers or exact strings) as a numpy array of doubles; `columns` shapes an
    empty matrix."""

    def f(x: Any) -> Any:
        if isinstance(x, list):
            return [f(y) for y in x]
        return float(Fraction(x)) if isinstance(x, str) else float(x)

    a = _numpy().array(f(value), dtype=float)
    return a.reshape(-1, columns) if columns else a
