"""The spoken-command grammar (thesis 3.2.5, 3.3.3) as words, JSGF and a parser; decoding audio is left to the backends.

Two sentence shapes::

    label <component>
    [the] <component> <verb> [[<prep> [<prep>]] [the] <component>]

``<component>`` is one of the current labels, the default component names (`DEFAULT_COMPONENTS`) and the names a
vocabulary file adds (``component frying pan``); verbs and prepositions are the phrase vocabulary's
(`physink_tui.timeline.phrases`). An article stands only before a component, never on both sides of a word, so
"the the ball" is no sentence. Words the recogniser's dictionary lacks cannot be said: `SpeechGrammar.build` leaves
out every name with such a word and lists it in ``unspeakable``.

>>> grammar = SpeechGrammar.build(["paddle a"], DEFAULT_VOCABULARY)
>>> grammar.parse("the egg lands in the frying pan").as_json()["object"]
'frying pan'
>>> grammar.parse("label ball").as_json()
{'kind': 'label', 'label': 'ball'}
>>> grammar.parse("ball hits paddle a").as_json()["object"]
'paddle a'
>>> grammar.parse("the the ball falls") is None
True
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import Any

from physink_tui.timeline.phrases import ARTICLES, DEFAULT_VOCABULARY, Vocabulary

__all__ = ["DEFAULT_COMPONENTS", "DEFAULT_VOCABULARY", "LabelCommand", "PhraseCommand", "SpeechGrammar", "normalise"]

DEFAULT_COMPONENTS = frozenset(name.replace("_", " ") for name in """
    ball platform knife egg paddle pan frying_pan basket rope spring cup peg lever ramp pulley box block wheel
    bucket domino marble weight seesaw hammer funnel track floor tee club hoop gear bat magnet base""".split())
"""Things people build machines of, speakable before anything is labelled (thesis 3.2.5's list, widened). Names
that sound like one of them ("bowl", "wall", "string", "bell") are left to vocabulary files: every name in the
grammar is one more thing a mumbled "ball" may become."""


PREPOSITION_PAIRS = ("out of", "down into", "off of", "on top of", "in front of", "next to", "up onto")
"""Prepositions people say as one, spoken together; a grammar of any two in a row lets noise through."""


def normalise(text: str) -> str:
    """Lower-case words separated by one space, punctuation at word ends dropped: how names are compared."""
    return " ".join(w for w in (t.strip('.,;:!?"').lower() for t in text.split()) if w)


@dataclass(frozen=True, slots=True)
class LabelCommand:
    """``label <component>``: name the component the session finds meant (selected, being drawn, hovered).

    Attributes:
        label: the name said, normalised (`normalise`).
    """

    label: str

    @property
    def text(self) -> str:
        return f"label {self.label}"

    def as_json(self) -> dict[str, Any]:
        return {"kind": "label", "label": self.label}


@dataclass(frozen=True, slots=True)
class PhraseCommand:
    """An event phrase: ``[the] subject verb [preps] [[the] object]``; the session labels the nearest event.

    Attributes:
        text: the whole phrase as said, normalised.
        subject: the subject's name.
        verb: the verb.
        preposition: the preposition(s), space-separated, or None.
        object: the object's name, or None.
    """

    text: str
    subject: str
    verb: str
    preposition: str | None
    object: str | None

    def as_json(self) -> dict[str, Any]:
        return {"kind": "phrase", "text": self.text, "subject": self.subject, "verb": self.verb,
                "preposition": self.preposition, "object": self.object}


Command = LabelCommand | PhraseCommand


@dataclass(frozen=True, slots=True)
class SpeechGrammar:
    """What may be said, as sorted tuples of names and words.

    Attributes:
        components: component names (labels, defaults, vocabulary names), normalised, each speakable.
        verbs: verbs, each speakable.
        prepositions: prepositions, each speakable.
        unspeakable: names and words left out because the recogniser cannot say one of their words.
        preferred: the component names the user gave (labels, vocabulary files), favoured over the default names
            when two sound alike.
    """

    components: tuple[str, ...]
    verbs: tuple[str, ...]
    prepositions: tuple[str, ...]
    unspeakable: tuple[str, ...] = ()
    preferred: frozenset[str] = frozenset()

    @classmethod
    def build(cls, labels: Iterable[str], vocabulary: Vocabulary = DEFAULT_VOCABULARY, *,
              defaults: Iterable[str] = DEFAULT_COMPONENTS,
              speakable: Callable[[str], bool] = lambda word: True) -> SpeechGrammar:
        """The grammar for these labels and words; ``speakable(word)`` says whether the recogniser knows a word."""
        labels = list(labels)
        names = {n for n in (normalise(x) for x in (*labels, *defaults, *vocabulary.components)) if n}
        names = {n for n in names if n.split()[0] not in ARTICLES}
        verbs, preps = set(vocabulary.verbs), set(vocabulary.prepositions) | set(PREPOSITION_PAIRS)
        unspeakable = sorted(x for x in names | verbs | preps if not all(speakable(w) for w in x.split()))
        gone = set(unspeakable)
        given = {normalise(x) for x in (*labels, *vocabulary.components)} & (names - gone)
        return cls(tuple(sorted(names - gone)), tuple(sorted(verbs - gone)), tuple(sorted(preps - gone)),
                   tuple(unspeakable), frozenset(given))

    def words(self) -> tuple[str, ...]:
        """Every word a sentence may have, sorted (for a recogniser that takes a word list)."""
        return tuple(sorted({"label", "the", *self.verbs,
                             *(w for n in (*self.prepositions, *self.components) for w in n.split())}))

    def jsgf(self, garbage: Iterable[str] = (), garbage_weight: float = 0.01) -> str:
        """The grammar in JSGF (CMU Sphinx's grammar format); top rule ``<command>``.

        ``garbage`` words (one per phone, say) make a loop that competes with the sentences at ``garbage_weight``
        against 1 for each shape: speech outside the grammar takes the loop rather than being forced into a
        sentence.
        """
        def alternatives(items: Iterable[str]) -> str:
            return " | ".join(items) or "<VOID>"
        garbage = list(garbage)
        top = (f"public <command> = /1/ <label> | /1/ <event> | /{garbage_weight:g}/ <garbage>+;" if garbage else
               "public <command> = <label> | <event>;")
        return "\n".join([
            "#JSGF V1.0;",
            "grammar physink;",
            top,
            *([f"<garbage> = {alternatives(garbage)};"] if garbage else []),
            "<label> = label <component>;",
            "<event> = [the] <component> <verb> [[<prep>] [the] <component>];",
            f"<component> = {alternatives(self.components)};",
            f"<verb> = {alternatives(self.verbs)};",
            f"<prep> = {alternatives(self.prepositions)};",
            "",
        ])

    def parse(self, text: str) -> Command | None:
        """The command ``text`` is a sentence of, or None when it is none (an empty or partial result)."""
        words = normalise(text).split()
        if len(words) >= 2 and words[0] == "label":
            name = " ".join(words[1:])
            return LabelCommand(name) if name in self._names else None
        pos = 1 if words[:1] == ["the"] else 0
        for subject_end in self._name_ends(words, pos):
            if subject_end >= len(words) or words[subject_end] not in self._verbs:
                continue
            found = self._rest(words, subject_end + 1)
            if found is not None:
                preps, obj = found
                return PhraseCommand(" ".join(words), " ".join(words[pos:subject_end]), words[subject_end],
                                     " ".join(preps) or None, obj)
        return None

    @property
    def _names(self) -> frozenset[str]:
        return frozenset(self.components)

    @property
    def _verbs(self) -> frozenset[str]:
        return frozenset(self.verbs)

    def _name_ends(self, words: list[str], pos: int) -> list[int]:
        """The ends of the component names that start at ``pos``, longest first."""
        return [end for end in range(len(words), pos, -1) if " ".join(words[pos:end]) in self._names]

    def _rest(self, words: list[str], pos: int) -> tuple[list[str], str | None] | None:
        """(prepositions, object) for ``words[pos:]``, or None when they are not ``[[<prep> [<prep>]] [the] obj]``."""
        if pos == len(words):
            return [], None
        preps: list[str] = []
        for n in (3, 2, 1):
            if " ".join(words[pos:pos + n]) in self.prepositions:
                preps.append(" ".join(words[pos:pos + n]))
                pos += n
                break
        if words[pos:pos + 1] == ["the"]:
            pos += 1
        name = " ".join(words[pos:])
        if name in self._names:
            return preps, name
        return None
