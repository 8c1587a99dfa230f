"""Which event of a timeline a narrated phrase labels: the thesis's temporally nearest event involving the phrase's
components (2.3.4); parsing the phrase is `phrases`', narrating `narrate`'s.

>>> from physink_tui.timeline.phrases import DEFAULT_VOCABULARY, parse_phrase
>>> phrase = parse_phrase("The egg lands in the frying pan", {"b4": "egg", "b6": "frying pan"}, DEFAULT_VOCABULARY)
>>> timeline = Timeline((Event("e1", "start"), Event("e2", "movement", ("b4",), ("e1",), 0.0, 2.0),
...                      Event("e3", "contact", ("b4", "b6"), ("e2",), 2.0, 2.0)))
>>> relabelled, event_id = label_event(timeline, phrase, 2.5)
>>> event_id, relabelled.event("e3").label
('e3', 'The egg lands in the frying pan')
"""

from __future__ import annotations

from physink_tui.timeline.events import Event, Timeline
from physink_tui.timeline.phrases import Phrase, PhraseError


def _distance(event: Event, t: float) -> float:
    """Seconds from ``t`` to the event's [t0, t1]; 0 inside it."""
    return max(event.t0 - t, 0.0, t - event.t1)


def _tier(event: Event, phrase: Phrase) -> int | None:
    """How well the event fits the phrase, 0 best; None when it does not involve the phrase's components."""
    components = event.components
    if event.type == "start" or not any(s in components for s in phrase.subjects):
        return None
    if phrase.objects:
        pair = any(s != o and s in components and o in components for s in phrase.subjects for o in phrase.objects)
        if not pair:
            return None
        return 0 if event.type in ("contact", "end_contact") else 1
    return 0 if event.type == "movement" else 1


def nearest_event(timeline: Timeline, phrase: Phrase, t: float) -> str | None:
    """The id of the event the phrase labels when said at time ``t`` (seconds), or None when no event fits.

    The thesis's "temporally-nearest event that involves the subject and object components", start events
    excepted. With an object: a contact or end-contact between the two, else any event involving both (a
    movement carrying one attached to the other). Without an object: a movement of the subject or of what it is
    attached to, else any event involving it. Within the best of these kinds the event nearest ``t`` wins
    (distance to its [t0, t1], 0 inside); on a tie the one that began earlier, then the one created earlier,
    since a user narrates what has just been shown. Components sharing a label are all tried.
    """
    best: tuple[int, float, float, int] | None = None
    found: str | None = None
    for position, event in enumerate(timeline.events):
        tier = _tier(event, phrase)
        if tier is None:
            continue
        key = (tier, _distance(event, t), event.t0, position)
        if best is None or key < best:
            best, found = key, event.id
    return found


def label_event(timeline: Timeline, phrase: Phrase, t: float) -> tuple[Timeline, str]:
    """The timeline with the phrase as the label of its `nearest_event`, and that event's id.

    Raises `PhraseError` when no event involves the phrase's components.
    """
    event_id = nearest_event(timeline, phrase, t)
    if event_id is None:
        names = phrase.subject_label if phrase.object_label is None else (
            f"{phrase.subject_label} and {phrase.object_label}")
        raise PhraseError(f"{phrase.text!r}: no event involves {names} yet", phrase.text)
    return timeline.relabel(event_id, phrase.text), event_id
