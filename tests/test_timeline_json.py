"""The timeline JSON codec: what it encodes decodes to an equal Timeline; versions and their migration."""

from __future__ import annotations

import json

import pytest

from physink_tui.formats.timeline_json import FORMAT, FORMAT_VERSION, decode_timeline_json, encode_timeline_json
from physink_tui.timeline.events import Event, Timeline, TimelineError, TrajectoryPoint

NAMES = {"b1": "ball", "b2": "paddle", "b3": "cup"}


def timeline() -> Timeline:
    frames = (TrajectoryPoint(0.0, 1.5, 2.25, 0.0, 0.125, -3.0), TrajectoryPoint(0.5, 1.75, 2.5, 0.1, 0.25, -2.5))
    return Timeline((
        Event("e1", "start"),
        Event("e2", "movement", ("b1", "b3"), ("e1",), 0.0, 0.5, "the ball falls", (), (("b2", ("above", "left")),),
              frames, None, (("b3", frames),)),
        Event("e3", "contact", ("b1", "b2"), ("e2",), 0.5, 0.5, None, (("b1", "bottom"), ("b2", "top")), (), (),
              (1.5, 2.5)),
        Event("e4", "end_contact", ("b1", "b2"), ("e3",), 0.75, 0.75),
    ))


def test_decoding_what_was_encoded_gives_an_equal_timeline_and_the_names() -> None:
    text = encode_timeline_json(timeline(), NAMES)
    back, names = decode_timeline_json(text)
    assert back == timeline()
    assert names == NAMES
    assert encode_timeline_json(back, names) == text


def test_the_file_carries_its_format_and_version_first() -> None:
    doc = json.loads(encode_timeline_json(timeline(), NAMES))
    assert list(doc)[:2] == ["format", "version"] and (doc["format"], doc["version"]) == (FORMAT, FORMAT_VERSION)


def test_an_unversioned_file_of_before_reads_as_version_0() -> None:
    doc = json.loads(encode_timeline_json(timeline(), NAMES))
    del doc["format"], doc["version"]
    assert decode_timeline_json(json.dumps(doc)) == (timeline(), NAMES)


def test_a_newer_version_is_refused_naming_both_versions() -> None:
    with pytest.raises(TimelineError, match=r"written by timeline format version 2; this program reads version 1"):
        decode_timeline_json('{"format": "physink-timeline", "version": 2, "events": []}')


@pytest.mark.parametrize(("doc", "fragment"), [
    ('{"format": "physink-timeline", "events": []}', "version: expected an integer from 1 to 1, but it is missing"),
    ('{"format": "other", "version": 1, "events": []}', 'format: expected "physink-timeline", got "other"'),
    ('{"format": "physink-timeline", "version": true, "events": []}', "version: expected an integer from 1 to 1"),
])
def test_a_bad_format_or_version_is_named(doc: str, fragment: str) -> None:
    with pytest.raises(TimelineError, match=fragment):
        decode_timeline_json(doc)
