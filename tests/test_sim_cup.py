"""What SIMULATE needed for the cup dispenser (thesis 4.3), as rules of their own: a ball rattling in the cup it
landed in splits no movement of the cup, and a contact the simulation misses is measured on the body that made it."""

from __future__ import annotations

from physink_tui.sim.evaluate import miss_distance, mover
from physink_tui.timeline.equivalence import CAUSE_COST, compare
from physink_tui.timeline.events import Event, Timeline, TrajectoryPoint

NAMES = {"b1": "ball", "b2": "cup", "b3": "peg"}


def frames(t0: float, t1: float, x0: float, x1: float, y: float, v: float) -> tuple[TrajectoryPoint, ...]:
    return (TrajectoryPoint(t0, x0, y, 0.0, v, 0.0), TrajectoryPoint(t1, x1, y, 0.0, v, 0.0))


def cup_pushed(*, rattles: bool) -> Timeline:
    """The ball lands on the cup (and, with ``rattles``, bounces on it once more), the cup moves on under it, the
    peg, moving all along, hits the cup."""
    events = [Event("e1", "start"),
              Event("e2", "movement", ("b1",), ("e1",), 0.0, 1.0, trajectory=frames(0.0, 1.0, 100, 500, 400, 400)),
              Event("e3", "movement", ("b3",), ("e1",), 0.0, 2.0, trajectory=frames(0.0, 2.0, 300, 440, 500, 200)),
              Event("e4", "contact", ("b1", "b2"), ("e2",), 1.0, 1.0, sides=(("b1", "bottom"), ("b2", "top")),
                    point=(500.0, 440.0)),
              Event("e5", "movement", ("b1",), ("e4",), 1.0, 3.0, trajectory=frames(1.0, 3.0, 500, 520, 420, 10)),
              Event("e6", "movement", ("b2",), ("e4",), 1.0, 2.0, trajectory=frames(1.0, 2.0, 500, 500, 480, 1))]
    cup = "e6"
    if rattles:
        events += [Event("e10", "contact", ("b1", "b2"), ("e5", "e6"), 1.5, 1.5,
                         sides=(("b1", "bottom"), ("b2", "top")), point=(505.0, 440.0)),
                   Event("e11", "movement", ("b1",), ("e10",), 1.5, 3.0,
                         trajectory=frames(1.5, 3.0, 505, 520, 420, 10)),
                   Event("e12", "movement", ("b2",), ("e10",), 1.5, 2.0,
                         trajectory=frames(1.5, 2.0, 500, 500, 480, 1))]
        cup = "e12"
    events += [Event("e7", "contact", ("b2", "b3"), (cup, "e3"), 2.0, 2.0, sides=(("b2", "left"), ("b3", "right")),
                     point=(470.0, 500.0)),
               Event("e8", "movement", ("b2",), ("e7",), 2.0, 3.0, trajectory=frames(2.0, 3.0, 500, 600, 480, 100)),
               Event("e9", "movement", ("b3",), ("e7",), 2.0, 3.0, trajectory=frames(2.0, 3.0, 440, 460, 500, 20))]
    return Timeline(tuple(events))


def test_a_ball_rattling_in_the_cup_it_landed_in_splits_no_movement_of_the_cup() -> None:
    # the ball's bounce coming to rest is part of its landing (resting.coming_to_rest); so is the cup's movement it
    # restarted, which the peg's contact is then caused by: the cup's movement since the landing, as demonstrated
    demonstrated, simulated = cup_pushed(rattles=False), cup_pushed(rattles=True)
    assert compare(demonstrated, simulated, NAMES, NAMES, simulation=True).equivalent
    plain = compare(demonstrated, simulated, NAMES, NAMES)  # not a simulation: the bounce is another event
    assert not plain.equivalent and plain.qualitative_distance > CAUSE_COST


def test_a_missed_contact_is_measured_on_the_body_that_brought_it_about() -> None:
    demonstrated = cup_pushed(rattles=False)
    hit = demonstrated.event("e7")
    assert hit.components[0] == "b2" and mover(demonstrated, hit) == "b3"  # the peg, not the slow cup named first
    peg = Event("e2", "movement", ("b3",), ("e1",), 0.0, 2.0, trajectory=frames(0.0, 2.0, 300, 400, 500, 50))
    cup = Event("e3", "movement", ("b2",), ("e1",), 0.0, 2.0, trajectory=frames(0.0, 2.0, 470, 470, 400, 0))
    short = Timeline((Event("e1", "start"), peg, cup))
    assert miss_distance(demonstrated, short, ["e7"]) == 70.0  # the peg stopped 70 units short of the point
