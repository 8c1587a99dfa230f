"""The journal's ``load`` (with the loaded project embedded) and ``end`` commands, both ways, and their errors."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from physink_tui.errors import JournalError, SceneError
from physink_tui.formats.journal.codec import decode_line, encode_entry
from physink_tui.formats.journal.entries import CommandEntry, JournalDevice, JournalHeader
from physink_tui.formats.journal.reader import read_journal
from physink_tui.formats.journal.writer import JournalWriter
from physink_tui.formats.json_checks import Place
from physink_tui.formats.project.codec import Project, decode_project_object, encode_project
from physink_tui.scene.components import MATERIALS, Body, Scene

BALL = Body("b1", "circle", (), 20.0, (100.0, 50.0), 0.0, MATERIALS["round"], "ball")
PROJECT = json.loads(encode_project(Project(Scene({"b1": BALL}, {"b": 2}), ("verb plummets",), None, (800.0, 600.0))))
HEADER = JournalHeader(800, 600, (JournalDevice("tablet0", None, 3, 0x256C, 0x6E, b"\xa1\xc0"),), {}, 0.05, 0.01)


def test_load_with_its_project_and_end_round_trip_byte_identically() -> None:
    load = CommandEntry(1.5, "load", ("machine.physink.json",), PROJECT)
    end = CommandEntry(9.0, "end")

    line = encode_entry(load)

    assert line.startswith('{"t":1.5,"cmd":"load","args":["machine.physink.json"],"project":{"format":')
    assert decode_line(line, 2) == load and encode_entry(decode_line(line, 2)) == line
    assert encode_entry(end) == '{"t":9.0,"cmd":"end","args":[]}' and decode_line(encode_entry(end), 3) == end
    back = decode_project_object(decode_line(line, 2).project, Place("m.physink.json", SceneError))
    assert back.scene.components["b1"] == BALL


def test_a_written_journal_with_load_and_end_reads_back_equal(tmp_path: Path) -> None:
    path = tmp_path / "s.physink.jsonl"
    entries = [CommandEntry(0.5, "load", ("m.physink.json",), PROJECT), CommandEntry(4.0, "end")]
    with JournalWriter.create(path, HEADER) as writer:
        for entry in entries:
            writer.append(entry)

    assert list(read_journal(path).entries) == entries


def test_a_load_without_its_project_is_an_error_naming_the_line() -> None:
    with pytest.raises(JournalError, match=r'^line 4: key "project": expected the loaded project\'s JSON object '
                                           r"\(a replay needs the project embedded\), but it is missing$"):
        decode_line('{"t":1,"cmd":"load","args":["m.physink.json"]}', 4)
    with pytest.raises(JournalError, match=r"^cmd entry: .*a replay needs the project embedded"):
        encode_entry(CommandEntry(1.0, "load", ("m.physink.json",)))


@pytest.mark.parametrize(("change", "message"), [
    (lambda p: p["canvas"].update(width=-1), 'line 7: key "project": canvas.width: expected a number > 0, got -1'),
    (lambda p: p["components"][0].update(radius="big"),
     'line 7: key "project": components[0].radius: expected a number > 0, got "big"'),
    (lambda p: p.update(version=3), 'line 7: key "project" was written by format version 3; this program reads '
                                    "version 2"),
])
def test_a_bad_embedded_project_is_named_by_the_line_and_its_field(change, message: str) -> None:
    project = json.loads(json.dumps(PROJECT))
    change(project)
    line = json.dumps({"t": 1.0, "cmd": "load", "args": ["m.physink.json"], "project": project})
    with pytest.raises(JournalError, match="^" + message.replace("[", r"\[").replace("]", r"\]")):
        decode_line(line, 7)


def test_only_load_embeds_a_project_and_end_takes_no_arguments() -> None:
    with pytest.raises(JournalError, match=r'line 2: key "project": expected nothing: only "load" embeds a project'):
        decode_line('{"t":1,"cmd":"save","args":["a"],"project":{}}', 2)
    with pytest.raises(JournalError, match=r'line 3: key "args": expected no arguments for "end", got \["now"\]'):
        decode_line('{"t":1,"cmd":"end","args":["now"]}', 3)


def test_a_bad_load_line_in_a_file_names_the_file_and_the_line(tmp_path: Path) -> None:
    path = tmp_path / "s.physink.jsonl"
    with JournalWriter.create(path, HEADER) as writer:
        writer.append(CommandEntry(0.5, "end"))
    with path.open("a", encoding="utf-8") as f:
        f.write('{"t":1,"cmd":"load","args":["m.physink.json"]}\n')
    with pytest.raises(JournalError, match=rf"^{path}: line 3: key \"project\": .*a replay needs the project embedded"):
        read_journal(path)
