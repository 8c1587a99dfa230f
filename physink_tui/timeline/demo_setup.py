"""What a demonstration's `Recorder` needs to know of the scene: outlines, which bodies move, what is tied to
what, and which movable bodies touch at the start. Reads the scene only; stepping it is the session's business."""

from __future__ import annotations

from physink_tui.scene.components import Joint, Rope, Scene, Spring
from physink_tui.scene.interpretation.body_shapes import body_geometry
from physink_tui.timeline.events import Timeline
from physink_tui.timeline.qualitative import outline_of
from physink_tui.timeline.recorder import Recorder

TOUCHING = 3.0
"""Canvas units within which two bodies drawn side by side touch (SIMULATE: what settles flush, what wakes)."""
BEGIN_IN_CONTACT = 6.0
"""Canvas units within which two movable bodies begin a demonstration in contact (`begun_in_contact`): drawn
touching, overlapping, or a few pixels apart, as a hand draws a ball resting on a stopper (the hurried hand of
tests/penmodels leaves 3-4 units where 2 were meant)."""
REACH = 0.25
"""Share of the canvas diagonal the regions above, below, left and right of a body extend over."""


def links_of(scene: Scene, movable: frozenset[str]) -> dict[str, tuple[str, ...]]:
    """The link graph between movable bodies, ropes and springs (node -> neighbours, in scene order)."""
    edges: dict[str, list[str]] = {}

    def tie(a: str, b: str) -> None:
        edges.setdefault(a, [])
        edges.setdefault(b, [])
        if b not in edges[a]:
            edges[a].append(b)
            edges[b].append(a)

    for c in scene.components.values():
        if isinstance(c, Rope):
            for end in (c.start_body, c.end_body):
                if end in movable:
                    tie(end, c.id)
        elif isinstance(c, Spring):
            for end in (c.a, c.b):
                if end in movable:
                    tie(end, c.id)
        elif isinstance(c, Joint) and c.a in movable and c.b in movable:
            tie(c.a, c.b)
    return {k: tuple(v) for k, v in edges.items()}


def touching_pairs(scene: Scene, movable: frozenset[str], within: float = TOUCHING) -> frozenset[frozenset[str]]:
    """Pairs of movable bodies drawn touching (closer than ``within``)."""
    bodies = [b for b in scene.bodies() if b.id in movable]
    pairs = set()
    for i, a in enumerate(bodies):
        ga = body_geometry(a)
        for b in bodies[i + 1:]:
            if ga.distance(body_geometry(b)) <= within:
                pairs.add(frozenset((a.id, b.id)))
    return frozenset(pairs)


def recorder_for(scene: Scene, canvas: tuple[float, float], dt: float, timeline: Timeline | None = None, *,
                 drawn: Scene | None = None) -> Recorder:
    """A recorder for a demonstration of ``scene`` on a canvas of ``canvas`` units, continuing ``timeline``.

    The pairs that begin in contact are the movable ones within `BEGIN_IN_CONTACT` of each other, of two
    mechanisms; with ``drawn`` (SIMULATE: ``scene`` is the drawn scene settled under gravity), only those that are
    so both as drawn and as settled, the pairs the demonstration of the drawn scene began with.
    """
    movable = frozenset(b.id for b in scene.bodies() if not scene.is_fixed(b.id))
    links = links_of(scene, movable)
    recorder = Recorder(
        outlines={b.id: outline_of(b) for b in scene.bodies()},
        movable=movable,
        links=links,
        initial_pairs=frozenset(),
        reach=REACH * (canvas[0] ** 2 + canvas[1] ** 2) ** 0.5,
        dt=dt,
        timeline=timeline if timeline is not None else Timeline(),
    )
    # pairs within one mechanism (a lever and the knife on its rope) never make end-contacts
    pairs = touching_pairs(scene, movable, BEGIN_IN_CONTACT)
    if drawn is not None:
        pairs &= touching_pairs(drawn, movable, BEGIN_IN_CONTACT)
    recorder.initial_pairs = frozenset(p for p in pairs if len({recorder.group_key(b) for b in p}) == 2)
    return recorder
