"""The journal's own words for single values (times, commands, hex reports); the checking itself is `json_checks`'.

The codec checks with these functions in both directions, so whatever the writer accepts the reader reads
back. Each takes the `Place` made by `at` (``"line 12"`` when reading, ``"pen entry"`` when writing) and the
key's dotted path (``"pen.x"``), and raises `JournalError` worded ``<where>: key "<key>": expected <what>, got
<value>``, the value shown as it appears in JSON.
"""

from __future__ import annotations

import re
from typing import Any

from physink_tui.errors import JournalError
from physink_tui.formats.json_checks import Place, real, show

KINDS = ("hid", "pen", "cmd", "say", "device")
"""The keys that say what an entry is; a line has exactly one of them."""

COMMANDS = ("mode", "play", "pause", "stop", "seek", "clear", "undo", "redo", "label", "simulate", "save", "load",
            "end")
"""Command names, as the session knows them."""

MODES = ("sketch", "demo")
"""The arguments ``mode`` takes."""

LABEL_TARGETS = ("last", "selected")
"""``label`` targets besides a component id."""

MAX_SECONDS = 366 * 24 * 3600.0
"""The latest ``t`` (and ``seek`` time) a journal may hold, in seconds: a year and a day. Larger finite values
(``1e308``) are refused, since time arithmetic on them overflows and no session lasts that long."""

MAX_COUNT = 2**31 - 1
"""The largest ``simulate`` seed or budget a journal may hold (any reader's integers hold it exactly)."""

SECONDS_EXPECTED = f"a number in [0, {MAX_SECONDS:.0f}] (seconds since the session start)"
"""What a ``t`` must be, in error messages."""

_USAGE = {
    "mode": 'one argument, "sketch" or "demo",',
    "seek": f"one argument, a number in [0, {MAX_SECONDS:.0f}] (seconds of timeline time),",
    "label": 'two arguments, TARGET ("last", "selected" or a component id) and a non-empty TEXT,',
    "save": "one argument, a non-empty PATH,",
    "load": "one argument, a non-empty PATH,",
}
_HEX = re.compile(r"[0-9a-fA-F]{2}(?: [0-9a-fA-F]{2})*\Z")


def at(name: str) -> Place:
    """The place ``name`` (``"line 12"``, ``"pen entry"``) of a journal: `JournalError`, keys quoted."""
    return Place(name, JournalError, quoted=True)


def kinds_error(where: Place, found: list[str]) -> JournalError:
    """The error for a line with none or several of ``hid``, ``pen``, ``cmd``, ``say``, ``device``."""
    what = " and ".join(found) if found else "none"
    return JournalError(f"{where}: expected exactly one of {', '.join(KINDS)}; found {what}")


def seconds(where: Place, key: str, value: Any, previous: float | None = None) -> float:
    """A time in seconds: finite, in [0, `MAX_SECONDS`], and >= ``previous`` when given.

    >>> seconds(at("line 12"), "t", 3.2, previous=3.5)
    Traceback (most recent call last):
    ...
    physink_tui.errors.JournalError: line 12: key "t": expected a number >= the previous t 3.5, got 3.2
    """
    t = real(value)
    if t is None or not 0 <= t <= MAX_SECONDS:
        raise where.bad(key, SECONDS_EXPECTED, value)
    if previous is not None and t < previous:
        raise where.bad(key, f"a number >= the previous t {previous!r}", value)
    return t


def hex_bytes(where: Place, key: str, value: Any) -> bytes:
    """Bytes from their hex form, two digits each, separated by one space (``"02 c1 00"``), at least one."""
    if not isinstance(value, str) or not _HEX.match(value):
        raise where.bad(key, 'hex bytes separated by spaces, e.g. "02 c1 00"', value)
    return bytes.fromhex(value)


def report_bytes(where: Place, key: str, value: Any) -> bytes:
    """Bytes built in code: a non-empty ``bytes``-like value."""
    if not isinstance(value, bytes | bytearray | memoryview) or not len(value):
        raise where.bad(key, "non-empty bytes", value)
    return bytes(value)


def command(where: Place, name: Any, args: Any) -> tuple[str | float, ...]:
    """A command's name and arguments, minimally checked; the arguments as a tuple (seek's as a float, simulate's
    as ints).

    >>> command(at("line 5"), "seek", [2])
    (2.0,)
    >>> command(at("line 5"), "mode", ["draw"])
    Traceback (most recent call last):
    ...
    physink_tui.errors.JournalError: line 5: key "args": expected one argument, "sketch" or "demo", for "mode", \
got ["draw"]
    """
    if not isinstance(name, str) or name not in COMMANDS:
        raise where.bad("cmd", f"one of {', '.join(COMMANDS)}", name)
    if not isinstance(args, list | tuple):
        raise where.bad("args", "a list", args)
    if name == "simulate":
        return simulate_args(where, args)
    ok = _args_ok(name, args)
    if ok is None:
        raise where.bad("args", f"{_USAGE.get(name, 'no arguments')} for {show(name)}", list(args))
    return ok


def simulate_args(where: Place, args: list[Any] | tuple[Any, ...]) -> tuple[int, ...]:
    """``simulate [SEED [BUDGET]]``: the seed an integer >= 0, the budget (rollouts) an integer >= 1, both at
    most `MAX_COUNT`; a missing one is the default's (the session journals both).

    >>> simulate_args(at("line 5"), [3, 20])
    (3, 20)
    >>> simulate_args(at("line 5"), [1.5])
    Traceback (most recent call last):
    ...
    physink_tui.errors.JournalError: line 5: key "args[0]": expected a seed, an integer in [0, 2147483647], got 1.5
    """
    if len(args) > 2:
        raise where.bad("args", 'at most two arguments, SEED and BUDGET, for "simulate"', list(args))
    for i, (value, (what, least)) in enumerate(zip(args, (("a seed", 0), ("a budget (rollouts)", 1)),
                                                   strict=False)):
        if not isinstance(value, int) or isinstance(value, bool) or not least <= value <= MAX_COUNT:
            raise where.bad(f"args[{i}]", f"{what}, an integer in [{least}, {MAX_COUNT}]", value)
    return tuple(args)


def _args_ok(name: str, args: list[Any] | tuple[Any, ...]) -> tuple[str | float, ...] | None:
    def is_text(value: Any) -> bool:
        try:
            return isinstance(value, str) and bool(value) and bool(value.encode("utf-8"))
        except UnicodeEncodeError:
            return False

    if name == "mode":
        return (args[0],) if len(args) == 1 and args[0] in MODES and isinstance(args[0], str) else None
    if name == "seek":
        t = real(args[0]) if len(args) == 1 else None
        return (t,) if t is not None and 0 <= t <= MAX_SECONDS else None
    if name == "label":
        return (args[0], args[1]) if len(args) == 2 and is_text(args[0]) and is_text(args[1]) else None
    if name in ("save", "load"):
        return (args[0],) if len(args) == 1 and is_text(args[0]) else None
    return () if not args else None
