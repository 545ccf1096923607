"""The CLI's rules for options (cli/option_checks.h), so that every entry point refuses what the CLI refuses, with a
ValueError naming the option: a choice is one of its values, integers are ints (no bool, float or string) within the
option's range, and a time limit is a finite number of seconds from 0 to the CLI's limit (no nan, inf or
overflow)."""

from __future__ import annotations

import math
import numbers
from typing import Literal, get_args

from . import _core

Arith = Literal["exact", "float", "verified", "adaptive"]
ARITHS: tuple[str, ...] = get_args(Arith)

LONG_MAX = 2**63 - 1
UINT64_MAX = 2**64 - 1
MAX_TIME_LIMIT: float = _core.MAX_TIME_LIMIT


def whole_number(value: object, lo: int, hi: int, option: str) -> int:
    """value as an int in [lo, hi], else ValueError naming the option."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or not lo <= int(value) <= hi:
        raise ValueError(f"{option}: expected a decimal integer from {lo} to {hi}, found {value!r}")
    return int(value)


def seconds(value: object, option: str = "--time-limit") -> float:
    """value as a float number of seconds in [0, MAX_TIME_LIMIT], else ValueError naming the option."""
    v = math.nan
    if isinstance(value, numbers.Real) and not isinstance(value, bool):
        try:
            v = float(value)
        except OverflowError:  # an int or Fraction beyond double's range
            v = math.inf
    if not (math.isfinite(v) and 0 <= v <= MAX_TIME_LIMIT):
        raise ValueError(f"{option}: expected a number of seconds from 0 to 1e7, found {value!r}")
    return v


def choice(value: str, allowed: tuple[str, ...], option: str) -> str:
    """`value` if it is one of `allowed`, else ValueError naming the CLI option."""
    if value not in allowed:
        raise ValueError(f"{option}: {value!r} not in {{{', '.join(allowed)}}}")
    return value
