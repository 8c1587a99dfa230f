"""Guesses an English word's pronunciation from its spelling (ARPAbet phones, as the recognisers' dictionaries
spell them), by rules of our own; looking words up in a dictionary, and deciding whether to trust a guess, is left
to others.

A label the pronouncing dictionary lacks ("zorblax", "grabber") is still sayable with a guessed pronunciation
(issue 16). The rules cover English spelling's regular patterns: consonant digraphs (``sh``, ``ch``, ``th``,
``ph``, ``ng``, ``ck``), soft ``c`` and ``g`` before ``e``/``i``/``y``, vowel digraphs (``ee``, ``oa``, ``ou``,
``igh``), r-coloured vowels (``ar``, ``er``, ``or``), a silent final ``e`` that lengthens the vowel before it
(``tape``), ``-tion``, ``-le``, doubled consonants as one. Irregular words are the dictionary's job.

>>> pronounce("zorblax")
'Z AO R B L AH K S'
>>> pronounce("crate"), pronounce("shelf"), pronounce("thing")
('K R EY T', 'SH EH L F', 'TH IH NG')
>>> pronounce("r2d2") is None
True
"""

from __future__ import annotations

import re

__all__ = ["LETTER_NAMES", "pronounce"]

LETTER_NAMES = {
    "a": "EY", "b": "B IY", "c": "S IY", "d": "D IY", "e": "IY", "f": "EH F", "g": "JH IY", "h": "EY CH", "i": "AY",
    "j": "JH EY", "k": "K EY", "l": "EH L", "m": "EH M", "n": "EH N", "o": "OW", "p": "P IY", "q": "K Y UW",
    "r": "AA R", "s": "EH S", "t": "T IY", "u": "Y UW", "v": "V IY", "w": "D AH B AH L Y UW", "x": "EH K S",
    "y": "W AY", "z": "Z IY",
}
"""How a letter said alone sounds ("paddle b")."""

_WORD = re.compile(r"[a-z]+(?:['-][a-z]+)*")
_VOWELS = frozenset("aeiou")
_SOFT = frozenset("eiy")

# (spelling, phones), tried longest first at each position; "" phones is silent
_CLUSTERS = sorted([
    ("tch", "CH"), ("sch", "S K"), ("igh", "AY"), ("tion", "SH AH N"), ("sion", "ZH AH N"), ("ture", "CH ER"),
    ("ough", "AO"), ("augh", "AO"), ("eigh", "EY"), ("dge", "JH"), ("que", "K"), ("qu", "K W"),
    ("sh", "SH"), ("ch", "CH"), ("th", "TH"), ("ph", "F"), ("wh", "W"), ("ck", "K"), ("ng", "NG"), ("gh", ""),
    ("ee", "IY"), ("ea", "IY"), ("oo", "UW"), ("ou", "AW"), ("ow", "OW"), ("oi", "OY"), ("oy", "OY"),
    ("ai", "EY"), ("ay", "EY"), ("au", "AO"), ("aw", "AO"), ("ei", "EY"), ("ey", "EY"), ("ie", "IY"),
    ("ue", "UW"), ("ew", "UW"), ("oa", "OW"), ("ui", "UW"),
    ("ar", "AA R"), ("er", "ER"), ("ir", "ER"), ("ur", "ER"), ("or", "AO R"), ("yr", "ER"),
], key=lambda rule: -len(rule[0]))
_CONSONANTS = {
    "b": "B", "d": "D", "f": "F", "h": "HH", "j": "JH", "k": "K", "l": "L", "m": "M", "n": "N", "p": "P",
    "q": "K", "r": "R", "s": "S", "t": "T", "v": "V", "w": "W", "x": "K S", "z": "Z",
}
_SHORT = {"a": "AE", "e": "EH", "i": "IH", "o": "AA", "u": "AH"}
_LONG = {"a": "EY", "e": "IY", "i": "AY", "o": "OW", "u": "UW", "y": "AY"}


def pronounce(word: str) -> str | None:
    """ARPAbet phones for ``word`` (lower-case letters, inner ``'`` or ``-``), or None for anything else.

    >>> pronounce("b"), pronounce("paddle"), pronounce("ramp"), pronounce("t-bar"), pronounce("ball's")
    ('B IY', 'P AE D AH L', 'R AE M P', 'T IY B AA R', 'B AO L Z')
    """
    word = word.lower()
    if not _WORD.fullmatch(word):
        return None
    if len(word) == 1:
        return LETTER_NAMES[word]
    phones: list[str] = []
    for part in word.split("-"):  # "t-bar": a letter said by its name; "ball's", "don't": one word
        phones.extend(LETTER_NAMES[part].split() if len(part) == 1 else _with_suffix(part.replace("'", "")))
    return " ".join(phones) or None


_SIBILANTS = frozenset({"S", "Z", "SH", "ZH", "CH", "JH"})
_VOICELESS = frozenset({"P", "T", "K", "F", "TH"})


def _with_suffix(word: str) -> list[str]:
    """Phones of a run of letters, with a plural or verb ending ``-s``/``-es``/``-ies``, ``-ed`` or ``-ing`` said
    after the stem as English says it (``slides`` Z, ``pokes`` S, ``bounces`` IH Z)."""
    if len(word) > 4 and word.endswith("ies"):
        stem = word[:-3]
        return _part(stem) + (["IY", "Z"] if _has_vowel(stem) else ["AY", "Z"])
    if len(word) > 3 and word.endswith("s") and not word.endswith(("ss", "us", "is")):
        phones = _part(word[:-1])
        if not phones:
            return _part(word)
        end = phones[-1]
        return phones + (["IH", "Z"] if end in _SIBILANTS and word.endswith("es") else
                       ["S"] if end in _VOICELESS else ["Z"])
    if len(word) > 4 and word.endswith("ing") and _has_vowel(word[:-3]):
        return [*_part(word[:-3]), "IH", "NG"]
    if len(word) > 4 and word.endswith("ed") and _has_vowel(word[:-2]):
        phones = _part(word[:-2] + ("e" if _silent_final_e(word[:-1]) else ""))
        end = phones[-1] if phones else ""
        return phones + (["IH", "D"] if end in ("T", "D") else ["T"] if end in _VOICELESS | _SIBILANTS else ["D"])
    return _part(word)


def _part(word: str) -> list[str]:
    """Phones of a run of letters."""
    out: list[str] = []
    silent_e = _silent_final_e(word)
    stem = word[:-1] if silent_e else word
    i = 0
    while i < len(stem):
        rest = stem[i:]
        prev = stem[i - 1] if i else ""
        if prev == rest[0] and rest[0] not in _VOWELS:  # doubled consonant: one sound
            i += 1
            continue
        if i == 0 and rest[:2] in ("kn", "wr", "gn", "ps"):  # silent first letter
            i += 1
            continue
        if rest.startswith("le") and len(rest) == 2 and prev and prev not in _VOWELS:
            out += ["AH", "L"]
            break
        rule = next(((s, p) for s, p in _CLUSTERS if rest.startswith(s)), None)
        if rule is not None and not (rule[0] in ("ea", "ie", "ue") and silent_e and len(rest) == 2):
            out += rule[1].split()
            i += len(rule[0])
            continue
        letter, after = rest[0], word[i + 1:i + 2]  # the silent e still softens c and g ("bounce", "nudge")
        if letter == "c":
            out.append("S" if after in _SOFT else "K")
        elif letter == "g":
            out.append("JH" if after in _SOFT and i > 0 else "G")
        elif letter == "y":
            out.append("Y" if i == 0 else ("IY" if i == len(stem) - 1 and _has_vowel(stem[:i]) else
                                           "AY" if i == len(stem) - 1 else "IH"))
        elif letter == "a" and stem[i + 1:i + 3] in ("ll", "lk", "lt"):
            out.append("AO")
        elif letter == "u" and prev in ("p", "b", "f") and stem[i + 1:i + 3] in ("ll", "sh"):
            out.append("UH")
        elif letter in _VOWELS:
            out.append(_vowel(stem, i, silent_e))
        elif letter == "s" and prev in _VOWELS and after in _VOWELS and i > 1:
            out.append("Z")  # between vowels ("rises", "closes")
        elif letter == "n" and after in ("k", "g"):
            out.append("NG")
        else:
            out += _CONSONANTS[letter].split()
        i += 1
    return out


def _vowel(stem: str, i: int, silent_e: bool) -> str:
    """A single vowel letter: long before one consonant and a silent e ("tape"), or at the end of a one-vowel
    word ("go"), else short."""
    letter = stem[i]
    tail = stem[i + 1:]
    if silent_e and len(tail) == 1 and tail not in _VOWELS:
        return _LONG[letter]
    if not tail and not _has_vowel(stem[:i]):
        return _LONG[letter]
    if not tail:
        return {"a": "AH", "e": "IY", "i": "IY", "o": "OW", "u": "UW"}[letter]
    if letter in "aeo" and _has_vowel(stem[:i]) and not _has_vowel(tail):
        return "AH"  # an unstressed last syllable ("basket", "magnet", "pivot")
    return _SHORT[letter]


def _silent_final_e(word: str) -> bool:
    """Whether ``word`` ends in an e that is not said (after a consonant, with a vowel before it)."""
    return (len(word) > 2 and word.endswith("e") and word[-2] not in _VOWELS and _has_vowel(word[:-2])
            and not word.endswith("le"))


def _has_vowel(letters: str) -> bool:
    return any(c in _VOWELS or c == "y" for c in letters)
