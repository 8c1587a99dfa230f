"""Strict JSON object building: a key given twice in one object is an error, not silently the last one."""

from __future__ import annotations

from typing import Any


class DuplicateKey(Exception):
    """A JSON object repeats ``key``."""

    def __init__(self, key: str) -> None:
        super().__init__(key)
        self.key = key


def unique_pairs(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    """``object_pairs_hook`` for `json.JSONDecoder` that refuses repeated keys.

    >>> import json
    >>> json.loads('{"a": 1, "a": 2}', object_pairs_hook=unique_pairs)
    Traceback (most recent call last):
    ...
    physink_tui.formats.strict_json.DuplicateKey: a
    """
    obj = dict(pairs)
    if len(obj) != len(pairs):
        seen: set[str] = set()
        for key, _ in pairs:
            if key in seen:
                raise DuplicateKey(key)
            seen.add(key)
    return obj
