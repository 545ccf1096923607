"""Exact numbers across the boundary: inputs as int, str or Fraction (SPEC section 1 strings), outputs as
fractions.Fraction, float views as numpy arrays."""

import numbers
from fractions import Fraction

import numpy as np


def number_text(x, what):
    """The exact number x as the engine's text ("-7/20", "0.966"); floats are refused (not exact)."""
    if isinstance(x, bool) or isinstance(x, float) or isinstance(x, np.floating):
        raise ValueError(f"{what}: expected an exact number (int, str or Fraction), found the float {x!r}")
    if isinstance(x, numbers.Integral):
        return str(int(x))
    if isinstance(x, Fraction):
        return f"{x.numerator}/{x.denominator}"
    if isinstance(x, str):
        return x.strip()
    raise ValueError(f"{what}: expected an exact number (int, str or Fraction), found {type(x).__name__}")


def vector_text(v, what):
    """A vector of exact numbers as "a,b,c" (a string is taken as already written so)."""
    if isinstance(v, str):
        return v
    if all(type(x) is int for x in v):  # the common case, without the checks of number_text
        return ",".join(map(str, v))
    return ",".join(number_text(x, f"{what}[{i}]") for i, x in enumerate(v))


def exact(value):
    """The engine's exact strings ("3/4", nested in lists) as Fractions."""
    if isinstance(value, list):
        return tuple(exact(v) for v in value)
    return Fraction(value)


def floats(value, columns=None):
    """A float view (nested lists of numbers or exact strings) as a numpy array of doubles; `columns` shapes an
    empty matrix."""

    def f(x):
        if isinstance(x, list):
            return [f(y) for y in x]
        return float(Fraction(x)) if isinstance(x, str) else float(x)

    a = np.array(f(value), dtype=float)
    return a.reshape(-1, columns) if columns else a
