"""The spoken-command grammar: its words, its JSGF, its parser, and vocabulary files naming components."""

from __future__ import annotations

import pytest

from physink_tui.input.speech.grammar import DEFAULT_COMPONENTS, LabelCommand, PhraseCommand, SpeechGrammar
from physink_tui.timeline.phrases import DEFAULT_VOCABULARY, PhraseError, parse_vocabulary

GRAMMAR = SpeechGrammar.build(["Paddle A", "the ramp"], DEFAULT_VOCABULARY)


@pytest.mark.parametrize(("text", "command"), [
    ("label ball", LabelCommand("ball")),
    ("Label frying pan.", LabelCommand("frying pan")),
    ("label paddle a", LabelCommand("paddle a")),
    ("the ball falls", PhraseCommand("the ball falls", "ball", "falls", None, None)),
    ("ball hits paddle a", PhraseCommand("ball hits paddle a", "ball", "hits", None, "paddle a")),
    ("the egg lands in the frying pan",
     PhraseCommand("the egg lands in the frying pan", "egg", "lands", "in", "frying pan")),
    ("the ball rolls out of the basket",
     PhraseCommand("the ball rolls out of the basket", "ball", "rolls", "out of", "basket")),
    ("the egg lands in pan", PhraseCommand("the egg lands in pan", "egg", "lands", "in", "pan")),
])
def test_sentences_of_the_grammar_parse_to_their_command(text: str, command: object) -> None:
    assert GRAMMAR.parse(text) == command


@pytest.mark.parametrize("text", [
    "", "label", "label the ball", "the the ball falls", "ball", "the ball", "ball falls the",
    "the ball falls in the", "the egg lands in the frying", "ball hits in on pan", "what time is it",
    "label elephant", "the ball falls the the pan", "ball hits paddle a now",
])
def test_anything_else_is_no_command(text: str) -> None:
    assert GRAMMAR.parse(text) is None


def test_jsgf_never_allows_an_article_on_both_sides_and_lists_every_name() -> None:
    jsgf = GRAMMAR.jsgf()
    assert "public <command> = <label> | <event>;" in jsgf
    assert "<event> = [the] <component> <verb> [[<prep>] [the] <component>];" in jsgf
    assert "<label> = label <component>;" in jsgf
    component_rule = next(line for line in jsgf.splitlines() if line.startswith("<component> ="))
    assert "frying pan" in component_rule and "paddle a" in component_rule
    assert "[the]" not in component_rule  # "the ramp" was normalised away as a label starting with an article
    with_garbage = GRAMMAR.jsgf(["gbaa", "gbb"], 0.01)
    assert "| /0.01/ <garbage>+;" in with_garbage and "<garbage> = gbaa | gbb;" in with_garbage


def test_words_the_recogniser_cannot_say_are_left_out_and_listed() -> None:
    grammar = SpeechGrammar.build(["zorblax", "blue zorblax", "ball"], DEFAULT_VOCABULARY,
                                  speakable=lambda word: word != "zorblax")
    assert "zorblax" in grammar.unspeakable and "blue zorblax" in grammar.unspeakable
    assert "zorblax" not in grammar.words()
    assert grammar.parse("label zorblax") is None
    assert grammar.parse("label ball") == LabelCommand("ball")


def test_default_components_include_the_issue_list() -> None:
    assert {"ball", "platform", "knife", "egg", "paddle", "pan", "frying pan", "basket", "rope", "spring", "cup",
            "peg"} <= DEFAULT_COMPONENTS


def test_vocabulary_files_name_components_for_the_grammar() -> None:
    words = parse_vocabulary("component Golf Ball, skillet\nverb plummets\n")
    assert words.components == frozenset({"golf ball", "skillet"})
    grammar = SpeechGrammar.build([], DEFAULT_VOCABULARY.extended(words))
    assert grammar.parse("the golf ball plummets into the skillet") == PhraseCommand(
        "the golf ball plummets into the skillet", "golf ball", "plummets", "into", "skillet")
    with pytest.raises(PhraseError, match=r"<vocabulary>:1: .*is an article"):
        parse_vocabulary("component the ball\n")
    with pytest.raises(PhraseError, match="component names separated by commas"):
        parse_vocabulary("component ball,,cup\n")
