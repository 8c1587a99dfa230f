"""Field checks for project files: each names the JSON path of a bad value and what was expected; no format."""

from __future__ import annotations

import json
import math
import numbers
from typing import Any

from physink_tui.errors import SceneError
from physink_tui.scene.components import BACKGROUND

SHOW_MAX = 60
_MISSING = object()
_LABEL = "null or a non-empty string"


def show(value: Any) -> str:
    """The value as it would appear in JSON, shortened.

    >>> show(3.5), show("high"), show(None), show(float("nan")), show([1, "a"])
    ('3.5', '"high"', 'null', 'NaN', '[1, "a"]')
    """
    try:
        text = json.dumps(value, ensure_ascii=False)
    except (TypeError, ValueError, RecursionError):
        text = repr(value)
    return text if len(text) <= SHOW_MAX else text[: SHOW_MAX - 3] + "..."


def bad(where: str, key: str, expected: str, got: Any = _MISSING, note: str = "") -> SceneError:
    """The error for one field: its JSON path, what was expected, and what was found (or that it is missing).

    >>> print(bad("project.json", "components[3].material.friction", "a number >= 0", "high"))
    project.json: components[3].material.friction: expected a number >= 0, got "high"
    >>> print(bad("project.json", "canvas", "an object"))
    project.json: canvas: expected an object, but it is missing
    """
    found = "but it is missing" if got is _MISSING else f"got {show(got)}"
    return SceneError(f"{where}: {key}: expected {expected}, {found}{note}")


def _get(obj: dict[str, Any], where: str, path: str, key: str, expected: str) -> Any:
    try:
        return obj[key]
    except KeyError:
        raise bad(where, f"{path}.{key}" if path else key, expected) from None


def _object(where: str, path: str, value: Any, keys: tuple[str, ...], expected: str,
            warnings: list[str] | None) -> dict[str, Any]:
    if not isinstance(value, dict):
        raise bad(where, path, expected, value)
    if warnings is not None:
        prefix = f"{path}." if path else ""
        warnings.extend(f'{where}: unknown key "{prefix}{k}" ignored' for k in value if k not in keys)
    return value


def _real(value: Any) -> float | None:
    """The value as a finite float, or None if it is no finite real number (bools are not numbers)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        return None
    try:
        v = float(value)
    except (OverflowError, ValueError):
        return None
    return v if math.isfinite(v) else None


def _number(where: str, key: str, value: Any, expected: str = "a finite number", low: float | None = None,
            high: float | None = None, above: float | None = None) -> float:
    v = _real(value)
    if v is None or (low is not None and v < low) or (high is not None and v > high) or (
            above is not None and v <= above):
        raise bad(where, key, expected, value)
    return v


def _text(where: str, key: str, value: Any, expected: str = "a non-empty string") -> str:
    if not isinstance(value, str) or not value:
        raise bad(where, key, expected, value)
    try:
        value.encode("utf-8")
    except UnicodeEncodeError:
        raise bad(where, key, "valid Unicode text (no lone surrogates)", value) from None
    return value


def _label(where: str, key: str, value: Any) -> str | None:
    return None if value is None else _text(where, key, value, _LABEL)


def _point(where: str, key: str, value: Any) -> tuple[float, float]:
    if not isinstance(value, list) or len(value) != 2:
        raise bad(where, key, "a point [x, y]", value)
    return _number(where, f"{key}[0]", value[0]), _number(where, f"{key}[1]", value[1])


def _points(where: str, key: str, value: Any, least: int) -> tuple[tuple[float, float], ...]:
    expected = f"a list of at least {least} points [x, y]"
    if not isinstance(value, list) or len(value) < least:
        raise bad(where, key, expected, value)
    return tuple(_point(where, f"{key}[{i}]", p) for i, p in enumerate(value))


def _one_of(where: str, key: str, value: Any, choices: tuple[str, ...]) -> str:
    if not isinstance(value, str) or value not in choices:
        raise bad(where, key, "one of " + ", ".join(show(c) for c in choices), value)
    return value


def _json_value(where: str, key: str, value: Any) -> None:
    """Plain JSON this format can write and read back exactly: no NaN or infinity, no lone surrogates."""
    if value is None or isinstance(value, bool | int):
        return
    if isinstance(value, float):
        _number(where, key, value)
    elif isinstance(value, str):
        if value:
            _text(where, key, value, "a string")
    elif isinstance(value, list):
        for i, item in enumerate(value):
            _json_value(where, f"{key}[{i}]", item)
    elif isinstance(value, dict):
        for k, item in value.items():
            if not isinstance(k, str):
                raise bad(where, key, "an object with string keys", value)
            if k:
                _text(where, f"{key} key", k, "a string")
            _json_value(where, f"{key}.{k}" if k.isidentifier() else f"{key}[{show(k)}]", item)
    else:
        raise bad(where, key, "a JSON value (object, list, string, number, true, false or null)", value)



class _Fields:
    """The fields of one JSON object at ``path``, read with the checks above; references resolved by ``kinds``."""

    def __init__(self, where: str, path: str, obj: dict[str, Any], kinds: dict[str, str]) -> None:
        self.where, self.path, self.obj, self.kinds = where, path, obj, kinds

    def key(self, key: str) -> str:
        return f"{self.path}.{key}" if self.path else key

    def get(self, key: str, expected: str) -> Any:
        return _get(self.obj, self.where, self.path, key, expected)

    def number(self, key: str, expected: str = "a finite number", **bounds: float) -> float:
        return _number(self.where, self.key(key), self.get(key, expected), expected, **bounds)

    def text(self, key: str, expected: str = "a non-empty string") -> str:
        return _text(self.where, self.key(key), self.get(key, expected), expected)

    def label(self) -> str | None:
        return _label(self.where, self.key("label"), self.get("label", _LABEL))

    def one_of(self, key: str, choices: tuple[str, ...]) -> str:
        return _one_of(self.where, self.key(key), self.get(key, "one of " + ", ".join(map(show, choices))), choices)

    def point(self, key: str) -> tuple[float, float]:
        return _point(self.where, self.key(key), self.get(key, "a point [x, y]"))

    def points(self, key: str, least: int) -> tuple[tuple[float, float], ...]:
        return _points(self.where, self.key(key), self.get(key, f"a list of at least {least} points [x, y]"), least)

    def body(self, key: str, *, background: bool = True, other: str | None = None) -> str:
        """The id of a body of the project, or the background where allowed, and not ``other``."""
        expected = f"{show(BACKGROUND)} or the id of a body" if background else "the id of a body"
        return self._body(key, self.get(key, expected), expected, background, other)

    def end(self, key: str) -> str | None:
        """A rope end: null when free, else the background or the id of a body."""
        expected = f"null, {show(BACKGROUND)} or the id of a body"
        value = self.get(key, expected)
        return None if value is None else self._body(key, value, expected, True, None)

    def _body(self, key: str, value: Any, expected: str, background: bool, other: str | None) -> str:
        if isinstance(value, str) and ((background and value == BACKGROUND) or self.kinds.get(value) == "body"):
            if value == other:
                raise bad(self.where, self.key(key), f"something other than the other end {show(other)}", value)
            return value
        note = ""
        if isinstance(value, str):
            note = f" (a {self.kinds[value]}, not a body)" if value in self.kinds else (
                " (the background)" if value == BACKGROUND else " (no component has that id)")
        raise bad(self.where, self.key(key), expected, value, note)
