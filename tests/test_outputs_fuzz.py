"""Fuzz (hypothesis, derandomized): mutated project and timeline files and `recognize` lines give a result or one
`physink:` line on stderr, never a traceback, NaN or Infinity."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from physink_tui.cli import main

JOURNAL = Path(__file__).resolve().parent / "journals" / "bouncing_below_b.physink.jsonl"
def fuzz(examples: int) -> settings:
    return settings(derandomize=True, deadline=None, suppress_health_check=list(HealthCheck), database=None,
                    max_examples=examples)

VALUES = st.recursive(
    st.none() | st.booleans() | st.integers(min_value=-(10**400), max_value=10**400)
    | st.sampled_from([float("nan"), float("inf"), -float("inf"), 1e308, -0.0, 1e-320]) | st.floats()
    | st.text(max_size=8) | st.sampled_from(["contact", "movement", "top", "above", "e1", "b1"]),
    lambda children: st.lists(children, max_size=3) | st.dictionaries(st.text(max_size=6), children, max_size=3),
    max_leaves=6,
)


def _paths(doc: Any, prefix: tuple = ()) -> list[tuple]:
    out = [prefix]
    if isinstance(doc, dict):
        for k, v in doc.items():
            out += _paths(v, (*prefix, k))
    elif isinstance(doc, list):
        for i, v in enumerate(doc[:3]):
            out += _paths(v, (*prefix, i))
    return out


def _mutate(doc: Any, path: tuple, value: Any, delete: bool) -> Any:
    if not path:
        return value
    parent = doc
    for key in path[:-1]:
        parent = parent[key]
    if delete and isinstance(parent, dict):
        del parent[path[-1]]
    else:
        parent[path[-1]] = value
    return doc


@pytest.fixture(scope="module")
def valid(tmp_path_factory) -> dict[str, Any]:
    out = tmp_path_factory.mktemp("valid")
    assert main(["replay", str(JOURNAL), "--out", str(out)]) == 0
    timeline = json.loads((out / "timeline.json").read_text())
    for ev in timeline["events"]:  # small documents: more mutations per second
        ev["trajectory"] = ev["trajectory"][:2]
        for track in ev["tracks"]:
            track["trajectory"] = track["trajectory"][:2]
    project = json.loads((out / "project.json").read_text())
    project["timeline"] = timeline
    return {"timeline": timeline, "project": project}


def _check(capsys, argv: list[str]) -> None:
    status = main(argv)  # an exception escaping main is the failure this test looks for
    out, err = capsys.readouterr()
    assert status in (0, 1), (argv, status, err)
    if status == 1:
        assert err.startswith("physink: ") and err.count("\n") == 1, err
    assert "NaN" not in out and "Infinity" not in out and " nan" not in out and " inf" not in out, out


@pytest.mark.parametrize("kind", ["timeline", "project"])
def test_mutated_files_give_a_result_or_one_line(valid, tmp_path, capsys, kind: str) -> None:
    doc0 = valid[kind]
    paths = _paths(doc0)
    target = tmp_path / f"fuzz.{kind}.json"

    forms = st.sampled_from(["json", "dot", "text", "equiv", "equiv-text"])

    @fuzz(600)
    @given(st.sampled_from(paths), VALUES, st.booleans(), forms)
    def case(path: tuple, value: Any, delete: bool, form: str) -> None:
        doc = _mutate(json.loads(json.dumps(doc0)), path, value, delete)
        try:
            text = json.dumps(doc)
        except (ValueError, RecursionError):  # a 10**400 integer beyond the text conversion limit
            return
        target.write_text(text)
        if form.startswith("equiv"):
            _check(capsys, ["equiv", str(target), str(target), *(["--json"] if form == "equiv" else [])])
        else:
            _check(capsys, ["timeline", str(target), "--format", form])

    case()


def test_recognize_lines_give_a_result_or_one_line(tmp_path, capsys) -> None:
    target = tmp_path / "strokes.jsonl"
    point = st.lists(VALUES | st.floats(min_value=-1e3, max_value=1e3), min_size=0, max_size=4)
    line = st.one_of(
        st.binary(max_size=40),
        st.builds(lambda s: json.dumps({"strokes": s}).encode(), st.lists(st.lists(point, max_size=6), max_size=3)),
        st.builds(lambda v: json.dumps(v).encode(), VALUES),
    )

    @fuzz(700)
    @given(line)
    def case(raw: bytes) -> None:
        target.write_bytes(raw.replace(b"\n", b" ") + b"\n")
        _check(capsys, ["recognize", str(target)])

    case()
