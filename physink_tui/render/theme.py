"""The renderer's light and dark palettes as frozen values (colours as 0xAARRGGBB); no drawing."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True, slots=True)
class Theme:
    """The colours of one look, each an ``0xAARRGGBB`` integer.

    Attributes:
        name: ``light`` or ``dark``.
        bars: the letterbox bars outside the canvas (differs from ``background`` so the canvas's edge shows).
        background: the canvas (the paper).
        ink: strokes being drawn and strokes waiting (a half-X).
        body_fill, body_stroke: a body that can move.
        fixed_fill, fixed_stroke: a body welded to the background (drawn distinctly: it never moves).
        joint: weld X's and pivot circles.
        rope: ropes.
        spring: springs' zig-zags.
        label: the labels under bodies.
        demonstration: trails of a demonstration (green, as in the thesis's figures).
        simulation: trails of a simulation (red).
        contact, contact_recent: contact markers, and the ones that just happened.
        subtitle, subtitle_back: the narration's text and the box behind it.
        bar_track, bar_fill, bar_tick: the time bar: its track, the part played, the events' ticks.
    """

    name: str
    bars: int
    background: int
    ink: int
    body_fill: int
    body_stroke: int
    fixed_fill: int
    fixed_stroke: int
    joint: int
    rope: int
    spring: int
    label: int
    demonstration: int
    simulation: int
    contact: int
    contact_recent: int
    subtitle: int
    subtitle_back: int
    bar_track: int
    bar_fill: int
    bar_tick: int


LIGHT = Theme(
    name="light",
    bars=0xFFB8B8B8,
    background=0xFFFBFAF6,
    ink=0xFF1F3A93,
    body_fill=0xFFDCE6F2,
    body_stroke=0xFF2B3A4A,
    fixed_fill=0xFF9AA3AD,
    fixed_stroke=0xFF3B424A,
    joint=0xFF6A1B9A,
    rope=0xFF7A5230,
    spring=0xFF2E6F8E,
    label=0xFF222222,
    demonstration=0xFF1E9E3A,
    simulation=0xFFD62828,
    contact=0xFFE08A00,
    contact_recent=0xFFFF5A00,
    subtitle=0xFFFFFFFF,
    subtitle_back=0xC0202020,
    bar_track=0xFFCBCBCB,
    bar_fill=0xFF4A6FA5,
    bar_tick=0xFF333333,
)

DARK = Theme(
    name="dark",
    bars=0xFF000000,
    background=0xFF1C1F24,
    ink=0xFF9CC3FF,
    body_fill=0xFF34414F,
    body_stroke=0xFFC9D4E0,
    fixed_fill=0xFF5A5F66,
    fixed_stroke=0xFFA0A6AD,
    joint=0xFFE1A6FF,
    rope=0xFFD9A66B,
    spring=0xFF6EC6E8,
    label=0xFFE8E8E8,
    demonstration=0xFF3DDC5F,
    simulation=0xFFFF5C5C,
    contact=0xFFFFB23F,
    contact_recent=0xFFFF7A1A,
    subtitle=0xFF101010,
    subtitle_back=0xD0E8E8E8,
    bar_track=0xFF444A52,
    bar_fill=0xFF7FA7E0,
    bar_tick=0xFFDDDDDD,
)

THEMES: dict[str, Theme] = {"light": LIGHT, "dark": DARK}


def theme_named(name: str) -> Theme:
    """The theme called ``name`` (``light`` or ``dark``).

    Raises:
        ValueError: no theme has that name.

    >>> theme_named("dark").name
    'dark'
    """
    try:
        return THEMES[name]
    except (KeyError, TypeError):
        raise ValueError(f"theme: expected one of {sorted(THEMES)}, got {name!r}") from None
