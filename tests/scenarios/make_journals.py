"""Records the thesis scenarios (``thesis.py``) and the demonstrations on the ball-and-platforms machine
(``bouncing.py``) with the virtual pen into ``tests/journals/<name>.physink.jsonl``, and the demonstrations kept
from earlier drawings (``restored.py``) into ``tests/journals/restored/``.

Run ``python tests/scenarios/make_journals.py`` after changing a drawing, the virtual pen or the journal
format; the tests check that the stored journals are exactly what this makes. A journal is never
overwritten in place: the old file is deleted first.
"""

from __future__ import annotations

import os
import sys
from functools import cache
from pathlib import Path

from physink_tui.formats.journal.reader import read_journal
from physink_tui.input.journal_compose import capture_entries, header_for_capture, write_journal
from physink_tui.session.session import Session

try:
    from scenarios.bouncing import all_scenarios as bouncing_scenarios
    from scenarios.restored import restored_scenarios
    from scenarios.thesis import MAPPING, Scenario, all_scenarios
except ModuleNotFoundError:  # run as a script: the tests folder is not on the path
    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
    from scenarios.bouncing import all_scenarios as bouncing_scenarios
    from scenarios.restored import restored_scenarios
    from scenarios.thesis import MAPPING, Scenario, all_scenarios

JOURNALS = Path(__file__).resolve().parents[1] / "journals"
RESTORED = JOURNALS / "restored"
"""Demonstrations kept from earlier drawings (`scenarios.restored`), apart from the portfolio's journals."""
SUFFIX = ".physink.jsonl"


def journal_path(scenario: Scenario, folder: str | os.PathLike[str] = JOURNALS) -> Path:
    return Path(folder) / f"{scenario.name}{SUFFIX}"


def write_scenario_journal(scenario: Scenario, path: str | os.PathLike[str]) -> Path:
    """Record the scenario's drawing and write it, with what is said and typed, as a journal at ``path``
    (which must not exist)."""
    capture = scenario.capture()
    write_journal(path, header_for_capture(capture, MAPPING), capture_entries(capture), scenario.spoken_and_typed())
    return Path(path)


@cache
def replayed(scenario_name: str, path: Path) -> Session:
    """The session a stored journal ends in (run once per test process; checked to read cleanly)."""
    assert path.exists(), f"{path} is missing; regenerate with `python tests/scenarios/make_journals.py`"
    journal = read_journal(path)
    assert not journal.warnings and journal.truncated is None, scenario_name
    return Session.from_header(journal.header).run(journal.entries)


def main() -> int:
    JOURNALS.mkdir(parents=True, exist_ok=True)
    for scenario in (*all_scenarios(), *bouncing_scenarios()):
        path = journal_path(scenario)
        path.unlink(missing_ok=True)
        write_scenario_journal(scenario, path)
        print(f"{path}: {path.stat().st_size} bytes, {len(scenario.steps)} strokes")
    RESTORED.mkdir(parents=True, exist_ok=True)
    for scenario in restored_scenarios():
        path = journal_path(scenario, RESTORED)
        path.unlink(missing_ok=True)
        write_scenario_journal(scenario, path)
        print(f"{path}: {path.stat().st_size} bytes, {len(scenario.steps)} strokes")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
