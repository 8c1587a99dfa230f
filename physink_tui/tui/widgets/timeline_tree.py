"""The causal timeline as a Textual `Tree`: each event under the event that caused it, selecting one posts
`TimelineTree.Seek`; builds nothing but the tree (the timeline is the session's).

A timeline is a DAG; the tree shows each event under its first cause (an event with several causes says the
others in its line). It is rebuilt only when what it shows changes (the events, their causes, starts and names),
not while a recording only lengthens its movements: a rebuild lays out the whole screen again.
"""

from __future__ import annotations

from dataclasses import dataclass

from textual.message import Message
from textual.widgets import Tree
from textual.widgets.tree import TreeNode

from physink_tui.session.view import SessionView
from physink_tui.timeline.events import Event, Timeline, event_label


class TimelineTree(Tree[tuple[float, tuple[str, ...]]]):
    """The timeline of the views it is given (`show`)."""

    @dataclass
    class Seek(Message):
        """The user chose an event: play back from its start (timeline seconds)."""

        t: float
        event_id: str
        components: tuple[str, ...] = ()

    def __init__(self, **kwargs) -> None:
        super().__init__("Timeline", **kwargs)
        self.show_root = False
        self.auto_expand = False  # choosing an event seeks; it does not fold its consequences away
        self._shown: tuple | None = None  # what the tree shows (`_key`); None: nothing yet
        self._names: dict[str, str] = {}
        self.guide_depth = 2

    def show(self, view: SessionView) -> bool:
        """Show ``view``'s timeline; whether the tree was built again (its cursor is then back at the top)."""
        timeline = view.timeline
        names = dict(view.scene.names())
        key = self._key(timeline, names)
        if key == self._shown:
            return False
        self._shown, self._names = key, names
        self.clear()
        if timeline is None or not timeline.events:
            self.root.add_leaf("(nothing demonstrated yet: press d for demo mode and move a body)")
            return True
        events = {ev.id: ev for ev in timeline.events}
        nodes: dict[str, TreeNode[tuple[float, tuple[str, ...]]]] = {}
        waiting = sorted(timeline.events, key=lambda e: (e.t0, e.id))
        while waiting:  # parents first: an event waits until its first cause has a node
            later = []
            for ev in waiting:
                cause = ev.causes[0] if ev.causes and ev.causes[0] in events else None
                if cause is not None and cause not in nodes:
                    later.append(ev)
                    continue
                where = nodes[cause] if cause is not None else self.root
                nodes[ev.id] = where.add(self._label(ev, events, names), data=(ev.t0, ev.components), expand=True)
            if len(later) == len(waiting):  # a cycle (never in a valid timeline): show the rest at the root
                for ev in later:
                    nodes[ev.id] = self.root.add(self._label(ev, events, names), data=(ev.t0, ev.components),
                                                 expand=True)
                later = []
            waiting = later
        for node in nodes.values():
            node.allow_expand = bool(node.children)
        return True

    @staticmethod
    def _key(timeline: Timeline | None, names: dict[str, str]) -> tuple:
        """Everything the tree shows of ``timeline`` (each event's id, type, start, components, causes and label)."""
        if timeline is None:
            return ((), names)
        return (tuple((ev.id, ev.type, ev.t0, ev.components, ev.causes, ev.label) for ev in timeline.events), names)

    @staticmethod
    def _label(ev: Event, events: dict[str, Event], names: dict[str, str]) -> str:
        text = event_label(ev, names)
        if ev.type == "start":  # "start", with the pairs that began in contact: "start (stopper and ball in contact)"
            text = "start" + text.removeprefix("Start") if ev.label is None else text
        more = [c for c in ev.causes[1:] if c in events]
        also = f"  (also caused by {', '.join(more)})" if more else ""
        return f"{ev.t0:5.2f} s  {text}{also}"

    def on_tree_node_selected(self, event: Tree.NodeSelected[tuple[float, tuple[str, ...]]]) -> None:
        event.stop()
        if event.node.data is not None:
            t, components = event.node.data
            self.post_message(self.Seek(float(t), str(event.node.label), tuple(components)))
