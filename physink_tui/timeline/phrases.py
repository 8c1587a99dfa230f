"""Parses user phrases that label timeline events (thesis 3.3.3); speech recognition and timing are left to others.

A phrase follows the thesis's grammar ``<component> <verb> [<preposition>...] [<component>]``: "ball falls",
"the egg lands in the frying pan", "ball hits paddle a", "the ball rolls out of the tube". Matching is
case-insensitive; punctuation at the ends of words (``.,;:!?"``) is ignored; "the", "a" or "an" may stand before
a component. Components are named by their labels (``labels`` maps component id -> label); at each position the
longest label wins ("frying pan" over "pan"), a label that includes an article counts ("paddle a"), and after
the verb a label is tried before a preposition. Verbs and prepositions come from a `Vocabulary`
(`DEFAULT_VOCABULARY`, extended by the user's file, see `parse_vocabulary`). Several prepositions in a row are
kept together ("out of", "down into").

Components that share a label are all kept as candidates (`Phrase.subjects`, `Phrase.objects`);
`phrase_events.nearest_event` picks the event, and so the component, nearest in time.

>>> labels = {"b1": "ball", "b4": "egg", "b6": "frying pan"}
>>> phrase = parse_phrase("The egg lands in the frying pan", labels, DEFAULT_VOCABULARY)
>>> phrase.subject, phrase.verb, phrase.preposition, phrase.object
('b4', 'lands', 'in', 'b6')
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass

from physink_tui.errors import PhysinkError

ARTICLES = frozenset({"the", "a", "an"})
_PUNCTUATION = ".,;:!?\""
_WORD = re.compile(r"[^\W\d_]+(?:['-][^\W\d_]+)*")
_GRAMMAR = "<component> <verb> [<preposition>] [<component>]"


class PhraseError(PhysinkError):
    """A phrase that cannot label an event, or a vocabulary file line that cannot be read.

    Attributes:
        text: the offending phrase, or the vocabulary file's offending line.
        source: the vocabulary file's name, or None for a phrase.
        line: 1-based line number in ``source``, or None for a phrase.
    """

    def __init__(self, message: str, text: str, source: str | None = None, line: int | None = None) -> None:
        self.text = text
        self.source = source
        self.line = line
        where = ":".join(str(p) for p in (source, line) if p is not None)
        super().__init__(f"{where}: {message}" if where else message)


def _check_words(words: Iterable[str], kind: str) -> None:
    for word in words:
        if not _WORD.fullmatch(word) or word != word.lower():
            raise PhraseError(f"{kind} {word!r} is not a single lower-case word of letters, ' and -", word)
        if word in ARTICLES:
            raise PhraseError(f"{kind} {word!r} is an article, which phrases skip; it cannot be a {kind}", word)


def _forms(word: str) -> set[str]:
    """The spellings a verb may have: the word, plus or minus a final ``s``/``es``, and ``y`` <-> ``ies``."""
    forms = {word, word + "s", word + "es"}
    if word.endswith("s"):
        forms.add(word[:-1])
    if word.endswith("es"):
        forms.add(word[:-2])
    if word.endswith("ies"):
        forms.add(word[:-3] + "y")
    if word.endswith("y"):
        forms.add(word[:-1] + "ies")
    return forms


@dataclass(frozen=True, slots=True)
class Vocabulary:
    """The verbs and prepositions phrases may use, and the component names a user may say (for speech).

    A spoken verb matches a vocabulary verb when they are equal or differ by a final ``s`` or ``es``, or ``y``
    against ``ies``: "hit", "hits"; "press", "presses"; "carry", "carries". Other inflections ("hitting",
    "fell") must be listed themselves. Prepositions match exactly.

    Attributes:
        verbs: lower-case single words (letters, ``'`` and ``-``), never an article.
        prepositions: lower-case single words, never an article.
        components: names of components a user may say before labelling anything ("frying pan"): lower-case
            words separated by one space, the first not an article. Phrases name components by their labels;
            these only widen what a speech grammar listens for.
    """

    verbs: frozenset[str] = frozenset()
    prepositions: frozenset[str] = frozenset()
    components: frozenset[str] = frozenset()

    def __post_init__(self) -> None:
        _check_words(self.verbs, "verb")
        _check_words(self.prepositions, "preposition")
        for name in self.components:
            words = name.split(" ")
            _check_words([w for w in words[1:] if w not in ARTICLES], "component word")
            _check_words(words[:1], "component name's first word")

    def extended(self, other: Vocabulary) -> Vocabulary:
        """Both vocabularies' words together (e.g. `DEFAULT_VOCABULARY` extended by the user's file)."""
        return Vocabulary(self.verbs | other.verbs, self.prepositions | other.prepositions,
                          self.components | other.components)

    def is_verb(self, word: str) -> bool:
        """Whether the lower-case ``word`` is one of the verbs, allowing for the inflections above."""
        return not _forms(word).isdisjoint(self.verbs)


DEFAULT_VOCABULARY = Vocabulary(
    verbs=frozenset("""
        hits falls moves lands rolls drops bounces pushes pulls slides swings rotates turns strikes knocks
        releases lifts presses cracks tips spins stops launches hangs rises flies tees dispenses weighs touches
        breaks catches throws kicks taps topples tilts flips pivots raises lowers opens closes triggers trips
        fires shoots sinks floats enters leaves meets collides bumps crashes pours fills empties spills carries
        holds rests sits stays starts travels goes climbs descends slips pops snaps cuts slices drags winds
        unwinds stretches compresses rocks wobbles shakes sets sends passes reaches jumps glides sweeps scoops
        pokes nudges feeds""".split()),
    prepositions=frozenset("""
        in on from into onto off against through over under toward towards at down up with across along past
        inside outside out of to by behind beside around above below beneath upon within away back near""".split()),
)


def parse_vocabulary(text: str, source: str = "<vocabulary>") -> Vocabulary:
    """The extra words of a user's vocabulary file.

    One entry per line: ``verb`` or ``prep`` and then one or more words, separated by spaces, or ``component``
    and then one or more component names separated by commas (``component frying pan, golf ball``). ``#`` starts a
    comment; blank lines are ignored; keywords and words are case-insensitive and kept lower-case. A bad line
    raises `PhraseError` naming ``source``, the line number, the line and what was expected. Combine the result
    with `DEFAULT_VOCABULARY.extended`.

    >>> extra = parse_vocabulary('''
    ... # Rube Goldberg words the default lacks
    ... verb plummets Topples   # one or more per line
    ... prep amid
    ... component Frying  pan, golf ball
    ... ''')
    >>> sorted(extra.verbs), sorted(extra.prepositions), sorted(extra.components)
    (['plummets', 'topples'], ['amid'], ['frying pan', 'golf ball'])
    """
    verbs: set[str] = set()
    prepositions: set[str] = set()
    components: set[str] = set()
    for number, raw in enumerate(text.splitlines(), start=1):
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        keyword, *words = line.lower().split()
        if keyword not in ("verb", "prep", "component"):
            raise PhraseError(f"{line!r}: expected 'verb WORD...', 'prep WORD...' or 'component NAME, ...', "
                              f"not {line.split()[0]!r}", raw, source, number)
        if keyword == "component":
            names = [" ".join(name.split()) for name in " ".join(words).split(",")]
            if not all(names):
                raise PhraseError(f"{line!r}: expected component names separated by commas", raw, source, number)
            try:
                Vocabulary(components=frozenset(names))
            except PhraseError as error:
                raise PhraseError(f"{line!r}: {error}", raw, source, number) from None
            components.update(names)
            continue
        if not words:
            raise PhraseError(f"{line!r}: expected at least one word after {keyword!r}", raw, source, number)
        kind = "verb" if keyword == "verb" else "preposition"
        try:
            _check_words(words, kind)
        except PhraseError as error:
            raise PhraseError(f"{line!r}: {error}", raw, source, number) from None
        (verbs if kind == "verb" else prepositions).update(words)
    return Vocabulary(frozenset(verbs), frozenset(prepositions), frozenset(components))


@dataclass(frozen=True, slots=True)
class Phrase:
    """A parsed event phrase.

    Attributes:
        subjects: ids of the components with the subject's label, sorted; usually exactly one.
        verb: the verb as spoken, lower-case.
        preposition: the preposition(s) as spoken, lower-case and space-separated, or None.
        objects: ids of the components with the object's label, sorted; empty when no object was spoken.
        text: the phrase as it will be shown: the user's words, whitespace normalised.
        subject_label: the subject's label, lower-case, words separated by one space.
        object_label: the object's label likewise, or None.
    """

    subjects: tuple[str, ...]
    verb: str
    preposition: str | None
    objects: tuple[str, ...]
    text: str
    subject_label: str
    object_label: str | None = None

    @property
    def subject(self) -> str:
        """The subject's component id (the first of `subjects` when components share the label)."""
        return self.subjects[0]

    @property
    def object(self) -> str | None:
        """The object's component id (the first of `objects` when components share the label), or None."""
        return self.objects[0] if self.objects else None


def _words(text: str) -> list[str]:
    return [w for w in (t.strip(_PUNCTUATION).lower() for t in text.split()) if w]


def _label_index(labels: Mapping[str, str]) -> dict[tuple[str, ...], tuple[str, ...]]:
    """Label words -> ids of the components with that label, sorted; empty labels are left out."""
    index: dict[tuple[str, ...], list[str]] = {}
    for component, label in labels.items():
        key = tuple(_words(label or ""))
        if key:
            index.setdefault(key, []).append(component)
    return {key: tuple(sorted(ids)) for key, ids in index.items()}


class _Parser:
    """One phrase being parsed: its words, the labels and vocabulary, and the messages for what goes wrong."""

    def __init__(self, text: str, labels: Mapping[str, str], vocabulary: Vocabulary) -> None:
        self.text = " ".join(text.split())
        self.words = _words(text)
        self.index = _label_index(labels)
        self.longest = max((len(k) for k in self.index), default=0)
        self.vocabulary = vocabulary

    def fail(self, message: str) -> PhraseError:
        return PhraseError(f"{self.text!r}: {message}", self.text)

    def known_labels(self) -> str:
        names = sorted({" ".join(key) for key in self.index})
        return "labelled components: " + ", ".join(names)

    def label_at(self, pos: int) -> tuple[int, tuple[str, ...]] | None:
        """(end, key) of the longest label starting at ``pos``, or None."""
        for n in range(min(self.longest, len(self.words) - pos), 0, -1):
            key = tuple(self.words[pos:pos + n])
            if key in self.index:
                return pos + n, key
        return None

    def component_at(self, pos: int) -> tuple[int, tuple[str, ...]] | None:
        """(end, key) of the component named at ``pos``, perhaps after an article; the longer match wins."""
        plain = self.label_at(pos)
        if pos < len(self.words) and self.words[pos] in ARTICLES:
            after = self.label_at(pos + 1)
            if after is not None and (plain is None or after[0] > plain[0]):
                return after
        return plain

    def unknown_name(self, start: int, stop: int) -> str:
        words = self.words[start:stop]
        return " ".join(words[1:] if words and words[0] in ARTICLES else words)

    def subject(self) -> tuple[int, tuple[str, ...]]:
        found = self.component_at(0)
        if found is not None:
            return found
        verb_at = next((i for i, w in enumerate(self.words) if self.vocabulary.is_verb(w)), None)
        name = self.unknown_name(0, verb_at) if verb_at is not None else ""
        if name:
            raise self.fail(f"no component is called {name!r}; {self.known_labels()}")
        raise self.fail(f"expected a component's label at the start ({_GRAMMAR}); {self.known_labels()}")

    def verb(self, pos: int, subject: str) -> str:
        verbs = ", ".join(sorted(self.vocabulary.verbs))
        if pos == len(self.words):
            raise self.fail(f"expected a verb after {subject!r}; known verbs: {verbs}")
        word = self.words[pos]
        if not self.vocabulary.is_verb(word):
            raise self.fail(f"{word!r} after {subject!r} is not a known verb (a vocabulary file line "
                            f"'verb {word}' adds it); known verbs: {verbs}")
        return word

    def rest(self, pos: int) -> tuple[list[str], tuple[str, ...] | None]:
        """The prepositions and the object's label key (or None) from ``pos`` to the end of the phrase."""
        prepositions: list[str] = []
        while pos < len(self.words):
            found = self.component_at(pos)
            if found is not None:
                end, key = found
                if end < len(self.words):
                    raise self.fail(f"unexpected {' '.join(self.words[end:])!r} after {' '.join(key)!r}; "
                                    f"a phrase ends with its second component ({_GRAMMAR})")
                return prepositions, key
            word = self.words[pos]
            if word not in self.vocabulary.prepositions:
                raise self.unknown_at(pos)
            prepositions.append(word)
            pos += 1
        return prepositions, None

    def unknown_at(self, pos: int) -> PhraseError:
        """The error for a word after the verb that is neither a preposition nor the start of a label."""
        word = self.words[pos]
        after = pos + 1
        while after < len(self.words) and self.component_at(after) is None and (
                self.words[after] in self.vocabulary.prepositions):
            after += 1
        follows = self.component_at(after)
        if word not in ARTICLES and follows is not None and follows[0] == len(self.words):
            known = ", ".join(sorted(self.vocabulary.prepositions))
            return self.fail(f"{word!r} is not a known preposition (a vocabulary file line 'prep {word}' adds "
                             f"it); known prepositions: {known}")
        name = self.unknown_name(pos, len(self.words))
        if not name:
            return self.fail(f"expected a component's label after {word!r}; {self.known_labels()}")
        if name == word:
            return self.fail(f"{word!r} is neither a component's label nor a known preposition; "
                             f"{self.known_labels()}")
        return self.fail(f"no component is called {name!r}; {self.known_labels()}")

    def parse(self) -> Phrase:
        if not self.words:
            raise self.fail(f"the phrase is empty; expected {_GRAMMAR}, e.g. 'the ball falls'")
        if not self.index:
            raise self.fail("no component has a label yet; label components in sketch mode first")
        end, subject = self.subject()
        verb = self.verb(end, " ".join(subject))
        prepositions, obj = self.rest(end + 1)
        return Phrase(
            subjects=self.index[subject],
            verb=verb,
            preposition=" ".join(prepositions) or None,
            objects=self.index[obj] if obj is not None else (),
            text=self.text,
            subject_label=" ".join(subject),
            object_label=" ".join(obj) if obj is not None else None,
        )


def parse_phrase(text: str, labels: Mapping[str, str], vocabulary: Vocabulary) -> Phrase:
    """The phrase's subject, verb, preposition and object; `PhraseError` with a message for the user if it has none.

    ``labels`` maps component ids to the user's labels. See the module docstring for the grammar.

    >>> parse_phrase("ball hits paddle a", {"b1": "ball", "b2": "paddle a"}, DEFAULT_VOCABULARY).object
    'b2'
    >>> parse_phrase("the egg lands in the skillet", {"b1": "ball", "b4": "egg"}, DEFAULT_VOCABULARY)
    Traceback (most recent call last):
    ...
    physink_tui.timeline.phrases.PhraseError: 'the egg lands in the skillet': no component is called 'skillet'; \
labelled components: ball, egg
    """
    return _Parser(text, labels, vocabulary).parse()
