"""Draws a `FrameContent` into RGBA pixels with skia, anti-aliased, in one reused buffer; writes no files.

One `Renderer` owns one raster surface over one numpy array, for one output size, canvas and theme. What does not
move between frames is kept: the paper with the fixed bodies as one image per scene, a path per body shape, a path
per trail grown as the trail grows, a rope's shape until its bodies move, a text blob per label. The canvas keeps
its aspect inside the output (letterbox bars in the theme's ``bars`` colour).
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping

import numpy as np
import skia

from physink_tui.errors import RenderError
from physink_tui.render.attachments import RopeShape, carried
from physink_tui.render.frame import FrameContent, TimeBar, Trail
from physink_tui.render.limits import MAX_SIDE, MIN_SIDE
from physink_tui.render.shapes import body_path, cross, extend, lowest, polyline, zigzag
from physink_tui.render.theme import Theme, theme_named
from physink_tui.scene.components import BACKGROUND, Body, Joint, Rope, Scene, Spring
from physink_tui.scene.physics.state import Pose

FONT_PATH = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
"""The one font every text is drawn with, so that images are the same on every machine."""

# Sizes in canvas units (never thinner than MIN_LINE pixels).
BODY_LINE, POLYLINE_LINE, ROPE_LINE, SPRING_LINE, JOINT_LINE, INK_LINE, TRAIL_LINE = 3.0, 4.0, 3.0, 2.5, 3.0, 3.0, 3.0
PIVOT_RADIUS, WELD_HALF, CONTACT_RADIUS = 7.0, 9.0, 6.0
LABEL_SIZE, LABEL_GAP = 22.0, 6.0
MIN_LINE, MIN_TEXT = 1.0, 9.0


def load_typeface(path: str = FONT_PATH) -> skia.Typeface:
    """The typeface in ``path``.

    Raises:
        RenderError: the file is missing or is not a font.
    """
    # a font manager of its own, without fontconfig: nothing depends on the system's font setup (whose newer
    # config files skia's bundled fontconfig warns about on stderr)
    typeface = skia.FontMgr.New_Custom_Empty().makeFromFile(path) if os.path.isfile(path) else None
    if typeface is None:
        raise RenderError(f"font {path!r} is missing or unreadable; the renderer draws text with DejaVu Sans only "
                          "(install the DejaVu fonts, e.g. the fonts-dejavu-core package)")
    return typeface


def _size(name: str, value: object) -> int:
    if isinstance(value, bool) or not isinstance(value, int) or not MIN_SIDE <= value <= MAX_SIDE:
        raise ValueError(f"{name}: expected a whole number of pixels from {MIN_SIDE} to {MAX_SIDE}, got {value!r}")
    return value


def _paint(color: int, width: float | None = None) -> skia.Paint:
    """An anti-aliased fill (``width`` None) or round-capped stroke of ``width``."""
    paint = skia.Paint(AntiAlias=True, Color=color)
    if width is not None:
        paint.setStyle(skia.Paint.kStroke_Style)
        paint.setStrokeWidth(width)
        paint.setStrokeCap(skia.Paint.kRound_Cap)
        paint.setStrokeJoin(skia.Paint.kRound_Join)
    return paint


CONTROLS = 0.1
"""Share of the output's height kept below the canvas for the narration and the time bar."""


class _Plan:
    """A scene's components sorted by how they are drawn, kept while the scene is the same object."""

    def __init__(self, scene: Scene) -> None:
        self.scene = scene
        parts = list(scene.components.values())
        self.bodies = [c for c in parts if isinstance(c, Body)]
        self.joints = [c for c in parts if isinstance(c, Joint)]
        self.springs = [c for c in parts if isinstance(c, Spring)]
        self.ropes = [c for c in parts if isinstance(c, Rope)]
        self.fixed = scene.fixed_bodies()


class Renderer:
    """Draws frames of one canvas at one output size in one theme.

    Args:
        width, height: the output in pixels, whole numbers from 16 to 7680.
        canvas: (width, height) of the canvas in canvas units; it is scaled to fit, its aspect kept.
        theme: ``light`` or ``dark``.
        controls: keep a strip below the canvas for the narration and the time bar (`CONTROLS` of the height), so
            they never cover the machine; without it they are drawn over the canvas's bottom edge.

    Raises:
        ValueError: a size, the canvas or the theme is not one of those.
        RenderError: the font is missing.
    """

    def __init__(self, width: int, height: int, canvas: tuple[float, float], theme: str = "light",
                 controls: bool = True) -> None:
        self.width, self.height = _size("width", width), _size("height", height)
        cw, ch = canvas
        if not (isinstance(cw, int | float) and isinstance(ch, int | float) and cw > 0 and ch > 0
                and math.isfinite(cw) and math.isfinite(ch)):
            raise ValueError(f"canvas: expected a positive (width, height), got {canvas!r}")
        self.canvas = (float(cw), float(ch))
        self.theme: Theme = theme_named(theme)
        strip = round(CONTROLS * height) if controls else 0
        above = height - strip
        self.scale = min(width / cw, above / ch)
        self.box = ((width - cw * self.scale) / 2, (above - ch * self.scale) / 2, cw * self.scale, ch * self.scale)
        """The canvas inside the output: left, top, width, height in pixels."""
        self.controls = (0.0, float(above), float(width), float(strip)) if strip else self.box
        """Where the narration and the time bar go: the strip below the canvas, or the canvas itself."""
        self._typeface = load_typeface()
        self._pixels = np.zeros((height, width, 4), dtype=np.uint8)
        self._surface = skia.Surface(self._pixels, colorType=skia.kRGBA_8888_ColorType,
                                     alphaType=skia.kPremul_AlphaType)
        self._canvas = self._surface.getCanvas()
        self._matrix = skia.Matrix.Translate(self.box[0], self.box[1]).preScale(self.scale, self.scale)
        self._static_pixels = np.zeros_like(self._pixels)
        self._static: tuple[Scene, tuple[object, ...], tuple[Trail, ...]] | None = None
        self._scene_plan: _Plan | None = None
        self._bodies: dict[str, tuple[Body, skia.Path]] = {}
        self._ropes: dict[str, tuple[Rope, RopeShape, tuple[object, ...] | None, skia.Path]] = {}
        self._trails: dict[int, tuple[tuple[tuple[float, float], ...], skia.Path, int]] = {}
        self._blobs: dict[tuple[str, float], tuple[skia.TextBlob, float]] = {}
        self._make_paints()

    def _px(self, units: float, least: float = MIN_LINE) -> float:
        """A length in canvas units, no shorter than ``least`` pixels on the output."""
        return max(units, least / self.scale)

    def _make_paints(self) -> None:
        th, px = self.theme, self._px
        self._p = {
            "body_fill": _paint(th.body_fill), "body_stroke": _paint(th.body_stroke, px(BODY_LINE)),
            "fixed_fill": _paint(th.fixed_fill), "fixed_stroke": _paint(th.fixed_stroke, px(BODY_LINE)),
            "body_line": _paint(th.body_stroke, px(POLYLINE_LINE, 1.5)),
            "fixed_line": _paint(th.fixed_stroke, px(POLYLINE_LINE, 1.5)),
            "joint": _paint(th.joint, px(JOINT_LINE)), "rope": _paint(th.rope, px(ROPE_LINE)),
            "spring": _paint(th.spring, px(SPRING_LINE)), "label": _paint(th.label),
            "demonstration": _paint(th.demonstration, px(TRAIL_LINE, 1.5)),
            "simulation": _paint(th.simulation, px(TRAIL_LINE, 1.5)),
            "contact": _paint(th.contact, px(2.0)), "contact_recent": _paint(th.contact_recent, px(3.5, 1.5)),
            "contact_text": _paint(th.contact_recent), "ink": _paint(th.ink, px(INK_LINE, 1.5)),
            "subtitle": _paint(th.subtitle), "subtitle_back": _paint(th.subtitle_back),
            "bar_track": _paint(th.bar_track), "bar_fill": _paint(th.bar_fill), "bar_tick": _paint(th.bar_tick),
            "highlight": _paint(th.contact_recent, px(2 * BODY_LINE, 2.0)),
        }

    # -- text -----------------------------------------------------------------------------------------------

    def _blob(self, text: str, size: float) -> tuple[skia.TextBlob, float]:
        """A text blob of ``text`` at ``size`` and its advance width, kept for the next frames."""
        key = (text, size)
        found = self._blobs.get(key)
        if found is None:
            font = skia.Font(self._typeface, size)
            font.setEdging(skia.Font.Edging.kAntiAlias)
            font.setSubpixel(True)
            found = (skia.TextBlob.MakeFromString(text, font), font.measureText(text))
            if len(self._blobs) > 512:
                self._blobs.clear()
            self._blobs[key] = found
        return found

    def _text(self, canvas: skia.Canvas, text: str, x: float, y: float, size: float, paint: skia.Paint,
              centred: bool = True) -> None:
        blob, width = self._blob(text, size)
        if blob is not None:
            canvas.drawTextBlob(blob, x - width / 2 if centred else x, y, paint)

    # -- bodies ---------------------------------------------------------------------------------------------

    def _body_path(self, body: Body) -> skia.Path:
        found = self._bodies.get(body.id)
        if found is None or found[0] is not body:
            found = (body, body_path(body))
            self._bodies[body.id] = found
        return found[1]

    def _draw_body(self, canvas: skia.Canvas, body: Body, x: float, y: float, angle: float, fixed: bool) -> None:
        path = self._body_path(body)
        canvas.save()
        canvas.translate(x, y)
        if angle:
            canvas.rotate(math.degrees(angle))
        if body.shape == "polyline":
            canvas.drawPath(path, self._p["fixed_line" if fixed else "body_line"])
        else:
            canvas.drawPath(path, self._p["fixed_fill" if fixed else "body_fill"])
            canvas.drawPath(path, self._p["fixed_stroke" if fixed else "body_stroke"])
        canvas.restore()
        if body.label:
            size = self._px(LABEL_SIZE, MIN_TEXT)
            self._text(canvas, body.label, x, y + lowest(body, angle) + LABEL_GAP + size * 0.8, size, self._p["label"])

    def _draw_joint(self, canvas: skia.Canvas, joint: Joint, point: tuple[float, float]) -> None:
        if joint.kind == "weld":
            canvas.drawPath(cross(point, WELD_HALF), self._p["joint"])
        else:
            canvas.drawCircle(point[0], point[1], PIVOT_RADIUS, self._p["joint"])

    # -- the layer that does not move -----------------------------------------------------------------------

    def _plan(self, scene: Scene) -> _Plan:
        if self._scene_plan is None or self._scene_plan.scene is not scene:
            self._scene_plan = _Plan(scene)
        return self._scene_plan

    def _static_layer(self, plan: _Plan, still: frozenset[str], done: tuple[Trail, ...]) -> np.ndarray:
        """The pixels of the bars, the paper, the fixed bodies ``still`` (with labels and joints) and the trails
        ``done`` (complete: they grow no more), drawn once for as long as those stay the same."""
        key = (still, tuple(id(trail.points) for trail in done), tuple(trail.kind for trail in done))
        cached = self._static
        if cached is not None and cached[0] is plan.scene and cached[1] == key:
            return self._static_pixels
        pixels = self._static_pixels
        surface = skia.Surface(pixels, colorType=skia.kRGBA_8888_ColorType, alphaType=skia.kPremul_AlphaType)
        canvas = surface.getCanvas()
        canvas.clear(self.theme.bars)
        canvas.drawRect(skia.Rect.MakeXYWH(*self.box), _paint(self.theme.background))
        canvas.clipRect(skia.Rect.MakeXYWH(*self.box))  # what leaves the canvas is not drawn over bars or strip
        canvas.setMatrix(self._matrix)
        for body in plan.bodies:
            if body.id in still:
                self._draw_body(canvas, body, body.position[0], body.position[1], body.angle, fixed=True)
        for joint in plan.joints:
            if {joint.a, joint.b} <= still | {BACKGROUND}:
                self._draw_joint(canvas, joint, joint.anchor)
        for trail in done:
            canvas.drawPath(polyline(trail.points), self._p[trail.kind])
        surface.flushAndSubmit()
        del canvas, surface
        self._static = (plan.scene, key, done)  # the trails are kept so that their ids stay theirs
        return pixels

    # -- frames ---------------------------------------------------------------------------------------------

    def render(self, content: FrameContent) -> np.ndarray:
        """Draw ``content``; returns the (height, width, 4) uint8 RGBA pixels.

        The array is this renderer's one buffer: it is valid until the next `render` call (copy it to keep it).

        Raises:
            RenderError: ``content`` is of another canvas than this renderer's.
        """
        if tuple(content.canvas) != self.canvas:
            raise RenderError(f"frame of a {content.canvas!r} canvas given to a renderer of a {self.canvas!r} canvas")
        scene, poses = content.scene, content.poses
        plan = self._plan(scene)
        still = frozenset(b for b in plan.fixed if b not in poses or self._unmoved(scene, b, poses[b]))
        done = tuple(t for t in content.trails if t.shown == len(t.points) and t.head is None)
        growing = tuple(t for t in content.trails if t.shown and not (t.shown == len(t.points) and t.head is None))
        np.copyto(self._pixels, self._static_layer(plan, still, done))  # a copy is far faster than drawing
        canvas = self._canvas
        canvas.resetMatrix()
        canvas.save()
        canvas.clipRect(skia.Rect.MakeXYWH(*self.box))
        canvas.setMatrix(self._matrix)
        self._draw_trails(canvas, growing)
        for spring in plan.springs:
            a = carried(spring.anchor_a, spring.a, scene, poses)
            b = carried(spring.anchor_b, spring.b, scene, poses)
            canvas.drawPath(zigzag(a, b, spring.rest_length), self._p["spring"])
        for rope in plan.ropes:
            canvas.drawPath(self._rope_path(rope, scene, poses), self._p["rope"])
        for body in plan.bodies:
            if body.id not in still:
                x, y, angle = content.pose(body)
                self._draw_body(canvas, body, x, y, angle, fixed=body.id in plan.fixed)
        for body in plan.bodies:  # outlined in the emphasis colour, over whatever is drawn
            if body.id in content.highlight:
                x, y, angle = content.pose(body)
                canvas.save()
                canvas.translate(x, y)
                canvas.rotate(math.degrees(angle))
                canvas.drawPath(self._body_path(body), self._p["highlight"])
                canvas.restore()
        for joint in plan.joints:
            if not {joint.a, joint.b} <= still | {BACKGROUND}:
                self._draw_joint(canvas, joint, carried(joint.anchor, joint.a, scene, poses))
        self._draw_contacts(canvas, content)
        for stroke in content.ink:
            if len(stroke) == 1:
                canvas.drawPoint(stroke[0][0], stroke[0][1], self._p["ink"])
            elif stroke:
                canvas.drawPath(polyline(stroke), self._p["ink"])
        canvas.restore()
        canvas.resetMatrix()
        if content.time_bar is not None:
            self._draw_time_bar(canvas, content.time_bar)
        if content.subtitle:
            self._draw_subtitle(canvas, content.subtitle, content.time_bar is not None)
        return self._pixels

    @staticmethod
    def _unmoved(scene: Scene, body_id: str, pose: Pose) -> bool:
        body = scene.components[body_id]
        return isinstance(body, Body) and (pose[0], pose[1], pose[2]) == (*body.position, body.angle)

    def _rope_path(self, rope: Rope, scene: Scene, poses: Mapping[str, Pose]) -> skia.Path:
        """The rope's path with its bodies at ``poses``, made again only when one of them has moved."""
        found = self._ropes.get(rope.id)
        if found is None or found[0] is not rope:
            shape = RopeShape(rope, scene)
            found = (rope, shape, None, skia.Path())
        rope_, shape, key, path = found
        now = tuple(poses.get(b) for b in shape.bodies())
        if now != key:
            points = shape.at(scene, poses).tolist()
            path = polyline(points)
            self._ropes[rope.id] = (rope_, shape, now, path)
        return path

    def _draw_trails(self, canvas: skia.Canvas, trails: tuple[Trail, ...]) -> None:
        if len(self._trails) > 4 * len(trails) + 64:
            self._trails.clear()
        for trail in trails:
            if trail.shown == 0:
                continue
            key = id(trail.points)
            found = self._trails.get(key)
            if found is None or found[0] is not trail.points or found[2] > trail.shown:
                found = (trail.points, skia.Path(), 0)
            points, path, drawn = found
            if drawn < trail.shown:
                extend(path, points, drawn, trail.shown)
                found = (points, path, trail.shown)
            self._trails[key] = found
            paint = self._p[trail.kind]
            canvas.drawPath(path, paint)
            if trail.head is not None:
                last = points[trail.shown - 1]
                canvas.drawLine(last[0], last[1], trail.head[0], trail.head[1], paint)

    def _draw_contacts(self, canvas: skia.Canvas, content: FrameContent) -> None:
        """Older contacts as small rings; recent ones as bold rings with their sides written beside them (a text
        that would overlap one written already moves down a line)."""
        size = self._px(LABEL_SIZE * 0.8, MIN_TEXT)
        written: list[tuple[float, float, float]] = []  # left, top, right of each text written
        for marker in content.contacts:
            x, y = marker.point
            if not marker.recent:
                canvas.drawCircle(x, y, self._px(CONTACT_RADIUS, 2.0), self._p["contact"])
                continue
            canvas.drawCircle(x, y, self._px(CONTACT_RADIUS * 1.8, 4.0), self._p["contact_recent"])
            left = x + self._px(CONTACT_RADIUS * 2.5, 6.0)
            right = left + self._blob(marker.sides, size)[1]
            top = y - size * 1.4
            while any(l_ < right and left < r and abs(t - top) < size * 1.2 for l_, t, r in written):
                top += size * 1.2
            written.append((left, top, right))
            self._text(canvas, marker.sides, left, top + size, size, self._p["contact_text"], centred=False)

    def _draw_subtitle(self, canvas: skia.Canvas, text: str, above_bar: bool) -> None:
        left, top, width, height = self.controls
        if self.controls is not self.box:  # in the strip: the text above the bar, as large as the strip allows
            size = max(MIN_TEXT, 0.34 * height)
            bottom = top + (0.52 if above_bar else 0.7) * height
        else:
            size = max(MIN_TEXT, 0.04 * height)
            bottom = top + height - (0.07 if above_bar else 0.03) * height
        blob, advance = self._blob(text, size)
        if blob is None:
            return
        pad = 0.4 * size
        x = left + (width - advance) / 2
        back = skia.Rect.MakeLTRB(x - pad, bottom - size - pad * 0.5, x + advance + pad, bottom + pad)
        canvas.drawRoundRect(back, pad, pad, self._p["subtitle_back"])
        canvas.drawTextBlob(blob, x, bottom - 0.2 * size, self._p["subtitle"])

    def _draw_time_bar(self, canvas: skia.Canvas, bar: TimeBar) -> None:
        left, top, width, height = self.controls
        if self.controls is not self.box:
            thick = max(2.0, 0.07 * height)
            y = top + 0.78 * height
        else:
            thick = max(2.0, 0.008 * height)
            y = top + height - 0.03 * height
        margin = 0.03 * width
        x0, x1 = left + margin, left + width - margin
        track = skia.Rect.MakeLTRB(x0, y - thick / 2, x1, y + thick / 2)
        canvas.drawRoundRect(track, thick / 2, thick / 2, self._p["bar_track"])
        if bar.duration > 0:
            f = min(max(bar.t / bar.duration, 0.0), 1.0)
            x = x0 + f * (x1 - x0)
            canvas.drawRoundRect(skia.Rect.MakeLTRB(x0, y - thick / 2, x, y + thick / 2), thick / 2, thick / 2,
                                 self._p["bar_fill"])
            for tick in bar.ticks:
                tx = x0 + min(max(tick / bar.duration, 0.0), 1.0) * (x1 - x0)
                canvas.drawRect(skia.Rect.MakeLTRB(tx - 0.5 - thick * 0.15, y - thick * 1.5, tx + 0.5 + thick * 0.15,
                                                   y + thick * 1.5), self._p["bar_tick"])
            canvas.drawCircle(x, y, thick * 1.4, self._p["bar_fill"])
