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
        Event("e1", "start", in_contact=(("b1", "b3"),)),
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
    with pytest.raises(TimelineError, match=r"written by timeline format version 3; this program reads version 2"):
        decode_timeline_json('{"format": "physink-timeline", "version": 3, "events": []}')


@pytest.mark.parametrize(("doc", "fragment"), [
    ('{"format": "physink-timeline", "events": []}', "version: expected an integer from 1 to 2, but it is missing"),
    ('{"format": "other", "version": 1, "events": []}', 'format: expected "physink-timeline", got "other"'),
    ('{"format": "physink-timeline", "version": true, "events": []}', "version: expected an integer from 1 to 2"),
])
def test_a_bad_format_or_version_is_named(doc: str, fragment: str) -> None:
    with pytest.raises(TimelineError, match=fragment):
        decode_timeline_json(doc)


def test_the_start_names_the_pairs_in_contact_by_id_and_label() -> None:
    doc = json.loads(encode_timeline_json(timeline(), NAMES))
    start, *others = doc["events"]
    assert start["in_contact"] == [[{"id": "b1", "label": "ball"}, {"id": "b3", "label": "cup"}]]
    assert start["label"] == "Start (ball and cup in contact)"
    assert all(ev["in_contact"] == [] for ev in others)


@pytest.mark.parametrize(("in_contact", "fragment"), [
    ([["b1"]], r"events\[0\]\.in_contact\[0\]: expected a pair"),
    ([[{"id": "b1"}, {"label": "cup"}]], r"events\[0\]\.in_contact\[0\]\[1\]\.id: expected a string"),
    ("b1 b3", r"events\[0\]\.in_contact: expected a list of pairs"),
])
def test_a_bad_pair_in_contact_is_named_by_its_path(in_contact, fragment: str) -> None:
    doc = json.loads(encode_timeline_json(timeline(), NAMES))
    doc["events"][0]["in_contact"] = in_contact
    with pytest.raises(TimelineError, match=fragment):
        decode_timeline_json(json.dumps(doc))


def test_only_a_start_names_pairs_in_contact() -> None:
    with pytest.raises(TimelineError, match="only the start names pairs in contact"):
        Event("e2", "movement", ("b1",), ("e1",), in_contact=(("b1", "b3"),))
