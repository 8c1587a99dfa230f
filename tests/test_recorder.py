"""The recorder builds the thesis's events from observations alone (no physics here): qualitative geometry
(figures 3-6 and 3-8, containers), the 15-frame rule and contacts that go on, end-contacts (figure 3-9), pushes,
concurrent movement splits and the assisted edit."""

from __future__ import annotations

import math

from physink_tui.scene.physics.contacts import ContactRecord
from physink_tui.timeline.events import Timeline
from physink_tui.timeline.graph import check_acyclic, descendants
from physink_tui.timeline.observation import Observation
from physink_tui.timeline.qualitative import BodyOutline, contact_sides
from physink_tui.timeline.recorder import Recorder

DT = 1 / 120


def box(body_id: str, w: float, h: float) -> BodyOutline:
    return BodyOutline(body_id, ((-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2)), False)


def cup(body_id: str) -> BodyOutline:
    """An open container 100 wide and 60 deep (its hull; the hollow is what the hull adds)."""
    return BodyOutline(body_id, ((-50, -30), (50, -30), (50, 30), (-50, 30)), True)


def still(x: float, y: float) -> tuple:
    return (x, y, 0.0, 0.0, 0.0, 0.0)


def moving(x: float, y: float, vx: float, vy: float) -> tuple:
    return (x, y, 0.0, vx, vy, 0.0)


class Run:
    """Feeds a recorder one observation per frame at 120 Hz."""

    def __init__(self, recorder: Recorder) -> None:
        self.recorder = recorder
        self.frame = 0

    def step(self, poses: dict, contacts=(), grabbed=None, touching=(), playing=()) -> None:
        self.frame += 1
        self.recorder.observe(Observation(round(self.frame * DT, 6), poses, tuple(contacts), grabbed,
                                          frozenset(frozenset(p) for p in touching), frozenset(playing)))

    @property
    def timeline(self) -> Timeline:
        return self.recorder.snapshot()


def kinds(timeline: Timeline) -> list[tuple[str, tuple[str, ...]]]:
    return [(e.type, e.components) for e in timeline.events]


def test_a_movement_records_the_regions_it_passes_through_as_in_figure_3_6() -> None:
    # the ball passes above and right of platform A, and left of platform B
    recorder = Recorder({"ball": box("ball", 20, 20), "a": box("a", 200, 20), "b": box("b", 200, 20)},
                        frozenset({"ball"}), reach=300)
    run = Run(recorder)
    fixed = {"a": still(300, 400), "b": still(800, 500)}
    path = [(250 + 4 * k, 300 + 2.2 * k) for k in range(100)]  # from over A down past its right end
    for x, y in path:
        run.step({"ball": moving(x, y, 480, 264), **fixed}, grabbed="ball")
    regions = dict(run.timeline.events[1].regions)
    assert regions == {"a": ("above", "right"), "b": ("left",)}
    assert run.timeline.events[1].trajectory[-1].x == path[-1][0]


def test_contact_sides_come_from_the_normal_and_a_container_holds_what_lands_in_it() -> None:
    ball, platform = box("ball", 20, 20), box("p", 300, 10)
    # the ball comes down on the far end of a long platform: still its top, not its side
    assert contact_sides(ball, still(440, 385), platform, still(300, 400), (0.0, 1.0)) == ("bottom", "top")
    assert contact_sides(ball, still(300, 415), platform, still(300, 400), (0.0, -1.0)) == ("top", "bottom")
    basket = cup("k")
    assert contact_sides(ball, still(500, 510), basket, still(500, 500), (0.0, 1.0)) == ("bottom", "inside")
    assert contact_sides(ball, still(500, 455), basket, still(500, 500), (0.0, 1.0))[1] == "top"  # on its rim


def test_reports_of_one_pair_within_15_frames_are_one_contact() -> None:
    recorder = Recorder({"ball": box("ball", 20, 20), "p": box("p", 200, 20)}, frozenset({"ball"}))
    run = Run(recorder)
    hit = ContactRecord(0, "ball", "p", (300, 390), (0.0, 1.0))
    on, away = {"ball": moving(300, 380, 0, 100), "p": still(300, 400)}, {"ball": moving(300, 300, 0, -100),
                                                                        "p": still(300, 400)}
    run.step(away, grabbed="ball")
    run.step(on, [hit], grabbed="ball", touching=[("ball", "p")])
    for _ in range(14):
        run.step(away, grabbed="ball")  # 70 units clear: it has left
    run.step(on, [hit], grabbed="ball", touching=[("ball", "p")])  # 15 frames later: the same contact
    assert [e.type for e in run.timeline.events].count("contact") == 1
    for _ in range(16):
        run.step(away, grabbed="ball")
    run.step(on, [hit], grabbed="ball", touching=[("ball", "p")])  # 17 frames after the last report: a new one
    assert [e.type for e in run.timeline.events].count("contact") == 2


def test_a_body_that_lifts_off_by_less_than_half_its_size_and_touches_again_stays_in_one_contact() -> None:
    # a 20 x 20 box (size: a disc of its area, 22.6 across) rattles on a platform, then really bounces
    recorder = Recorder({"ball": box("ball", 20, 20), "p": box("p", 200, 20)}, frozenset({"ball"}))
    run = Run(recorder)
    hit = ContactRecord(0, "ball", "p", (300, 390), (0.0, 1.0))
    on = {"ball": moving(300, 380, 0, 100), "p": still(300, 400)}
    run.step({"ball": moving(300, 300, 0, 100), "p": still(300, 400)}, grabbed="ball")
    for _ in range(5):
        run.step(on, [hit], grabbed="ball", touching=[("ball", "p")])
        for k in range(60):  # half a second off the platform, at most 10 units up: it has not left
            run.step({"ball": moving(300, 380 - 10 * math.sin(math.pi * k / 60), 0, 30), "p": still(300, 400)},
                     grabbed="ball")
    assert [e.type for e in run.timeline.events].count("contact") == 1
    for k in range(60):  # up 15 units (more than half its size) and down again: a second bounce
        run.step({"ball": moving(300, 380 - 15 * math.sin(math.pi * k / 60), 0, 30), "p": still(300, 400)},
                 grabbed="ball")
    run.step(on, [hit], grabbed="ball", touching=[("ball", "p")])
    assert [e.type for e in run.timeline.events].count("contact") == 2


def test_moving_a_stopper_away_from_a_ball_resting_on_it_is_an_end_contact_that_moves_both() -> None:
    # figure 3-9: the ball rests on the stopper; the stopper is moved to the right
    outlines = {"ball": box("ball", 20, 20), "stopper": box("stopper", 60, 20)}
    recorder = Recorder(outlines, frozenset({"ball", "stopper"}), initial_pairs=frozenset({frozenset(outlines)}))
    run = Run(recorder)
    for k in range(1, 40):
        run.step({"ball": still(100, 80), "stopper": moving(100 + 3 * k, 100, 360, 0)}, grabbed="stopper")
    timeline = run.timeline
    assert kinds(timeline)[:2] == [("start", ()), ("movement", ("stopper",))]
    (end,) = [e for e in timeline.events if e.type == "end_contact"]
    assert end.causes == (timeline.events[1].id,) and set(end.components) == {"ball", "stopper"}
    moved = [e.components[0] for e in timeline.events if e.causes == (end.id,)]
    assert sorted(moved) == ["ball", "stopper"]
    for k in range(20):  # now the ball falls (the user moves it): its movement is the one the end-contact made
        run.step({"ball": moving(100, 80 + 2 * k, 0, 240), "stopper": still(220, 100)}, grabbed="ball")
    ball_moves = [e for e in run.timeline.events if e.type == "movement" and e.components[0] == "ball"]
    assert len(ball_moves) == 1 and ball_moves[0].causes == (end.id,) and len(ball_moves[0].trajectory) > 15


def test_the_physics_reporting_a_pair_that_began_in_contact_is_no_contact_unless_one_drives_into_the_other() -> None:
    # figure 3-9 as a session sees it: the ball drawn 2 px into the stopper, the overlap resolved on the first step
    # (a contact report), the stopper grazing the ball as it slides out (another): the start names the pair, and
    # the only event between them is the end-contact
    outlines = {"ball": box("ball", 20, 20), "stopper": box("stopper", 60, 20)}
    recorder = Recorder(outlines, frozenset(outlines), initial_pairs=frozenset({frozenset(outlines)}))
    run = Run(recorder)
    graze = ContactRecord(0, "ball", "stopper", (100, 90), (0.0, 1.0))
    for k in range(1, 40):
        run.step({"ball": moving(100, 80, 0, -12 if k < 3 else 0), "stopper": moving(100 + 3 * k, 100, 360, -3)},
                 [graze] if k in (1, 5) else [], grabbed="stopper", touching=[("ball", "stopper")] if k < 20 else [])
    timeline = run.timeline
    assert timeline.events[0].in_contact == (("ball", "stopper"),)
    assert [e.type for e in timeline.events if e.type in ("contact", "end_contact")] == ["end_contact"]
    assert [e.components[0] for e in timeline.events if e.type == "movement"] == ["stopper", "stopper", "ball"]


def test_a_body_driving_into_the_one_it_began_in_contact_with_makes_a_contact() -> None:
    # the cup dispenser: the cup stands on the platform from the start; pressed down, it carries the platform
    outlines = {"cup": box("cup", 20, 20), "platform": box("platform", 100, 10)}
    recorder = Recorder(outlines, frozenset(outlines), initial_pairs=frozenset({frozenset(outlines)}))
    run = Run(recorder)
    for k in range(10):
        run.step({"cup": moving(100, 85 + k, 0, 120), "platform": moving(100, 100 + k, 0, 120 if k else 0)},
                 grabbed="cup", touching=[("cup", "platform")])
    contact = next(e for e in run.timeline.events if e.type == "contact")
    assert contact.components == ("cup", "platform") and dict(contact.sides) == {"cup": "bottom", "platform": "top"}
    assert any(e.components[:1] == ("platform",) and e.causes == (contact.id,) for e in run.timeline.events)
    assert not [e for e in run.timeline.events if e.type == "end_contact"]


def test_a_stopper_lifting_a_ball_that_rests_near_its_end_drives_into_it() -> None:
    # pushed up across their contact, not along the line between their centres (which runs mostly sideways)
    outlines = {"ball": box("ball", 20, 20), "stopper": box("stopper", 240, 40)}
    recorder = Recorder(outlines, frozenset(outlines), initial_pairs=frozenset({frozenset(outlines)}))
    run = Run(recorder)
    for k in range(1, 6):
        y = 100 - 100 * k / 120
        run.step({"ball": moving(210, y - 30, 0, -100 if k > 1 else 0), "stopper": moving(100, y, 0, -100)},
                 grabbed="stopper", touching=[("ball", "stopper")])
    contact = next(e for e in run.timeline.events if e.type == "contact")
    assert contact.components == ("stopper", "ball") and dict(contact.sides) == {"stopper": "top", "ball": "bottom"}


def test_a_pair_drawn_a_few_units_apart_parts_only_once_further_apart_than_it_began() -> None:
    outlines = {"ball": box("ball", 20, 20), "stopper": box("stopper", 60, 20)}
    recorder = Recorder(outlines, frozenset(outlines), initial_pairs=frozenset({frozenset(outlines)}))
    run = Run(recorder)
    for k in range(1, 8):  # 5 units apart as drawn; lifted 3 units more: still in contact
        run.step({"ball": moving(100, 75 - 0.5 * k, 0, -60), "stopper": still(100, 100)}, grabbed="ball")
    assert not [e for e in run.timeline.events if e.type == "end_contact"]
    for k in range(8, 12):
        run.step({"ball": moving(100, 75 - 0.5 * k, 0, -60), "stopper": still(100, 100)}, grabbed="ball")
    (end,) = [e for e in run.timeline.events if e.type == "end_contact"]
    assert run.timeline.event(end.causes[0]).components[0] == "ball"


def test_a_body_pushed_by_a_moving_body_it_touches_is_moved_by_a_contact() -> None:
    recorder = Recorder({"cup": box("cup", 20, 20), "platform": box("platform", 100, 10)},
                        frozenset({"cup", "platform"}))
    run = Run(recorder)
    for k in range(10):
        run.step({"cup": moving(100, 80 + k, 0, 120), "platform": still(100, 100)}, grabbed="cup")
    run.step({"cup": moving(100, 91, 0, 120), "platform": moving(100, 101, 0, 120)}, grabbed="cup",
             touching=[("cup", "platform")])
    contact = next(e for e in run.timeline.events if e.type == "contact")
    assert contact.components == ("cup", "platform") and dict(contact.sides) == {"cup": "bottom", "platform": "top"}
    assert any(e.components[:1] == ("platform",) and e.causes == (contact.id,) for e in run.timeline.events)


def test_a_body_that_starts_moving_right_after_a_separation_was_released_by_it() -> None:
    # the cup dispenser: nothing touches the peg any more, and it moves: an end-contact explains it
    outlines = {"peg": box("peg", 40, 10), "platform": box("platform", 100, 10)}
    recorder = Recorder(outlines, frozenset(outlines))
    run = Run(recorder)
    run.step({"peg": still(40, 100), "platform": moving(100, 101, 0, 120)}, grabbed="platform",
             touching=[("peg", "platform")])
    for k in range(10):
        run.step({"peg": still(40, 100), "platform": moving(100, 102 + 2 * k, 0, 240)}, grabbed="platform")
    run.step({"peg": moving(41, 100, 120, 0), "platform": still(100, 122)})
    end = next(e for e in run.timeline.events if e.type == "end_contact")
    peg = next(e for e in run.timeline.events if e.type == "movement" and e.components[0] == "peg")
    assert peg.causes == (end.id,) and end.causes == (run.timeline.events[1].id,)


def test_grabbing_a_body_again_continues_its_movement() -> None:
    recorder = Recorder({"ball": box("ball", 20, 20)}, frozenset({"ball"}))
    run = Run(recorder)
    for k in range(10):
        run.step({"ball": moving(10 * k, 0, 1200, 0)}, grabbed="ball")
    for _ in range(20):
        run.step({"ball": still(90, 0)})
    for k in range(10):
        run.step({"ball": moving(90 + 10 * k, 0, 1200, 0)}, grabbed="ball")
    assert kinds(run.timeline) == [("start", ()), ("movement", ("ball",))]


def two_balls() -> Run:
    """Ball a hits a paddle; ball b falls on its own, unrelated (the pinball of figure 3-14)."""
    outlines = {"a": box("a", 20, 20), "b": box("b", 20, 20), "p": box("p", 100, 10), "q": box("q", 100, 10)}
    run = Run(Recorder(outlines, frozenset({"a", "b", "p", "q"})))
    for k in range(30):
        contacts = [ContactRecord(0, "a", "p", (100, 95), (0.0, 1.0))] if k == 10 else []
        contacts += [ContactRecord(0, "a", "q", (300, 95), (0.0, 1.0))] if k == 25 else []
        run.step({"a": moving(100 + 10 * k, 80, 1200, 0), "b": moving(600, 10 * k, 0, 1200),
                  "p": still(100, 100), "q": still(300, 100)}, contacts, grabbed="a" if k < 20 else "b")
    return run


def test_redemonstrating_a_body_deletes_what_its_movement_caused_and_nothing_else() -> None:
    run = two_balls()
    before = run.recorder.pause()
    contact_p, contact_q = (e for e in before.events if e.type == "contact")
    after = run.recorder.redemonstrate("a", contact_p.t0 + 0.05)
    check_acyclic(after)
    assert contact_q.id not in after and contact_p.id in after
    assert all(e.id in after for e in before.events if e.components[:1] in (("b",), ("p",)))
    cut = next(e for e in after.events if e.components == ("a",) and e.causes == (contact_p.id,))
    assert cut.t1 <= contact_p.t0 + 0.05 and all(p.t <= contact_p.t0 + 0.05 for p in cut.trajectory)
    assert not descendants(after, cut.id)


def test_a_contact_with_a_body_playing_back_splits_its_recorded_movement() -> None:
    # basketball: ball b plays back its recording while ball a is demonstrated into it
    outlines = {"a": box("a", 20, 20), "b": box("b", 20, 20), "k": cup("k")}
    run = Run(Recorder(outlines, frozenset({"a", "b"})))
    for k in range(40):  # first b alone, into the basket at frame 30
        contacts = [ContactRecord(0, "b", "k", (500, 500), (0.0, 1.0))] if k == 30 else []
        run.step({"b": moving(200 + 10 * k, 500, 1200, 0), "a": still(0, 0), "k": still(500, 500)}, contacts,
                 grabbed="b")
    recorded = run.recorder.pause()
    (b_move,) = [e for e in recorded.events if e.type == "movement" and e.causes == ("e1",)]
    run.frame = 0
    for k in range(20):  # then a, while b plays back; they meet at frame 12
        contacts = [ContactRecord(0, "a", "b", (320, 500), (1.0, 0.0))] if k == 12 else []
        run.step({"a": moving(200 + 10 * k, 500, 1200, 0), "b": moving(200 + 10 * k, 500, 1200, 0),
                  "k": still(500, 500)}, contacts, grabbed="a", playing={"b"})
    timeline = run.recorder.pause()
    collision = next(e for e in timeline.events if e.type == "contact" and set(e.components) == {"a", "b"})
    head = timeline.event(b_move.id)
    assert head.t1 <= collision.t0 and b_move.id in collision.causes
    tail = next(e for e in timeline.events if e.components == ("b",) and e.causes == (collision.id,))
    assert tail.trajectory[0].t > collision.t0 and tail.trajectory[-1] == b_move.trajectory[-1]
    basket = next(e for e in timeline.events if e.type == "contact" and "k" in e.components)
    assert basket.causes == (tail.id,)  # the landing now follows the collision
    check_acyclic(timeline)


def test_a_body_set_moving_again_in_a_contact_that_goes_on_is_moved_by_that_contact() -> None:
    # a peg slides over a spring-held platform; the platform settles, then jitters under the peg again
    outlines = {"peg": box("peg", 40, 10), "platform": box("platform", 100, 10)}
    recorder = Recorder(outlines, frozenset(outlines))
    run = Run(recorder)
    run.step({"peg": moving(60, 90, 120, 0), "platform": still(100, 100)}, grabbed="peg")
    hit = ContactRecord(0, "peg", "platform", (60, 95), (0.0, 1.0))
    run.step({"peg": moving(61, 90, 120, 0), "platform": moving(100, 100, 0, 30)}, [hit], grabbed="peg",
             touching=[("peg", "platform")])
    for k in range(40):  # the platform comes to rest under the sliding peg, then bobs up again
        vy = 0.0 if k < 20 else -30.0
        run.step({"peg": moving(62 + k, 90, 120, 0), "platform": moving(100, 100, 0, vy)}, grabbed="peg",
                 touching=[("peg", "platform")])
    timeline = run.timeline
    (contact,) = [e for e in timeline.events if e.type == "contact"]
    platform = [e for e in timeline.events if e.type == "movement" and e.components[0] == "platform"]
    assert platform and all(e.causes == (contact.id,) for e in platform)


def push_and_catch_up(run: Run, between=lambda: None) -> None:
    """The held egg pushes the paddle, which swings ahead and stops (no gravity in demo mode); ``between`` runs
    meanwhile; then the egg, still held, catches the paddle up and touches it again."""
    hit = ContactRecord(0, "egg", "paddle", (100, 90), (0.0, 1.0))
    for k in range(10):
        run.step({"egg": moving(100, 60 + k, 0, 120), "paddle": still(100, 100), "ball": still(400, 100)},
                 grabbed="egg")
    run.step({"egg": moving(100, 70, 0, 120), "paddle": moving(100, 100, 0, 600)}, [hit], grabbed="egg",
             touching=[("egg", "paddle")])
    for k in range(1, 30):  # the paddle flies 5 units a frame for 10 frames, then stops 60 units ahead
        run.step({"egg": moving(100, 70 + k, 0, 120), "paddle": moving(100, 100 + 5 * min(k, 10), 0, 0 if k > 10
                                                                         else 600), "ball": still(400, 100)},
                 grabbed="egg")
    between()
    run.step({"egg": moving(100, 140, 0, 120), "paddle": moving(100, 150, 0, 120)},
             [ContactRecord(0, "egg", "paddle", (100, 140), (0.0, 1.0))], grabbed="egg",
             touching=[("egg", "paddle")])
    for k in range(1, 5):
        run.step({"egg": moving(100, 140 + k, 0, 120), "paddle": moving(100, 150 + k, 0, 120)}, grabbed="egg",
                 touching=[("egg", "paddle")])


def test_the_held_body_catching_up_with_a_body_it_pushed_is_still_pushing_it() -> None:
    # the egg pushed down through a paddle (thesis 2.3.3): the paddle swings ahead, the egg catches up
    recorder = Recorder({"egg": box("egg", 20, 20), "paddle": box("paddle", 60, 10), "ball": box("ball", 20, 20)},
                        frozenset({"egg", "paddle", "ball"}))
    run = Run(recorder)
    push_and_catch_up(run)
    timeline = run.timeline
    (push,) = [e for e in timeline.events if e.type == "contact"]
    paddle_moves = [e for e in timeline.events if e.type == "movement" and e.components[0] == "paddle"]
    assert paddle_moves and all(m.causes == (push.id,) for m in paddle_moves)


def test_a_pushed_body_that_something_else_touched_meanwhile_is_touched_anew() -> None:
    recorder = Recorder({"egg": box("egg", 20, 20), "paddle": box("paddle", 60, 10), "ball": box("ball", 20, 20)},
                        frozenset({"egg", "paddle", "ball"}))
    run = Run(recorder)

    def ball_hits_paddle() -> None:
        run.step({"egg": moving(100, 100, 0, 120), "paddle": moving(100, 150, 0, 10), "ball": moving(140, 150, -50, 0)},
                 [ContactRecord(0, "ball", "paddle", (130, 150), (-1.0, 0.0))], touching=[("ball", "paddle")],
                 grabbed="egg")

    push_and_catch_up(run, ball_hits_paddle)
    pairs = [frozenset(e.components) for e in run.timeline.events if e.type == "contact"]
    assert pairs == [frozenset({"egg", "paddle"}), frozenset({"ball", "paddle"}), frozenset({"egg", "paddle"})]
