"""The label -> kind table (`label_kinds.tsv`): which of the program's kinds count as right for a drawn label of each
public stroke set; read once, checked, never changed by a scoring run.

>>> table = read_table()
>>> sorted(table.accepts("dollar1", "circle")), table.label_class("bouchal", "diamond")
(['circle', 'ellipse'], 'quad')
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

TABLE = Path(__file__).resolve().parent / "label_kinds.tsv"
UNMAPPED = "-"


@dataclass(frozen=True)
class LabelTable:
    """Per (set, label) its class (or `UNMAPPED`); per class the kinds it accepts."""

    classes: dict[tuple[str, str], str]
    kinds: dict[str, frozenset[str]]

    def label_class(self, set_name: str, label: str) -> str | None:
        """The label's class, `UNMAPPED` for a label no kind stands for, None for a label not in the table."""
        return self.classes.get((set_name, label))

    def accepts(self, set_name: str, label: str) -> frozenset[str]:
        return self.kinds[self.classes[(set_name, label)]]

    def of_set(self, set_name: str) -> dict[str, str]:
        """label -> class for one set's mapped labels."""
        return {label: c for (s, label), c in self.classes.items() if s == set_name and c != UNMAPPED}


def read_table(path: Path = TABLE) -> LabelTable:
    """The table at ``path``.

    Raises:
        ValueError: a line without five fields, or a class given two different sets of kinds (named by line).
    """
    classes: dict[tuple[str, str], str] = {}
    kinds: dict[str, frozenset[str]] = {}
    lines = path.read_text(encoding="utf-8").splitlines()
    for number, line in enumerate(lines, 1):
        if not line.strip() or line.startswith("#") or line.startswith("set\t"):
            continue
        fields = line.split("\t")
        if len(fields) != 5:
            raise ValueError(f"{path}:{number}: expected 5 tab-separated fields, got {len(fields)}: {line!r}")
        set_name, label, cls, accepts, _why = fields
        if (set_name, label) in classes:
            raise ValueError(f"{path}:{number}: {set_name} {label!r} is listed twice")
        classes[(set_name, label)] = cls
        if cls == UNMAPPED:
            continue
        accepted = frozenset(accepts.split(","))
        if kinds.setdefault(cls, accepted) != accepted:
            raise ValueError(f"{path}:{number}: class {cls!r} accepts {sorted(accepted)} here but "
                             f"{sorted(kinds[cls])} above")
    return LabelTable(classes, kinds)
