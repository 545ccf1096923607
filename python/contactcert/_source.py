"""Problems read from a file, JSON text or a dict (names in messages: the path, "<json>", "<dict>")."""

import json
import os


class FromSource:
    """Constructors over the extension class `_core_type` (its static load(path) and parse(text, name))."""

    _core_type = None

    def __init__(self, core):
        self._core = core

    @classmethod
    def from_file(cls, path):
        return cls(cls._core_type.load(os.fspath(path)))

    @classmethod
    def from_json(cls, text, name="<json>"):
        return cls(cls._core_type.parse(text, name))

    @classmethod
    def from_dict(cls, data, name="<dict>"):
        return cls(cls._core_type.parse(json.dumps(data), name))
