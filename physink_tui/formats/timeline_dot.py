"""The causal timeline as a Graphviz digraph for `physink timeline --format dot`; write-only, no file I/O."""

from __future__ import annotations

from collections.abc import Mapping

from physink_tui.timeline.events import Timeline, event_label


def _dot_quote(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'


def encode_timeline_dot(timeline: Timeline, names: Mapping[str, str]) -> str:
    """The timeline as a Graphviz digraph: one node per event labelled by its narration, edges cause -> effect.

    >>> from physink_tui.timeline.events import Event
    >>> print(encode_timeline_dot(Timeline((Event("e1", "start"), Event("e2", "movement", ("b1",), ("e1",)))),
    ...                           {"b1": "ball"}), end="")
    digraph timeline {
      rankdir=TB;
      node [shape=box];
      "e1" [label="Start"];
      "e2" [label="Movement of ball"];
      "e1" -> "e2";
    }
    """
    lines = ["digraph timeline {", "  rankdir=TB;", "  node [shape=box];"]
    lines += [f"  {_dot_quote(ev.id)} [label={_dot_quote(event_label(ev, names))}];" for ev in timeline.events]
    lines += [f"  {_dot_quote(c)} -> {_dot_quote(ev.id)};" for ev in timeline.events for c in ev.causes]
    lines.append("}")
    return "\n".join(lines) + "\n"
