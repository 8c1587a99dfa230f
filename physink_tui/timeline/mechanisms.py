"""Which movable things move as one: a body and what the ropes, springs and joints between movable things tie it to.

A movement names the moving body, then what it reaches through links, nearest first (`Mechanisms.chain`); every body
of one mechanism has one key (`Mechanisms.key`), so the recorder keeps one open movement per mechanism.
"""

from __future__ import annotations

from collections.abc import Container, Mapping


class Mechanisms:
    """The mechanisms of a demonstration.

    Args:
        links: node -> neighbours, where nodes are movable body ids and rope/spring ids.
        movable: ids of the bodies that can move; each mechanism's key is its first body in sorted order.
        bodies: the ids that are bodies (not ropes or springs).
    """

    def __init__(self, links: Mapping[str, tuple[str, ...]], movable: frozenset[str], bodies: Container[str]) -> None:
        self._links = links
        self._bodies = bodies
        self.group: dict[str, str] = {}
        """Each member's mechanism key (bodies, ropes and springs tied to a movable body)."""
        for body in sorted(movable):
            if body not in self.group:
                for member in self.chain(body):
                    self.group[member] = body

    def chain(self, body: str) -> tuple[str, ...]:
        """``body`` and every movable body, rope and spring it reaches through links, nearest first."""
        seen = [body]
        i = 0
        while i < len(seen):
            for nxt in self._links.get(seen[i], ()):
                if nxt not in seen:
                    seen.append(nxt)
            i += 1
        return tuple(seen)

    def key(self, body: str) -> str:
        """The same key for every body of one mechanism (bodies tied together move as one)."""
        return self.group.get(body, body)

    def bodies(self, body: str) -> tuple[str, ...]:
        """The bodies that move with ``body`` (itself first)."""
        return tuple(c for c in self.chain(body) if c in self._bodies)
