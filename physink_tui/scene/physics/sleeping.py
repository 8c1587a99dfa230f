"""Puts groups of bodies to sleep in a pymunk space, to be woken together by a touch (`World.hold_until_touched`);
which bodies to hold is the simulation's business.

Chipmunk wakes a sleeping body when an awake body touches it, within the same step (the blow is solved as between
two moving bodies), and wakes its whole sleeping group with it; it does not wake the other end of a constraint. So
bodies tied by constraints (a lever, its rope's links and the knife on the rope) and any pairs named (bodies
touching one another) sleep as one group, and a group tied to a body that stays awake stays awake.
"""

from __future__ import annotations

from collections.abc import Sequence

import pymunk

NEVER_IDLE = 1.0e9
"""Seconds of rest after which Chipmunk would put a body to sleep by itself once sleeping is enabled: never, in
practice (a rollout only sleeps what it holds)."""


def sleep_groups(space: pymunk.Space, bodies: Sequence[pymunk.Body], awake: set[pymunk.Body],
                 pairs: Sequence[tuple[pymunk.Body, ...]] = ()) -> None:
    """Sleeps ``bodies`` (dynamic, in ``space``) in groups tied by the space's constraints and ``pairs``, except
    the groups holding a body of ``awake``."""
    if space.sleep_time_threshold == float("inf"):
        space.sleep_time_threshold = NEVER_IDLE
    ties = [(c.a, c.b) for c in space.constraints] + [p for p in pairs if len(p) == 2]
    for group in tied_groups(bodies, ties):
        if awake.isdisjoint(group):
            first, *rest = group
            if not first.is_sleeping:
                first.sleep()
            for body in rest:
                if not body.is_sleeping:
                    body.sleep_with_group(first)


def tied_groups(bodies: Sequence[pymunk.Body], ties: Sequence[tuple[pymunk.Body, ...]]) -> list[list[pymunk.Body]]:
    """``bodies`` in groups tied together by ``ties`` (pairs; through ``bodies`` only), in the given order.

    >>> a, b, c = pymunk.Body(), pymunk.Body(), pymunk.Body()
    >>> [len(g) for g in tied_groups([a, b, c], [(a, c)])]
    [2, 1]
    """
    index = {body: i for i, body in enumerate(bodies)}
    parent = list(range(len(bodies)))

    def root(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for tie_a, tie_b in ties:
        a, b = index.get(tie_a), index.get(tie_b)
        if a is not None and b is not None:
            parent[root(a)] = root(b)
    groups: dict[int, list[pymunk.Body]] = {}
    for i, body in enumerate(bodies):
        groups.setdefault(root(i), []).append(body)
    return list(groups.values())
