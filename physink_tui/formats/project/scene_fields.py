"""A project's scene components as JSON objects, both ways, checked field by field; the file around them is `codec`'s.

Every check is `physink_tui.formats.json_checks`'; this module knows the components' keys, their order and how
they refer to each other (a joint's or spring's bodies, a rope's ends), and the id counters.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from physink_tui.formats import json_checks as checks
from physink_tui.formats.json_checks import MISSING, Place, joined, show
from physink_tui.scene.components import BACKGROUND, Body, Component, Joint, Material, Rope, Spring

COMPONENT_KEYS = {
    "body": ("id", "type", "shape", "outline", "radius", "position", "angle", "material", "label"),
    "joint": ("id", "type", "kind", "a", "b", "anchor"),
    "rope": ("id", "type", "points", "start_body", "end_body", "label"),
    "spring": ("id", "type", "a", "b", "anchor_a", "anchor_b", "axis", "rest_length", "k", "label"),
}
"""Each component type's keys, in the order written."""
MATERIAL_KEYS = ("density", "restitution", "friction")
SHAPES = ("box", "circle", "ellipse", "polygon", "polyline")
MIN_POINTS = {"box": 3, "ellipse": 3, "polygon": 3, "polyline": 2}
"""The fewest outline points each non-circle shape may have."""
JOINT_KINDS = ("pivot", "weld")
AXES = ("horizontal", "vertical")
_LABEL = "null or a non-empty string"


class Fields:
    """The fields of one component's JSON object at ``path``; ``kinds`` (id -> type) resolves references."""

    def __init__(self, where: Place, path: str, obj: dict[str, Any], kinds: dict[str, str]) -> None:
        self.where, self.path, self.obj, self.kinds = where, path, obj, kinds

    def key(self, key: str) -> str:
        return joined(self.path, key)

    def get(self, key: str, expected: str) -> Any:
        return checks.get(self.obj, self.where, key, self.key(key), expected)

    def number(self, key: str, expected: str = "a finite number", **bounds: float) -> float:
        return checks.number(self.where, self.key(key), self.get(key, expected), expected, **bounds)

    def text(self, key: str, expected: str = "a non-empty string") -> str:
        return checks.text(self.where, self.key(key), self.get(key, expected), expected, empty=False)

    def label(self) -> str | None:
        return checks.optional(checks.text, self.where, self.key("label"), self.get("label", _LABEL), _LABEL,
                               empty=False)

    def one_of(self, key: str, choices: tuple[str, ...]) -> str:
        expected = "one of " + ", ".join(map(show, choices))
        return checks.one_of(self.where, self.key(key), self.get(key, expected), choices)

    def point(self, key: str) -> tuple[float, float]:
        return checks.point(self.where, self.key(key), self.get(key, "a point [x, y]"))

    def points(self, key: str, least: int) -> tuple[tuple[float, float], ...]:
        expected = f"a list of at least {least} points [x, y]"
        return checks.points(self.where, self.key(key), self.get(key, expected), least)

    def body(self, key: str, *, background: bool = True, other: str | None = None) -> str:
        """The id of a body of the project, or the background where allowed, and not ``other``."""
        expected = f"{show(BACKGROUND)} or the id of a body" if background else "the id of a body"
        return self._body(key, self.get(key, expected), expected, background, other)

    def end(self, key: str) -> str | None:
        """A rope end: null when free, else the background or the id of a body."""
        expected = f"null, {show(BACKGROUND)} or the id of a body"
        value = self.get(key, expected)
        return None if value is None else self._body(key, value, expected, True, None)

    def _body(self, key: str, value: Any, expected: str, background: bool, other: str | None) -> str:
        if isinstance(value, str) and ((background and value == BACKGROUND) or self.kinds.get(value) == "body"):
            if value == other:
                raise self.where.bad(self.key(key), f"something other than the other end {show(other)}", value)
            return value
        note = ""
        if isinstance(value, str):
            note = f" (a {self.kinds[value]}, not a body)" if value in self.kinds else (
                " (the background)" if value == BACKGROUND else " (no component has that id)")
        raise self.where.bad(self.key(key), expected, value, note)


def sub_object(where: Place, path: str, value: Any, keys: tuple[str, ...], expected: str,
               warnings: list[str] | None) -> dict[str, Any]:
    """An object at ``path``, its unknown keys warned about."""
    obj = checks.an_object(where, path, value, expected)
    checks.known_keys(where, path, obj, keys, warnings)
    return obj


# --- writing -----------------------------------------------------------------------------------------------------


def plain(value: Any) -> Any:
    """Tuples (points, outlines) as lists; everything else as it is, for the checks to judge."""
    return [plain(v) for v in value] if isinstance(value, tuple | list) else value


def plain_component(c: Component) -> dict[str, Any]:
    """The component as the JSON object written, unchecked (decoding it checks it)."""
    if isinstance(c, Body):
        m = c.material
        material = {"density": m.density, "restitution": m.restitution, "friction": m.friction} if isinstance(
            m, Material) else m
        return {"id": c.id, "type": "body", "shape": c.shape, "outline": plain(c.outline), "radius": c.radius,
                "position": plain(c.position), "angle": c.angle, "material": material, "label": c.label}
    if isinstance(c, Joint):
        return {"id": c.id, "type": "joint", "kind": c.kind, "a": c.a, "b": c.b, "anchor": plain(c.anchor)}
    if isinstance(c, Rope):
        return {"id": c.id, "type": "rope", "points": plain(c.points), "start_body": c.start_body,
                "end_body": c.end_body, "label": c.label}
    if isinstance(c, Spring):
        return {"id": c.id, "type": "spring", "a": c.a, "b": c.b, "anchor_a": plain(c.anchor_a),
                "anchor_b": plain(c.anchor_b), "axis": c.axis, "rest_length": c.rest_length, "k": c.k,
                "label": c.label}
    raise TypeError(f"not a scene component: {c!r}")


# --- reading -----------------------------------------------------------------------------------------------------


def decode_components(where: Place, raw: Any, warnings: list[str] | None) -> list[Component]:
    """The components in the ``components`` list, in order; ids unique, references resolved."""
    if not isinstance(raw, list):
        raise where.bad("components", "a list of components", raw)
    kinds: dict[str, str] = {}  # id -> type where first named, so that a rope end may name a later body
    for item in raw:
        if isinstance(item, dict) and isinstance(item.get("id"), str) and isinstance(item.get("type"), str):
            kinds.setdefault(item["id"], item["type"])
    seen: dict[str, int] = {}
    out: list[Component] = []
    for i, item in enumerate(raw):
        path = f"components[{i}]"
        if not isinstance(item, dict):
            raise where.bad(path, "an object (a component)", item)
        f = Fields(where, path, item, kinds)
        cid = f.text("id")
        if cid == BACKGROUND:
            raise where.bad(f.key("id"), f"an id other than {show(BACKGROUND)} (it names the background)", cid)
        if cid in seen:
            raise where.bad(f.key("id"), "an id no other component has", cid,
                            f" (already the id of components[{seen[cid]}])")
        seen[cid] = i
        kind = f.one_of("type", tuple(COMPONENT_KEYS))
        checks.known_keys(where, path, item, COMPONENT_KEYS[kind], warnings)
        out.append(_READERS[kind](f, cid, warnings))
    return out


def _body(f: Fields, cid: str, warnings: list[str] | None) -> Body:
    shape = f.one_of("shape", SHAPES)
    if shape == "circle":
        outline = f.get("outline", "[] (a circle is given by its radius)")
        if outline != []:
            raise f.where.bad(f.key("outline"), "[] (a circle is given by its radius)", outline)
        points: tuple[tuple[float, float], ...] = ()
        radius = f.number("radius", "a number > 0", above=0.0)
    else:
        points = f.points("outline", MIN_POINTS[shape])
        radius = f.number("radius", "0 (only a circle has a radius)", low=0.0, high=0.0)
    position = f.point("position")
    angle = f.number("angle", "a finite number (radians)")
    expected = 'an object {"density", "restitution", "friction"}'
    path = f.key("material")
    m = Fields(f.where, path, sub_object(f.where, path, f.get("material", expected), MATERIAL_KEYS, expected,
                                         warnings), {})
    material = Material(
        m.number("density", "a number > 0", above=0.0),
        m.number("restitution", "a number in [0, 1]", low=0.0, high=1.0),
        m.number("friction", "a number >= 0", low=0.0),
    )
    return Body(cid, shape, points, radius, position, angle, material, f.label())


def _joint(f: Fields, cid: str, warnings: list[str] | None) -> Joint:
    kind = f.one_of("kind", JOINT_KINDS)
    a = f.body("a", background=False)
    return Joint(cid, kind, a, f.body("b", other=a), f.point("anchor"))


def _rope(f: Fields, cid: str, warnings: list[str] | None) -> Rope:
    points = f.points("points", 2)
    return Rope(cid, points, f.end("start_body"), f.end("end_body"), f.label())


def _spring(f: Fields, cid: str, warnings: list[str] | None) -> Spring:
    a = f.body("a")
    b = f.body("b", other=a)
    anchor_a, anchor_b = f.point("anchor_a"), f.point("anchor_b")
    axis = f.one_of("axis", AXES)
    rest = f.number("rest_length", "a number >= 0", low=0.0)
    return Spring(cid, a, b, anchor_a, anchor_b, axis, rest, f.number("k", "a number > 0", above=0.0), f.label())


_READERS: dict[str, Callable[[Fields, str, list[str] | None], Component]] = {
    "body": _body, "joint": _joint, "rope": _rope, "spring": _spring}


def decode_next_id(where: Place, raw: Any, components: list[Component]) -> dict[str, int]:
    """The id counters: integers >= 1, each above every id already made from its prefix (ids are never reused)."""
    expected = 'an object of id counters, e.g. {"b": 3, "j": 1}'
    if not isinstance(raw, dict):
        raise where.bad("next_id", expected, raw)
    counters: dict[str, int] = {}
    for prefix, n in raw.items():
        checks.text(where, "next_id", prefix, "an object whose keys are id prefixes (non-empty strings)",
                    empty=False)
        if isinstance(n, bool) or not isinstance(n, int) or n < 1:
            raise where.bad(f"next_id.{prefix}", "an integer >= 1", n)
        counters[prefix] = n
    for prefix in sorted({*counters, "b", "j", "r", "s"}):
        used = []
        for i, c in enumerate(components):
            digits = c.id[len(prefix):] if c.id.startswith(prefix) else ""
            if digits.isascii() and digits.isdecimal() and digits[0] != "0":
                used.append((int(digits), i))
        if used:
            highest, index = max(used)
            if counters.get(prefix, 1) <= highest:
                note = f" (components[{index}] has the id {show(components[index].id)})"
                raise where.bad(f"next_id.{prefix}", f"an integer > {highest}, so that no id is made twice",
                                counters.get(prefix, MISSING), note)
    return counters
