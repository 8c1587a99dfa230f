"""The one JSON checker of every format: reads a value at a key path and says what was expected; no format, no I/O.

Each check takes a `Place` (which file or line the value comes from, which error to raise and how keys read),
the key's path (``"pen.x"``, ``"components[3].material.friction"``, ``"events[2].t0"``) and the value, returns the
value checked (numbers as floats) and raises ``place.error`` worded ``<place>: <key>: expected <what>, got
<value>`` (or ``..., but it is missing``), the value shown as it appears in JSON. The journal names its keys
``key "pen.x"`` (`Place.quoted`); the project and the timeline by their bare path. The formats' own words (the
journal's commands, a project's component references) stay with their codecs.
"""

from __future__ import annotations

import json
import math
import numbers
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, TypeVar

from physink_tui.errors import PhysinkError

SHOW_MAX = 60
"""Offending values are shown with at most this many characters."""

MISSING: Any = object()
"""Stands for a key that is absent, where a value is expected."""

T = TypeVar("T")


def show(value: Any) -> str:
    """The value as it would appear in JSON, shortened.

    >>> show(3.2), show("pad1"), show(True), show(None), show([1, "a"]), show(float("nan"))
    ('3.2', '"pad1"', 'true', 'null', '[1, "a"]', 'NaN')
    """
    try:
        text = json.dumps(value, ensure_ascii=False)
    except (TypeError, ValueError, RecursionError):
        text = repr(value)
    return text if len(text) <= SHOW_MAX else text[: SHOW_MAX - 3] + "..."


def printable(key: str) -> str:
    """A key path as one printable line: control and other unprintable characters escaped.

    >>> printable("devices.tab\\nlet")
    'devices.tab\\\\nlet'
    """
    if key.isprintable():
        return key
    return "".join(c if c.isprintable() else repr(c)[1:-1] for c in key)


@dataclass(frozen=True, slots=True)
class Place:
    """Where checked values come from, which error a bad one raises, and how its key is named.

    Attributes:
        name: what messages start with: ``"line 12"``, ``"pen entry"``, ``"project.json"``; "" for nothing.
        error: the `PhysinkError` subclass raised (`JournalError`, `SceneError`, `TimelineError`).
        quoted: keys read ``key "pen.x"`` (the journal's wording) rather than ``pen.x``.
    """

    name: str
    error: type[PhysinkError] = PhysinkError
    quoted: bool = False

    def __str__(self) -> str:
        return self.name

    def key(self, path: str) -> str:
        """The key as messages name it."""
        return f'key "{printable(path)}"' if self.quoted else printable(path)

    def fail(self, message: str) -> PhysinkError:
        """The error for a message about the whole place (no key): ``<place>: <message>``."""
        return self.error(f"{self.name}: {message}" if self.name else message)

    def bad(self, path: str, expected: str, got: Any = MISSING, note: str = "") -> PhysinkError:
        """The error for one key: what was expected and what was found (or that the key is missing).

        >>> from physink_tui.errors import JournalError, SceneError
        >>> print(Place("line 12", JournalError, quoted=True).bad("t", "a number >= the previous t 3.5", 3.2))
        line 12: key "t": expected a number >= the previous t 3.5, got 3.2
        >>> print(Place("project.json", SceneError).bad("canvas", "an object"))
        project.json: canvas: expected an object, but it is missing
        """
        found = "but it is missing" if got is MISSING else f"got {show(got)}"
        return self.fail(f"{self.key(path)}: expected {expected}, {found}{note}")

    def unknown_key(self, path: str) -> str:
        """The warning for a key the format does not define (it is ignored)."""
        prefix = f"{self.name}: " if self.name else ""
        return f'{prefix}unknown key "{printable(path)}" ignored'


def bad(where: Place, key: str, expected: str, got: Any = MISSING, note: str = "") -> PhysinkError:
    """`Place.bad` as a function: the error for ``key`` at ``where``."""
    return where.bad(key, expected, got, note)


def joined(path: str, key: str) -> str:
    """``key`` under ``path`` (``"canvas.width"``), or ``key`` alone at the top."""
    return f"{path}.{key}" if path else key


def get(obj: dict[str, Any], where: Place, key: str, path: str, expected: str) -> Any:
    """``obj[key]``, or the "missing" error naming ``path`` and what was expected."""
    try:
        return obj[key]
    except KeyError:
        raise where.bad(path, expected) from None


def real(value: Any) -> float | None:
    """The value as a finite float, or None if it is no finite real number (bools are not numbers)."""
    if type(value) is float:
        return value if math.isfinite(value) else None
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        return None
    try:
        value = float(value)
    except (OverflowError, ValueError):
        return None
    return value if math.isfinite(value) else None


def number(where: Place, key: str, value: Any, expected: str = "a finite number", *, low: float | None = None,
           high: float | None = None, above: float | None = None) -> float:
    """A finite number, within the bounds given (``above`` is exclusive), as a float."""
    v = real(value)
    if v is None or (low is not None and v < low) or (high is not None and v > high) or (
            above is not None and v <= above):
        raise where.bad(key, expected, value)
    return v


def limited(where: Place, key: str, value: Any, limit: float) -> float:
    """A number no larger than ``limit`` either way (NaN and infinity refused), as a float.

    >>> limited(Place(""), "events[0].t0", 2e9, 1e9)
    Traceback (most recent call last):
    ...
    physink_tui.errors.PhysinkError: events[0].t0: expected a finite number of at most 1e+09 in size, got 2000000000.0
    """
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise where.bad(key, "a number", value)
    try:
        v = float(value)
    except OverflowError:
        v = math.inf
    if not abs(v) <= limit:  # NaN too
        raise where.bad(key, f"a finite number of at most {limit:g} in size", value)
    return v


def unit(where: Place, key: str, value: Any) -> float:
    """A number in [0, 1]."""
    return number(where, key, value, "a number in [0, 1]", low=0.0, high=1.0)


def positive(where: Place, key: str, value: Any) -> int | float:
    """A finite number > 0, kept an int when it is one (so it is written back the same way)."""
    v = number(where, key, value, "a number > 0", above=0.0)
    return value if type(value) is int else v


def flag(where: Place, key: str, value: Any) -> bool:
    """``true`` or ``false``, nothing else (not 0 or 1)."""
    if value is True or value is False:
        return value
    raise where.bad(key, "true or false", value)


def text(where: Place, key: str, value: Any, expected: str | None = None, *, empty: bool = True) -> str:
    """A string of valid Unicode (no lone surrogates), non-empty unless ``empty``."""
    if expected is None:
        expected = "a string" if empty else "a non-empty string"
    if not isinstance(value, str) or (not empty and not value):
        raise where.bad(key, expected, value)
    try:
        value.encode("utf-8")
    except UnicodeEncodeError:
        raise where.bad(key, "valid Unicode text (no lone surrogates)", value) from None
    return value


def optional(check: Callable[..., T], where: Place, key: str, value: Any, *args: Any, **kwargs: Any) -> T | None:
    """None for ``null``, else ``check(where, key, value, ...)``."""
    return None if value is None else check(where, key, value, *args, **kwargs)


def optional_int(where: Place, key: str, value: Any, high: int) -> int | None:
    """``null`` or an integer in 0..high."""
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, int) or not 0 <= value <= high:
        raise where.bad(key, f"null or an integer in 0..{high}", value)
    return int(value)


def one_of(where: Place, key: str, value: Any, choices: tuple[str, ...]) -> str:
    """One of the strings ``choices``."""
    if not isinstance(value, str) or value not in choices:
        raise where.bad(key, "one of " + ", ".join(show(c) for c in choices), value)
    return value


def an_object(where: Place, key: str, value: Any, expected: str = "an object") -> dict[str, Any]:
    """A JSON object (a dict)."""
    if not isinstance(value, dict):
        raise where.bad(key, expected, value)
    return value


def a_list(where: Place, key: str, value: Any, expected: str = "a list") -> list[Any]:
    """A JSON array (a list)."""
    if not isinstance(value, list):
        raise where.bad(key, expected, value)
    return value


def known_keys(where: Place, path: str, obj: dict[str, Any], keys: tuple[str, ...],
               warnings: list[str] | None) -> None:
    """Appends to ``warnings`` (when given) one warning per key of ``obj`` not in ``keys``."""
    if warnings is not None:
        warnings.extend(where.unknown_key(joined(path, k)) for k in obj if k not in keys)


def point(where: Place, key: str, value: Any, expected: str = "a point [x, y]") -> tuple[float, float]:
    """A point ``[x, y]`` of finite numbers."""
    if not isinstance(value, list) or len(value) != 2:
        raise where.bad(key, expected, value)
    return number(where, f"{key}[0]", value[0]), number(where, f"{key}[1]", value[1])


def points(where: Place, key: str, value: Any, least: int) -> tuple[tuple[float, float], ...]:
    """A list of at least ``least`` points."""
    if not isinstance(value, list) or len(value) < least:
        raise where.bad(key, f"a list of at least {least} points [x, y]", value)
    return tuple(point(where, f"{key}[{i}]", p) for i, p in enumerate(value))


def json_value(where: Place, key: str, value: Any) -> None:
    """Checks that ``value`` is plain JSON a format can write and read back exactly.

    Objects with string keys, lists (or tuples), strings of valid Unicode, finite floats, ints, bools, null.
    """
    if value is None or isinstance(value, bool | int):
        return
    if isinstance(value, float):
        if not math.isfinite(value):
            raise where.bad(key, "a finite number", value)
    elif isinstance(value, str):
        text(where, key, value)
    elif isinstance(value, list | tuple):
        for i, item in enumerate(value):
            json_value(where, f"{key}[{i}]", item)
    elif isinstance(value, dict):
        for k, item in value.items():
            if not isinstance(k, str):
                raise where.bad(key, "an object with string keys", value)
            text(where, f"{key}.{k}", k)
            json_value(where, f"{key}.{k}", item)
    else:
        raise where.bad(key, "a JSON value (object, list, string, number, true, false or null)", value)
