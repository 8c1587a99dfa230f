"""The timeline as the thesis's text (section 2.3.3): each event once, its effects indented beneath it.

    Movement of ball CAUSES
    -- Contact between ball and rotating platform CAUSES
    ---- Movement of ball
    ---- Movement of rotating platform [attached to rope, knife] CAUSES
    ------ Contact between knife and egg CAUSES

An event with effects ends in ``CAUSES``; its effects follow, indented by ``--`` per level of depth. The start
event (the exogenous force) is not printed, as in the thesis: what it causes is listed at the top level. An event
reached from several causes is printed in full the first time, marked ``(#n)``, and later as a reference
``(#n, see above)``. Siblings are listed in creation order, so the text is deterministic.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Mapping

from physink_tui.timeline.events import Timeline, event_label
from physink_tui.timeline.graph import check_acyclic


def _prefix(depth: int) -> str:
    return "--" * depth + " " if depth else ""


def timeline_text(timeline: Timeline, names: Mapping[str, str], show_start: bool = False) -> str:
    """The narrated timeline, one event per line, without a trailing newline.

    ``names`` maps component ids to labels (see `events.default_label`); ``show_start`` prints start events too.
    A timeline holding only start events prints them. Raises `graph.CausalCycleError` on a cyclic timeline.
    """
    check_acyclic(timeline)
    hidden = set() if show_start else {ev.id for ev in timeline.events if ev.type == "start"}
    if len(hidden) == len(timeline):
        hidden = set()

    top: list[str] = []
    for ev in timeline.events:
        if ev.causes:
            continue
        if ev.id in hidden:
            top.extend(c for c in timeline.children(ev.id) if c not in top)
        else:
            top.append(ev.id)

    # How often each event is reached when printing: once per shown cause, plus once if it is listed at the top.
    reached = Counter(top)
    for ev in timeline.events:
        if ev.id not in hidden:
            reached.update(timeline.children(ev.id))

    lines: list[str] = []
    marks: dict[str, int] = {}
    printed: set[str] = set()
    stack = [(e, 0) for e in reversed(top)]
    while stack:
        e, depth = stack.pop()
        label = event_label(timeline.event(e), names)
        if e in printed:
            lines.append(f"{_prefix(depth)}{label} (#{marks[e]}, see above)")
            continue
        printed.add(e)
        if reached[e] > 1:
            marks[e] = len(marks) + 1
            label = f"{label} (#{marks[e]})"
        children = timeline.children(e)
        lines.append(f"{_prefix(depth)}{label}{' CAUSES' if children else ''}")
        stack.extend((c, depth + 1) for c in reversed(children))
    return "\n".join(lines)
