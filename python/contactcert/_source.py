"""Problems read from a file, JSON text or a dict (names in messages: the path, "<json>", "<dict>")."""

from __future__ import annotations

import json
import os
from typing import Any, Generic, TypeVar, Union

#: A file path as open() takes it.
Path = Union[str, "os.PathLike[str]"]
C = TypeVar("C")  # the extension class: _core.Scene or _core.Ucp
S = TypeVar("S", bound="FromSource[Any]")


class FromSource(Generic[C]):
    """Constructors over the extension class `_core_type` (its static load(path) and parse(text, name))."""

    _core_type: Any = None  # _core.Scene or _core.Ucp

    def __init__(self, core: C) -> None:
        self._core = core

    @classmethod
    def from_file(cls: type[S], path: Path) -> S:
        return cls(cls._core_type.load(os.fspath(path)))

    @classmethod
    def from_json(cls: type[S], text: str, name: str = "<json>") -> S:
        return cls(cls._core_type.parse(text, name))

    @classmethod
    def from_dict(cls: type[S], data: dict[str, Any], name: str = "<dict>") -> S:
        return cls(cls._core_type.parse(json.dumps(data), name))
