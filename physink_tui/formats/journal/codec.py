"""The journal's entry lines, both ways, and the JSON rules every line follows; the header is `header_codec`'s.

Lines are compact JSON (no spaces) in a fixed key order, floats written as ``repr`` writes them, so a value
read back is equal to the one written and re-encodes to the same bytes. ``"t"`` comes first, then the key
that says what the entry is::

    {"t":0.5,"hid":"02 c1 00","dev":"tablet0"}
    {"t":0.51,"pen":{"x":0.25,"y":0.5,"p":0.0,"tip":false,"range":true,"eraser":false,"b1":false,"b2":false}}
    {"t":1.0,"cmd":"seek","args":[2.5]}
    {"t":1.1,"cmd":"load","args":["egg.physink.json"],"project":{"format":"physink-project","version":1,...}}
    {"t":1.25,"say":"label ball"}
    {"t":2.0,"device":{"tablet1":{"name":null,"bus":3,"vid":9580,"pid":110,"descriptor":"05 0d ..."}}}

A ``load`` line embeds the loaded project's JSON object, checked as a project file is (a replay needs no
other file); ``end`` (no arguments) says the session ended at t. Non-ASCII text is written as UTF-8, not
escaped. Reading refuses what plain ``json`` lets pass: NaN and Infinity, and a key twice in one object.
Encoding checks every value with the same rules as decoding (`value_checks` over
`physink_tui.formats.json_checks`), so everything written reads back. Both raise `JournalError`. No file I/O.
"""

from __future__ import annotations

import json
from collections.abc import Collection
from typing import Any, cast

from physink_tui.errors import JournalError
from physink_tui.formats import json_checks as checks
from physink_tui.formats.journal import value_checks
from physink_tui.formats.journal.entries import CommandEntry, DeviceEntry, HidEntry, JournalEntry, PenEntry, SayEntry
from physink_tui.formats.journal.header_checks import decode_devices, encode_devices
from physink_tui.formats.journal.value_checks import at
from physink_tui.formats.json_checks import Place, bad, get, show
from physink_tui.formats.project.codec import decode_project_object
from physink_tui.formats.strict_json import DuplicateKey, unique_pairs

PEN_KEYS = ("x", "y", "p", "tip", "range", "eraser", "b1", "b2")
"""The keys of a ``pen`` object, in the order written."""

_ALLOWED = {"hid": {"t", "hid", "dev"}, "pen": {"t", "pen"}, "cmd": {"t", "cmd", "args", "project"},
            "say": {"t", "say"}, "device": {"t", "device"}}
_BOOL = {True: "true", False: "false"}
_LOAD_EXPECTED = "the loaded project's JSON object (a replay needs the project embedded)"
_PEN_EXPECTED = "an object with " + ", ".join(PEN_KEYS)



class _NotANumber(Exception):
    def __init__(self, name: str) -> None:
        super().__init__(name)
        self.name = name



def _constant(name: str) -> Any:
    raise _NotANumber(name)


_STRICT = json.JSONDecoder(object_pairs_hook=unique_pairs, parse_constant=_constant)
_PLAIN = json.JSONDecoder()


def json_string(value: str) -> str:
    """A string as JSON, non-ASCII characters kept (the lines are UTF-8)."""
    return json.dumps(value, ensure_ascii=False)


def compact_json(value: Any, *, sort_keys: bool = False) -> str:
    """A checked JSON value without spaces, floats as ``repr`` writes them (exact round trip)."""
    return json.dumps(value, ensure_ascii=False, separators=(",", ":"), allow_nan=False, sort_keys=sort_keys)


def parse_object(text: str, where: Place | str) -> dict[str, Any]:
    """The JSON object on one line; `JournalError` starting with ``where`` if it is not valid JSON or no object.

    >>> parse_object('{"t":1,"t":2}', "line 5")
    Traceback (most recent call last):
    ...
    physink_tui.errors.JournalError: line 5: key "t" appears twice in one object
    """
    try:
        value = _STRICT.decode(text)
    except DuplicateKey as e:
        raise JournalError(f'{where}: key "{e.key}" appears twice in one object') from None
    except _NotANumber as e:
        raise JournalError(f"{where}: not valid JSON: {e.name} is not a number JSON allows") from None
    except json.JSONDecodeError as e:
        raise JournalError(f"{where}: not valid JSON ({e.msg} at column {e.colno})") from None
    except (ValueError, RecursionError) as e:
        raise JournalError(f"{where}: not valid JSON ({e})") from None
    if not isinstance(value, dict):
        raise JournalError(f"{where}: expected a JSON object, got {show(value)}")
    return value


def is_json(text: str) -> bool:
    """Whether ``text`` is one complete JSON value: tells a line cut off mid-write from a malformed one.

    >>> is_json('{"t":1.5,"say":"hi"}'), is_json('{"t":1.5,"sa')
    (True, False)
    """
    try:
        _PLAIN.decode(text)
    except (ValueError, RecursionError):
        return False
    return True


def encode_entry(
    entry: JournalEntry, *, previous_t: float | None = None, devices: Collection[str] | None = None
) -> str:
    """The entry as one line (without the newline), after checking it.

    Args:
        entry: the entry.
        previous_t: the previous entry's t, when known: a smaller t is refused.
        devices: the header's device ids, when known: a `HidEntry` naming another device is refused.

    Raises:
        JournalError: ``<kind> entry: key "<key>": expected ..., got ...`` for the first bad field.
        TypeError: ``entry`` is not a journal entry.

    >>> print(encode_entry(CommandEntry(2.0, "seek", (1,))))
    {"t":2.0,"cmd":"seek","args":[1.0]}
    >>> encode_entry(PenEntry(3.2, 0.5, 1.5, 0.0, False, True, False, False, False))
    Traceback (most recent call last):
    ...
    physink_tui.errors.JournalError: pen entry: key "pen.y": expected a number in [0, 1], got 1.5
    """
    if type(entry) is PenEntry:
        where = at("pen entry")
        t = value_checks.seconds(where, "t", entry.t, previous_t)
        unit, flag = checks.unit, checks.flag
        return (
            f'{{"t":{t!r},"pen":{{"x":{unit(where, "pen.x", entry.x)!r},"y":{unit(where, "pen.y", entry.y)!r},'
            f'"p":{unit(where, "pen.p", entry.p)!r},"tip":{_BOOL[flag(where, "pen.tip", entry.tip)]},'
            f'"range":{_BOOL[flag(where, "pen.range", entry.range)]},'
            f'"eraser":{_BOOL[flag(where, "pen.eraser", entry.eraser)]},'
            f'"b1":{_BOOL[flag(where, "pen.b1", entry.b1)]},"b2":{_BOOL[flag(where, "pen.b2", entry.b2)]}}}}}'
        )
    if type(entry) is HidEntry:
        where = at("hid entry")
        t = value_checks.seconds(where, "t", entry.t, previous_t)
        data = value_checks.report_bytes(where, "hid", entry.data)
        dev = _device(where, checks.text(where, "dev", entry.dev, empty=False), devices)
        return f'{{"t":{t!r},"hid":"{data.hex(" ")}","dev":{json_string(dev)}}}'
    if type(entry) is CommandEntry:
        where = at("cmd entry")
        t = value_checks.seconds(where, "t", entry.t, previous_t)
        args = value_checks.command(where, entry.name, entry.args)
        listed = ",".join(repr(a) if isinstance(a, float) else json_string(a) for a in args)
        embedded = _embedded_project(where, entry.name, entry.project, entry.project is not None)
        project = "" if embedded is None else f',"project":{compact_json(embedded)}'
        return f'{{"t":{t!r},"cmd":{json_string(entry.name)},"args":[{listed}]{project}}}'
    if type(entry) is SayEntry:
        where = at("say entry")
        t = value_checks.seconds(where, "t", entry.t, previous_t)
        return f'{{"t":{t!r},"say":{json_string(checks.text(where, "say", entry.text))}}}'
    if type(entry) is DeviceEntry:
        where = at("device entry")
        t = value_checks.seconds(where, "t", entry.t, previous_t)
        if not entry.devices:
            raise bad(where, "device", "at least one device", [])
        return f'{{"t":{t!r},"device":{compact_json(encode_devices(where, "device", entry.devices))}}}'
    raise TypeError(f"not a journal entry: {entry!r}")


def _embedded_project(where: Place, name: str, project: Any, present: bool,
                      warnings: list[str] | None = None) -> dict[str, Any] | None:
    """A ``load`` command's embedded project, checked as a project file is (errors name the line and the field's
    path in the project); None for the other commands, which embed none."""
    if name != "load":
        if present:
            raise where.bad("project", 'nothing: only "load" embeds a project', project)
        return None
    if not present:
        raise where.bad("project", _LOAD_EXPECTED)
    checks.json_value(where, "project", project)
    decode_project_object(project, Place(f'{where}: key "project"', JournalError), warnings)
    return cast("dict[str, Any]", project)  # decode_project_object has checked that it is a JSON object


def _device(where: Place, dev: str, devices: Collection[str] | None) -> str:
    if devices is not None and dev not in devices:
        known = ", ".join(show(d) for d in devices) or "none"
        raise JournalError(f'{where}: "dev" {show(dev)} is not a device of the header (devices: {known})')
    return dev


def decode_line(
    text: str,
    lineno: int,
    *,
    previous_t: float | None = None,
    devices: Collection[str] | None = None,
    warnings: list[str] | None = None,
) -> JournalEntry:
    """The entry read from one line after the header.

    Args:
        text: the line, with or without its newline.
        lineno: its 1-based line number, for messages.
        previous_t: the previous entry's t, when known: a smaller t is an error.
        devices: the device ids known so far (the header's and earlier ``device`` lines'), when known: a ``hid``
            line naming another device is an error. The caller adds the ids of a `DeviceEntry` returned.
        warnings: when given, one message per unknown key (which is ignored) is appended.

    Raises:
        JournalError: ``line <lineno>: ...`` naming the key and what was expected.

    >>> decode_line('{"t":1.5,"say":"label ball"}', 3)
    SayEntry(t=1.5, text='label ball')
    >>> decode_line('{"t":1.5}', 4)
    Traceback (most recent call last):
    ...
    physink_tui.errors.JournalError: line 4: expected exactly one of hid, pen, cmd, say, device; found none
    """
    where = at(f"line {lineno}")
    obj = parse_object(text, where)
    found = [k for k in value_checks.KINDS if k in obj]
    if len(found) != 1:
        raise value_checks.kinds_error(where, found)
    kind = found[0]
    t = value_checks.seconds(
        where, "t", get(obj, where, "t", "t", value_checks.SECONDS_EXPECTED), previous_t
    )
    if warnings is not None and len(obj) > 2:
        warnings.extend(where.unknown_key(key) for key in obj if key not in _ALLOWED[kind])
    value = obj[kind]
    if kind == "pen":
        return _decode_pen(where, t, value, warnings)
    if kind == "hid":
        data = value_checks.hex_bytes(where, "hid", value)
        dev = checks.text(where, "dev", get(obj, where, "dev", "dev", "a device id of the header"), empty=False)
        return HidEntry(t, _device(where, dev, devices), data)
    if kind == "device":
        return DeviceEntry(t, tuple(decode_devices(where, value, warnings, "device")))
    if kind == "cmd":
        args = value_checks.command(where, value, get(obj, where, "args", "args", "a list of arguments"))
        project = _embedded_project(where, value, obj.get("project"), "project" in obj, warnings)
        return CommandEntry(t, value, args, project)
    return SayEntry(t, checks.text(where, "say", value))


def _decode_pen(where: Place, t: float, pen: Any, warnings: list[str] | None) -> PenEntry:
    if not isinstance(pen, dict):
        raise bad(where, "pen", _PEN_EXPECTED, pen)
    try:
        x, y, p, tip, in_range, eraser, b1, b2 = (pen[k] for k in PEN_KEYS)
    except KeyError:
        key = next(k for k in PEN_KEYS if k not in pen)
        raise bad(where, f"pen.{key}", "a number in [0, 1]" if key in "xyp" else "true or false") from None
    if warnings is not None and len(pen) > len(PEN_KEYS):
        warnings.extend(where.unknown_key(f"pen.{k}") for k in pen if k not in PEN_KEYS)
    unit, flag = checks.unit, checks.flag
    return PenEntry(
        t,
        unit(where, "pen.x", x),
        unit(where, "pen.y", y),
        unit(where, "pen.p", p),
        flag(where, "pen.tip", tip),
        flag(where, "pen.range", in_range),
        flag(where, "pen.eraser", eraser),
        flag(where, "pen.b1", b1),
        flag(where, "pen.b2", b2),
    )
