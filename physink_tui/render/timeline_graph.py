"""The causal timeline as a picture (SVG or PNG), drawn the way the thesis shows timelines (figures 3-4, 3-13):
events left to right from cause to effect, each type in its colour, named as the user named them; Graphviz's ``dot``
lays the graph out and draws it. Decides nothing about the timeline; writes one file.
"""

from __future__ import annotations

import os
import subprocess
from collections.abc import Mapping

from physink_tui.errors import RenderError
from physink_tui.formats.atomic_write import write_bytes_atomic
from physink_tui.timeline.events import EVENT_TYPES, Timeline, default_label

FORMATS = (".svg", ".png")
"""The picture formats, by file suffix."""
TYPE_STYLES: dict[str, tuple[str, str, str]] = {
    "start": ("#eeeeee", "#616161", "start"),
    "movement": ("#dcedc8", "#33691e", "movement"),  # the renderer's demonstration green
    "contact": ("#ffe0b2", "#e65100", "contact"),
    "end_contact": ("#d1c4e9", "#4527a0", "end of contact"),
}
"""Each event type's fill, outline and name in the legend."""
FONT = "DejaVu Sans"
"""The renderer's one font (Graphviz finds it through fontconfig)."""
PNG_DPI = 110


def _quote(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'


def timeline_graph_dot(timeline: Timeline, names: Mapping[str, str]) -> str:
    """The styled Graphviz source of the picture: one node per event (its label — the user's, with the default
    narration under it when the user named the event —, and its start time), an edge from each cause, a legend of
    the event types present.

    >>> from physink_tui.timeline.events import Event
    >>> dot = timeline_graph_dot(Timeline((Event("e1", "start"), Event("e2", "movement", ("b1",), ("e1",)))),
    ...                          {"b1": "ball"})
    >>> "rankdir=LR" in dot and '"e1" -> "e2"' in dot and "Movement of ball" in dot
    True
    """
    lines = ["digraph timeline {", "  rankdir=LR;", "  nodesep=0.25;", "  ranksep=0.45;",
             f'  graph [fontname={_quote(FONT)}, bgcolor="white", pad=0.2];',
             f'  node [shape=box, style="rounded,filled", fontname={_quote(FONT)}, fontsize=11, penwidth=1.4];',
             '  edge [color="#616161", arrowsize=0.7];']
    for ev in timeline.events:
        fill, outline, _ = TYPE_STYLES[ev.type]
        default = default_label(ev, names)
        text = [default] if ev.label is None else [ev.label, f"({default})"]
        label = _quote("\n".join([*text, f"{ev.t0:.2f} s"]))
        lines.append(f"  {_quote(ev.id)} [label={label}, fillcolor={_quote(fill)}, color={_quote(outline)}];")
    lines += [f"  {_quote(c)} -> {_quote(ev.id)};" for ev in timeline.events for c in ev.causes]
    present = [t for t in EVENT_TYPES if any(ev.type == t for ev in timeline.events)]
    if present:
        lines += ["  subgraph cluster_legend {", '    label="event types"; fontsize=10; color="#bdbdbd";']
        for kind in present:
            fill, outline, name = TYPE_STYLES[kind]
            lines.append(f"    {_quote('legend ' + kind)} [label={_quote(name)}, fillcolor={_quote(fill)}, "
                         f"color={_quote(outline)}, fontsize=9];")
        lines += ["    " + " -> ".join(_quote("legend " + k) for k in present) + " [style=invis, minlen=1];"
                  if len(present) > 1 else "", "  }"]
    lines.append("}")
    return "\n".join(line for line in lines if line) + "\n"


def write_timeline_picture(path: str | os.PathLike[str], timeline: Timeline, names: Mapping[str, str],
                           dot: str = "dot") -> None:
    """Draw the timeline to ``path``, an SVG or PNG by its suffix (atomically).

    Raises:
        RenderError: the suffix is neither, Graphviz's ``dot`` is missing or fails, or the file cannot be written.
    """
    suffix = os.path.splitext(os.fspath(path))[1].lower()
    if suffix not in FORMATS:
        raise RenderError(f"{os.fspath(path)}: a timeline picture is .svg or .png")
    command = [dot, f"-T{suffix[1:]}", *([f"-Gdpi={PNG_DPI}"] if suffix == ".png" else [])]
    try:
        done = subprocess.run(command, input=timeline_graph_dot(timeline, names).encode("utf-8"),
                              capture_output=True, timeout=120, check=False)
    except FileNotFoundError:
        raise RenderError(f"{os.fspath(path)}: drawing the timeline needs Graphviz's {dot!r} (Debian: apt install "
                          "graphviz; scripts/setup.sh installs it)") from None
    except subprocess.TimeoutExpired:
        raise RenderError(f"{os.fspath(path)}: Graphviz's {dot!r} took more than 120 s") from None
    if done.returncode != 0 or not done.stdout:
        why = done.stderr.decode("utf-8", "replace").strip().splitlines()
        raise RenderError(f"{os.fspath(path)}: Graphviz's {dot!r} failed: {why[-1] if why else done.returncode}")
    try:
        write_bytes_atomic(path, done.stdout)
    except OSError as exc:
        raise RenderError(f"cannot write {os.fspath(path)!r}: {exc.strerror or exc}") from exc
