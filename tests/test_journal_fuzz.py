"""Fuzzing journals: a valid journal with one value mutated is read and replayed, or refused with a JournalError."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from physink_tui.errors import JournalError
from physink_tui.formats.journal.reader import read_journal
from physink_tui.input.journal_replay import replay_journal_input
from physink_tui.session.session import Session

JOURNALS = Path(__file__).resolve().parent / "journals"
HEADER = json.loads((JOURNALS / "basketball.physink.jsonl").read_text().partition("\n")[0])
HEADER["vocabulary"] = "verb topples\nprep amid"
PEN = {"x": 0.25, "y": 0.75, "p": 0.5, "tip": True, "range": True, "eraser": False, "b1": False, "b2": False}
VALID: list[dict[str, Any]] = [
    HEADER,
    {"t": 0.0, "hid": "07 40 eb 07 9a 0e 00 00", "dev": "tablet0"},
    {"t": 0.01, "hid": "07 41 eb 07 9a 0e 80 00", "dev": "tablet0"},
    {"t": 0.2, "device": {"tablet1": HEADER["devices"]["tablet0"]}},
    {"t": 0.3, "hid": "07 41 eb 07 9a 0e 80 00", "dev": "tablet1"},
    {"t": 0.5, "pen": PEN},
    {"t": 0.6, "pen": {**PEN, "x": 0.5}},
    {"t": 0.8, "cmd": "seek", "args": [1.5]},
    {"t": 0.9, "cmd": "label", "args": ["last", "ball"]},
    {"t": 1.0, "say": "label ball"},
]

JUNK_LEAVES = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(min_value=-(2**70), max_value=2**70),
    st.sampled_from([0, -1, 1, 2, 65535, 65536, 10**400, -(10**400), 1e308, -1e308, 5e-324, 1e-300,
                     math.nan, math.inf, -math.inf, 0.5, 90, 270]),
    st.floats(),
    st.text(max_size=8),
    st.sampled_from(["", "0", "1.5", "07 40", "zz", "tablet0", "\ud800", "demo", "verb", "noun egg", "05 01 c0"]),
)
JUNK = st.recursive(
    JUNK_LEAVES,
    lambda inner: st.lists(inner, max_size=4) | st.dictionaries(st.text(max_size=6), inner, max_size=3),
    max_leaves=8,
)
DELETE = object()


def _paths(node: Any, path: tuple[Any, ...] = ()) -> list[tuple[Any, ...]]:
    """Every place in a JSON value: its own path and those of everything inside it."""
    out = [path]
    if isinstance(node, dict):
        for key, value in node.items():
            out += _paths(value, (*path, key))
    elif isinstance(node, list):
        for i, value in enumerate(node):
            out += _paths(value, (*path, i))
    return out


@st.composite
def mutated_journal(draw: st.DrawFn) -> list[Any]:
    """The valid journal with 1 to 3 values replaced by junk, deleted, or given a junk key, anywhere in a line
    (the header half the time, since it has the most to check)."""
    rows = json.loads(json.dumps(VALID))
    for _ in range(draw(st.integers(1, 3))):
        index = 0 if draw(st.booleans()) else draw(st.integers(1, len(rows) - 1))
        path = draw(st.sampled_from(_paths(rows[index])))
        action = draw(st.sampled_from(["replace", "replace", "replace", "delete", "add"]))
        if not path:
            if action == "replace":
                rows[index] = draw(JUNK)
            elif action == "add" and isinstance(rows[index], dict):
                rows[index][draw(st.text(max_size=6))] = draw(JUNK)
            continue
        parent = rows[index]
        for key in path[:-1]:
            parent = parent[key]
        key = path[-1]
        if action == "delete" and isinstance(parent, dict):
            del parent[key]
        elif action == "add" and isinstance(parent[key], dict):
            parent[key][draw(st.text(max_size=6))] = draw(JUNK)
        else:
            parent[key] = draw(JUNK)
    return rows


def _text(rows: list[Any]) -> bytes:
    lines = []
    for row in rows:
        try:
            lines.append(json.dumps(row, ensure_ascii=False).encode("utf-8", "surrogatepass"))
        except ValueError:  # a number too long for str(): leave the line as the digits would read
            lines.append(b'{"t":1' + b"0" * 5000 + b',"say":"x"}')
    return b"\n".join(lines) + b"\n"


@pytest.fixture(scope="module")
def folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("fuzz")


@settings(max_examples=2000, derandomize=True, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(mutated_journal())
def test_a_mutated_journal_is_replayed_or_refused_with_a_journal_error(folder: Path, rows: list[Any]) -> None:
    path = folder / "fuzz.physink.jsonl"
    path.write_bytes(_text(rows))
    try:
        journal = read_journal(path)
        replay_journal_input(path)
        Session.from_header(journal.header)
    except JournalError as exc:
        message = str(exc)
        assert message.startswith(str(path)) and "\n" not in message, message
