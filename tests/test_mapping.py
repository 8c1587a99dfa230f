"""Tablet-to-canvas mapping: proportions, area, rotation, left-handed use, display tablets, header round trip."""

from __future__ import annotations

import pytest

from physink_tui.input.pen.mapping import TabletMapping, mapping_from_header, mapping_to_header


@pytest.mark.parametrize(
    ("mapping", "tablet", "canvas"),
    [
        (TabletMapping(), (0.5, 0.5), (0.5, 0.5)),
        # a wide tablet on a square canvas: the sides are cropped, proportions kept
        (TabletMapping(canvas_width=1, canvas_height=1, tablet_width=2, tablet_height=1), (0.25, 0.0), (0.0, 0.0)),
        (TabletMapping(canvas_width=1, canvas_height=1, tablet_width=2, tablet_height=1), (0.75, 1.0), (1.0, 1.0)),
        (TabletMapping(canvas_width=1, canvas_height=1, tablet_width=2, tablet_height=1), (0.1, 0.5), (0.0, 0.5)),
        # a wide canvas on a square tablet crops top and bottom
        (TabletMapping(canvas_width=2, canvas_height=1, tablet_width=1, tablet_height=1), (0.5, 0.25), (0.5, 0.0)),
        # rotations: the tablet turned clockwise on the desk
        (TabletMapping(rotation=90, keep_aspect=False), (0.0, 0.0), (1.0, 0.0)),
        (TabletMapping(rotation=90, keep_aspect=False), (1.0, 0.0), (1.0, 1.0)),
        (TabletMapping(rotation=270, keep_aspect=False), (0.0, 0.0), (0.0, 1.0)),
        (TabletMapping(left_handed=True), (0.2, 0.3), (0.8, 0.7)),
        (TabletMapping(rotation=180, left_handed=True), (0.2, 0.3), (0.2, 0.3)),
        # a sub-area of the tablet
        (TabletMapping(area=(0.5, 0.5, 1.0, 1.0)), (0.75, 0.75), (0.5, 0.5)),
        # display tablets map one to one, never cropping
        (TabletMapping(canvas_width=1, canvas_height=1, tablet_width=2, tablet_height=1, display_tablet=True),
         (0.1, 0.5), (0.1, 0.5)),
    ],
    ids=["identity", "crop-left", "crop-right", "clamped", "crop-top", "rot90-origin", "rot90-corner",
         "rot270", "left-handed", "rot180-and-left-handed", "area", "display-tablet"],
)
def test_to_canvas(mapping: TabletMapping, tablet: tuple[float, float], canvas: tuple[float, float]) -> None:
    assert mapping.to_canvas(*tablet) == pytest.approx(canvas)


def test_rotated_wide_tablet_keeps_proportions() -> None:
    m = TabletMapping(canvas_width=1, canvas_height=1, tablet_width=2, tablet_height=1, rotation=90)
    # turned upright the tablet is 1 wide and 2 tall: top and bottom quarters of its long side are cropped
    assert m.to_canvas(0.25, 0.5) == pytest.approx((0.5, 0.0))
    assert m.to_canvas(0.75, 0.0) == pytest.approx((1.0, 1.0))


def test_header_round_trip() -> None:
    m = TabletMapping(canvas_width=1920, canvas_height=1080, tablet_width=40000, tablet_height=25000,
                      area=(0.1, 0.1, 0.9, 0.9), rotation=90, left_handed=True)
    assert mapping_from_header(mapping_to_header(m)) == m


@pytest.mark.parametrize(
    ("data", "needle"),
    [
        ({"rotation": 45}, "rotation"),
        ({"area": [0.5, 0, 0.4, 1]}, "area"),
        ({"area": [0, 0, 1]}, "area"),
        ({"canvas_width": 0}, "canvas_width"),
        ({"left_handed": "yes"}, "left_handed"),
        ({"zoom": 2}, "zoom"),
        ([], "object"),
    ],
    ids=["rotation", "area-order", "area-length", "canvas-zero", "bool", "unknown-key", "not-object"],
)
def test_bad_mapping_names_the_key(data, needle: str) -> None:
    with pytest.raises(ValueError, match=needle):
        mapping_from_header(data)
