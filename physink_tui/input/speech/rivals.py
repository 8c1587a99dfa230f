"""The rival sentences of a decoded command: the grammar's sentences that differ from it in exactly one name or the
verb, as JSGF for a recogniser to search; the margin to the best of them is how sure the command is, against the
sentences it is most easily confused with (issue 29). Decoding is the backends'.

>>> from physink_tui.input.speech.grammar import SpeechGrammar
>>> grammar = SpeechGrammar.build(["ball"], defaults=["ball", "marble", "cup"])
>>> print(rival_jsgf(grammar, grammar.parse("label ball")).splitlines()[-1])
public <rival> = label ( cup | marble );
>>> print(rival_jsgf(grammar, grammar.parse("the cup falls")).splitlines()[-1])  # doctest: +ELLIPSIS
public <rival> = ( the ( ball | marble ) falls ) | ( the cup ( bounces | ... | wobbles ) );
>>> differing(("label", "marble"), ("label", "ball"))
[1]
"""

from __future__ import annotations

from collections.abc import Sequence

from physink_tui.input.speech.grammar import Command, LabelCommand, SpeechGrammar


def _choice(items: Sequence[str]) -> str:
    return "( " + " | ".join(items) + " )"


def rival_jsgf(grammar: SpeechGrammar, command: Command) -> str | None:
    """JSGF whose sentences are ``command``'s words with one name (or the verb) replaced by another of the grammar,
    or None when there is no other."""
    if isinstance(command, LabelCommand):
        others = [c for c in grammar.components if c != command.label]
        sentences = [f"label {_choice(others)}"] if others else []
    else:
        words = command.text.split()
        pre = 1 if words[0] == "the" else 0
        verb_at = pre + len(command.subject.split())
        sentences = []
        subjects = [c for c in grammar.components if c != command.subject]
        if subjects:
            sentences.append(" ".join([*words[:pre], _choice(subjects), *words[verb_at:]]))
        verbs = [v for v in grammar.verbs if v != command.verb]
        if verbs:
            sentences.append(" ".join([*words[:verb_at], _choice(verbs), *words[verb_at + 1:]]))
        if command.object is not None:
            n = len(command.object.split())
            objects = [c for c in grammar.components if c != command.object]
            if objects:
                sentences.append(" ".join([*words[:-n], _choice(objects)]))
    if not sentences:
        return None
    body = sentences[0] if len(sentences) == 1 else " | ".join(f"( {s} )" for s in sentences)
    return f"#JSGF V1.0;\ngrammar rival;\npublic <rival> = {body};"


def differing(best: Sequence[str], rival: Sequence[str]) -> list[int]:
    """Positions in ``best``'s words where ``rival`` differs (all of them when their lengths differ)."""
    if len(best) != len(rival):
        return list(range(len(best)))
    return [i for i, (a, b) in enumerate(zip(best, rival, strict=True)) if a != b]
