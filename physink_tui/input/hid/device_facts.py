"""Looks up public facts about tablet models (maxima, report length) by VID:PID and name; decodes nothing.

The table is ``physink_tui/data/device_facts.tsv``, our own format written from the facts in
``/work/shared/data/tablets/tablets.tsv`` (see the file's header). It is used only where a device's
descriptor does not say what it should: the maxima of a vendor-mode report, for example. One
VID:PID often covers many models (Huion 256c:006e covers dozens): then the device's name picks
the model, and where it cannot, the caller infers the maxima from the data and says so.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import cache

FACTS_FILE = "device_facts.tsv"


@dataclass(frozen=True, slots=True)
class DeviceFact:
    """One model's facts.

    Attributes:
        vid, pid: USB ids.
        model: vendor and model, e.g. ``"Gaomon M10K"``.
        report_length: input report length in bytes as the vendor protocol sends it (0 unknown).
        x_max, y_max: logical maxima of X and Y in the vendor protocol.
        p_max: logical maximum of pressure.
        family: the report family the facts name (a parser name in the source data).
    """

    vid: int
    pid: int
    model: str
    report_length: int
    x_max: int
    y_max: int
    p_max: int
    family: str

    @property
    def maxima(self) -> tuple[int, int, int]:
        return (self.x_max, self.y_max, self.p_max)


def parse_facts(text: str) -> tuple[DeviceFact, ...]:
    """Parse the table: ``#`` comments, a header line, then tab-separated rows."""
    facts = []
    lines = [ln for ln in text.splitlines() if ln.strip() and not ln.startswith("#")]
    for line in lines[1:]:
        vid, pid, model, length, x, y, p, family = (line.split("\t") + [""] * 8)[:8]
        if not (x.isdigit() and y.isdigit()):
            continue
        facts.append(DeviceFact(int(vid, 16), int(pid, 16), model, int(length or 0), int(x), int(y),
                                int(p or 0), family))
    return tuple(facts)


@cache
def all_facts() -> tuple[DeviceFact, ...]:
    """The bundled table, read once."""
    from importlib import resources  # here: importing it (pathlib, tempfile) costs every decode's start-up

    return parse_facts(resources.files("physink_tui.data").joinpath(FACTS_FILE).read_text("utf-8"))


def facts_for(vid: int | None, pid: int | None) -> list[DeviceFact]:
    """Every model known under this VID:PID."""
    return [f for f in all_facts() if f.vid == vid and f.pid == pid]


def _model_words(fact: DeviceFact) -> str:
    """The model without its vendor word ("Gaomon M10K" -> "M10K")."""
    parts = fact.model.split(" ", 1)
    return parts[1] if len(parts) == 2 else parts[0]


@dataclass(frozen=True, slots=True)
class FactMatch:
    """What the table says about one device.

    Attributes:
        fact: the model chosen, or None when the table cannot choose.
        why: how it was chosen, or why not, for a warning.
        candidates: how many rows (a model may have several) the table holds for the VID:PID.
    """

    fact: DeviceFact | None
    why: str
    candidates: int


def match_device(vid: int | None, pid: int | None, name: str | None = None) -> FactMatch:
    """Choose a model: the only one under the id, one named in the device name, or all agreeing.

    >>> match_device(0x0543, 0xE668).fact.x_max
    44800
    """
    ids = f"{vid or 0:04x}:{pid or 0:04x}"
    found = facts_for(vid, pid)
    if not found:
        return FactMatch(None, f"no device facts for {ids}", 0)
    if name:
        named = [f for f in found if re.search(rf"(?<!\w){re.escape(_model_words(f))}(?!\w)", name, re.I)]
        named.sort(key=lambda f: -len(_model_words(f)))
        if named and len({f.maxima for f in named if _model_words(f) == _model_words(named[0])}) == 1:
            return FactMatch(named[0], f"device facts for {named[0].model} ({ids}, matched by name)", len(found))
    if len({f.maxima for f in found}) == 1:
        return FactMatch(found[0], f"device facts for {ids} ({found[0].model})", len(found))
    models = len({f.model for f in found})
    return FactMatch(None, f"{models} models with different maxima share {ids}", models)
