"""User phrases that label timeline events (thesis 2.3.4, 3.3.3): parsing against labels and a vocabulary, the
user's vocabulary file, and finding and relabelling the temporally-nearest event on hand-built timelines."""

from __future__ import annotations

import re

import pytest

from physink_tui.errors import PhysinkError
from physink_tui.timeline.events import Event, Timeline
from physink_tui.timeline.narrate import timeline_text
from physink_tui.timeline.phrase_events import label_event, nearest_event
from physink_tui.timeline.phrases import (
    DEFAULT_VOCABULARY,
    Phrase,
    PhraseError,
    Vocabulary,
    parse_phrase,
    parse_vocabulary,
)

LABELS = {
    "b1": "ball", "b2": "rotating platform", "r1": "rope", "b3": "knife", "b4": "egg", "b5": "paddles",
    "b6": "frying pan", "b8": "Paddle A", "b9": "paddle", "b10": "pan",
}


def parse(text: str, labels: dict[str, str] | None = None, vocabulary: Vocabulary = DEFAULT_VOCABULARY) -> Phrase:
    return parse_phrase(text, LABELS if labels is None else labels, vocabulary)


def parts(phrase: Phrase) -> tuple[str, str, str | None, str | None]:
    return phrase.subject, phrase.verb, phrase.preposition, phrase.object


def mov(eid: str, cause: str, *components: str, t0: float, t1: float) -> Event:
    return Event(eid, "movement", components, (cause,), t0, t1)


def con(eid: str, cause: str, a: str, b: str, t: float, kind: str = "contact") -> Event:
    return Event(eid, kind, (a, b), (cause,), t, t)


def egg_cracker() -> Timeline:
    """The egg cracker (thesis Figure 3-4) with times: each movement lasts until the next contact."""
    return Timeline((
        Event("e1", "start"),
        mov("e2", "e1", "b1", t0=0.0, t1=1.0),
        con("e3", "e2", "b1", "b2", t=1.0),
        mov("e4", "e3", "b1", t0=1.0, t1=2.0),
        mov("e5", "e3", "b2", "r1", "b3", t0=1.0, t1=2.0),
        con("e6", "e5", "b3", "b4", t=2.0),
        mov("e7", "e6", "b3", t0=2.0, t1=2.5),
        mov("e8", "e6", "b4", t0=2.0, t1=3.0),
        con("e9", "e8", "b4", "b5", t=3.0),
        mov("e10", "e9", "b5", t0=3.0, t1=3.5),
        mov("e11", "e9", "b4", t0=3.0, t1=4.0),
        con("e12", "e11", "b4", "b6", t=4.0),
    ))


# --- parsing -----------------------------------------------------------------------------------------------------

@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("ball falls", ("b1", "falls", None, None)),
        ("the ball falls", ("b1", "falls", None, None)),
        ("The egg lands in the frying pan.", ("b4", "lands", "in", "b6")),
        ("the egg lands in the pan", ("b4", "lands", "in", "b10")),
        ("ball hits paddle a", ("b1", "hits", None, "b8")),
        ("ball hits a paddle a", ("b1", "hits", None, "b8")),
        ("the paddle hits a ball", ("b9", "hits", None, "b1")),
        ("PADDLE A hits the ball", ("b8", "hits", None, "b1")),
        ("the knife cracks the egg", ("b3", "cracks", None, "b4")),
        ("an egg   drops   onto  paddles", ("b4", "drops", "onto", "b5")),
        ("the rotating platform tips over", ("b2", "tips", "over", None)),
        ("the egg rolls out of the paddles", ("b4", "rolls", "out of", "b5")),
    ],
)
def test_phrases_parse_into_subject_verb_preposition_object(text: str, expected: tuple) -> None:
    assert parts(parse(text)) == expected


def test_the_text_keeps_the_users_words_with_whitespace_normalised() -> None:
    phrase = parse("  The egg\tlands in   the Frying Pan ")
    assert phrase.text == "The egg lands in the Frying Pan"
    assert (phrase.subject_label, phrase.object_label) == ("egg", "frying pan")
    assert phrase.subjects == ("b4",) and phrase.objects == ("b6",)


def test_the_longest_label_wins_so_frying_pan_beats_pan() -> None:
    assert parse("the frying pan falls").subject == "b6"
    assert parse("the pan falls").subject == "b10"


def test_a_label_that_includes_an_article_is_matched_whole() -> None:
    labels = {"b1": "ball", "b2": "the ramp", "b3": "ramp"}
    assert parse("ball rolls down the ramp", labels).object == "b2"
    assert parse("ball rolls down ramp", labels).object == "b3"


@pytest.mark.parametrize(
    ("spoken", "known"),
    [("hit", "hits"), ("hits", "hit"), ("press", "presses"), ("presses", "press"), ("carry", "carries"),
     ("carries", "carry"), ("falls", "falls")],
)
def test_verbs_match_with_or_without_a_final_s_es_or_ies(spoken: str, known: str) -> None:
    vocabulary = Vocabulary(verbs=frozenset({known}))
    assert parse(f"ball {spoken} egg", vocabulary=vocabulary).verb == spoken


def test_other_inflections_are_not_verbs_unless_listed() -> None:
    with pytest.raises(PhraseError, match="'hitting' after 'ball' is not a known verb"):
        parse("ball hitting egg")


def test_components_sharing_a_label_are_all_candidates() -> None:
    phrase = parse("the ball hits the ball", {"b7": "ball", "b1": "Ball"})
    assert phrase.subjects == ("b1", "b7") and phrase.objects == ("b1", "b7")
    assert phrase.subject == "b1"


# --- parse errors ----------------------------------------------------------------------------------------------

def test_an_unknown_object_lists_the_labels_that_exist() -> None:
    labels = {"b1": "ball", "b4": "egg", "b6": "frying pan", "b3": "knife"}
    with pytest.raises(PhraseError) as info:
        parse("the egg lands in the skillet", labels)
    assert str(info.value) == ("'the egg lands in the skillet': no component is called 'skillet'; "
                               "labelled components: ball, egg, frying pan, knife")
    assert info.value.text == "the egg lands in the skillet"
    assert info.value.source is None and info.value.line is None
    assert isinstance(info.value, PhysinkError)


@pytest.mark.parametrize(
    ("text", "fragment"),
    [
        ("", "the phrase is empty; expected <component> <verb>"),
        ("  . ", "the phrase is empty"),
        ("the skillet falls", "no component is called 'skillet'; labelled components: ball, egg, frying pan"),
        ("falls the ball", "expected a component's label at the start"),
        ("the ball", "expected a verb after 'ball'; known verbs: bounces, breaks"),
        ("the ball plummets into the pan", "'plummets' after 'ball' is not a known verb (a vocabulary file line "
                                           "'verb plummets' adds it); known verbs: bounces"),
        ("the ball falls right into the pan", "'right' is not a known preposition"),
        ("the ball falls sideways", "'sideways' is neither a component's label nor a known preposition; labelled"),
        ("the ball falls amid the pan", "'amid' is not a known preposition (a vocabulary file line 'prep amid' adds "
                                        "it); known prepositions: above, across"),
        ("the ball falls in the big pan", "no component is called 'big pan'"),
        ("the egg lands in the frying pan today", "unexpected 'today' after 'frying pan'; a phrase ends with its "
                                                  "second component"),
        ("ball hits paddle a hard", "unexpected 'hard' after 'paddle a'"),
        ("the ball hits the", "expected a component's label after 'the'"),
    ],
)
def test_bad_phrases_say_what_was_expected(text: str, fragment: str) -> None:
    with pytest.raises(PhraseError, match=re.escape(fragment)):
        parse(text)


def test_a_phrase_before_any_label_says_to_label_components() -> None:
    with pytest.raises(PhraseError, match="no component has a label yet"):
        parse("the ball falls", {"b1": "", "b2": "   "})


# --- the vocabulary file ---------------------------------------------------------------------------------------

def test_a_vocabulary_file_adds_verbs_and_prepositions() -> None:
    text = "# words for my machine\n\nverb plummets Topples  # two on one line\nPREP amid\nverb flings\n"
    vocabulary = parse_vocabulary(text, "words.txt")
    assert vocabulary.verbs == {"plummets", "topples", "flings"}
    assert vocabulary.prepositions == {"amid"}
    assert parse_vocabulary("") == Vocabulary()


@pytest.mark.parametrize(
    ("text", "line", "fragment"),
    [
        ("verb plummets\nnoun skillet\n", 2,
         "'noun skillet': expected 'verb WORD...', 'prep WORD...' or 'component NAME, ...', not 'noun'"),
        ("\n\n  verb   # nothing\n", 3, "'verb': expected at least one word after 'verb'"),
        ("prep amid\n# ok\nprep out_of\n", 3, "'prep out_of': preposition 'out_of' is not a single lower-case word"),
        ("verb hits2\n", 1, "verb 'hits2' is not a single lower-case word"),
        ("verb plummets\nprep the\n", 2, "preposition 'the' is an article"),
        ("verbs: plummets\n", 1, "not 'verbs:'"),
    ],
)
def test_a_bad_vocabulary_line_names_the_file_and_line(text: str, line: int, fragment: str) -> None:
    with pytest.raises(PhraseError) as info:
        parse_vocabulary(text, "words.txt")
    assert str(info.value).startswith(f"words.txt:{line}: ")
    assert fragment in str(info.value)
    assert (info.value.source, info.value.line) == ("words.txt", line)
    assert info.value.text == text.splitlines()[line - 1]


def test_vocabulary_words_are_checked_when_built_directly() -> None:
    with pytest.raises(PhraseError, match="verb 'Hits' is not a single lower-case word"):
        Vocabulary(verbs=frozenset({"Hits"}))


def test_extending_the_default_vocabulary_makes_a_new_verb_work() -> None:
    with pytest.raises(PhraseError, match="'plummets' after 'ball' is not a known verb"):
        parse("the ball plummets amid the paddles")
    vocabulary = DEFAULT_VOCABULARY.extended(parse_vocabulary("verb plummets\nprep amid"))
    assert parts(parse("the ball plummets amid the paddles", vocabulary=vocabulary)) == (
        "b1", "plummets", "amid", "b5")
    assert DEFAULT_VOCABULARY.verbs < vocabulary.verbs
    assert {"hits", "falls", "moves"} <= DEFAULT_VOCABULARY.verbs
    assert {"in", "on", "from"} <= DEFAULT_VOCABULARY.prepositions


# --- finding and labelling the nearest event -------------------------------------------------------------------

@pytest.mark.parametrize(
    ("text", "t", "expected"),
    [
        ("the ball falls", 0.5, "e2"),           # said while the ball moves
        ("the ball falls", 1.5, "e4"),           # its second movement
        ("the ball falls", 1.0, "e2"),           # on the boundary the movement that began earlier wins
        ("the ball falls", 9.0, "e4"),           # long after: the last one
        ("the egg lands in the frying pan", 4.0, "e12"),   # the contact, not the egg's movement
        ("the egg lands in the frying pan", 3.5, "e12"),   # contacts come first even when a movement is nearer
        ("the egg lands on the paddles", 2.2, "e9"),
        ("the ball hits the rotating platform", 0.2, "e3"),
        ("the rotating platform lifts the knife", 1.5, "e5"),  # no contact between them: the shared movement
        ("the knife swings", 1.5, "e5"),         # the knife moves attached to the platform
        ("the knife swings", 2.4, "e7"),         # the knife's own movement
        ("the frying pan stops", 3.0, "e12"),    # no movement of the pan: its contact
    ],
)
def test_the_nearest_event_involving_the_components_is_found(text: str, t: float, expected: str) -> None:
    assert nearest_event(egg_cracker(), parse(text), t) == expected


def test_end_contacts_count_as_contacts() -> None:
    timeline = egg_cracker().add(con("e13", "e12", "b4", "b6", t=6.0, kind="end_contact"))
    assert nearest_event(timeline, parse("the egg bounces off the frying pan"), 5.8) == "e13"
    assert nearest_event(timeline, parse("the egg bounces off the frying pan"), 4.8) == "e12"


def test_equal_events_go_to_the_one_created_first() -> None:
    timeline = Timeline((Event("e1", "start"), mov("e2", "e1", "b1", t0=0.0, t1=1.0),
                         mov("e3", "e1", "b1", t0=0.0, t1=2.0)))
    assert nearest_event(timeline, parse("ball rolls"), 0.5) == "e2"


def test_start_events_and_unrelated_events_are_never_chosen() -> None:
    timeline = Timeline((Event("e1", "start", ("b1",)), mov("e2", "e1", "b4", t0=0.0, t1=1.0)))
    assert nearest_event(timeline, parse("the ball falls"), 0.0) is None
    assert nearest_event(egg_cracker(), parse("the ball hits the frying pan"), 1.0) is None
    assert nearest_event(Timeline(), parse("the ball falls"), 0.0) is None


def test_a_shared_label_resolves_to_the_component_of_the_nearest_event() -> None:
    labels = {"b1": "ball", "b7": "ball"}
    timeline = Timeline((Event("e1", "start"), mov("e2", "e1", "b1", t0=0.0, t1=1.0),
                         mov("e3", "e1", "b7", t0=2.0, t1=3.0)))
    phrase = parse("the ball falls", labels)
    assert nearest_event(timeline, phrase, 0.5) == "e2"
    assert nearest_event(timeline, phrase, 2.5) == "e3"


def test_a_component_does_not_contact_itself() -> None:
    labels = {"b1": "ball", "b2": "basket"}
    timeline = Timeline((Event("e1", "start"), mov("e2", "e1", "b1", t0=0.0, t1=1.0)))
    assert nearest_event(timeline, parse("ball hits ball", labels), 0.5) is None


def test_label_event_relabels_the_nearest_event_only() -> None:
    before = egg_cracker()
    after, event_id = label_event(before, parse("the egg lands in the frying pan"), 4.1)
    assert event_id == "e12"
    assert after.event("e12").label == "the egg lands in the frying pan"
    assert before.event("e12").label is None
    assert [ev.label for ev in after.events if ev.id != "e12"] == [None] * 11
    assert timeline_text(after, LABELS).splitlines()[-1].endswith("- the egg lands in the frying pan")


def test_label_event_without_a_matching_event_names_the_components() -> None:
    labels = {**LABELS, "b11": "basket"}
    with pytest.raises(PhraseError) as info:
        label_event(egg_cracker(), parse("The ball lands in the basket", labels), 2.0)
    assert str(info.value) == "'The ball lands in the basket': no event involves ball and basket yet"
    with pytest.raises(PhraseError, match="no event involves basket yet"):
        label_event(egg_cracker(), parse("the basket tips", labels), 2.0)
