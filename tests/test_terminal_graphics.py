"""The terminal graphics encoders (Kitty graphics protocol, Sixel): well-formed escapes that decode back to the
frame's pixels; the choice of protocol from the terminal's environment."""

from __future__ import annotations

import numpy as np
import pytest
from terminal_graphics import kitty_commands, kitty_image, sixel_image

from physink_tui.errors import RenderError
from physink_tui.render import kitty, sixel
from physink_tui.render.frames import view_frame
from physink_tui.render.renderer import Renderer
from physink_tui.scene.physics.state import Pose
from physink_tui.session.modes.base import ModeName
from physink_tui.session.view import SessionView
from physink_tui.tui.graphics import choose
from tests.sim_scenes import CANVAS, ball_floor_wall


def scene_frame(width: int = 301, height: int = 199) -> np.ndarray:
    """A real frame: the ball, floor and wall machine as the renderer draws it (anti-aliased edges included)."""
    scene = ball_floor_wall()
    poses = {b.id: Pose(*b.position, b.angle) for b in scene.bodies()}
    view = SessionView(1, 0.0, ModeName.SKETCH, scene, poses, (), (), None, False, False, None, 0.0, 0.0, False, ())
    return Renderer(width, height, CANVAS, "dark", controls=False).render(view_frame(view, CANVAS))


def test_kitty_transmission_is_chunked_and_decodes_to_the_frame() -> None:
    frame = scene_frame()
    text = kitty.transmit(frame, 4242, 30, 10)
    keys, pixels = kitty_image(text)
    assert keys == {"a": "T", "U": "1", "f": "100", "i": "4242", "c": "30", "r": "10", "q": "2", "m": keys["m"]}
    assert np.array_equal(pixels, frame)
    noise = np.random.default_rng(1).integers(0, 256, (64, 96, 4), dtype=np.uint8)  # PNG cannot shrink it
    noise[..., 3] = 255  # frames are opaque
    text = kitty.transmit(noise, 9, 12, 4)
    assert len(kitty_commands(text)) >= 4 and np.array_equal(kitty_image(text)[1], noise)


def test_kitty_placeholders_name_each_row_and_the_image() -> None:
    rows = kitty.placeholder_rows(5, 3)
    assert [len(r) for r in rows] == [7, 7, 7]
    for r, row in enumerate(rows):
        assert row[0] == kitty.PLACEHOLDER and row[1] == kitty.DIACRITICS[r] and row[2] == kitty.DIACRITICS[0]
        assert row[3:] == kitty.PLACEHOLDER * 4
    assert kitty.id_colour(0x123456) == (0x12, 0x34, 0x56)
    assert kitty_commands(kitty.delete(7)) == [({"a": "d", "d": "I", "i": "7", "q": "2"}, "")]


@pytest.mark.parametrize(("args", "named"), [((0, 3, 3), "id 0"), ((1 << 24, 3, 3), "id 16777216"),
                                             ((1, 0, 3), "0 x 3"), ((1, 3, 400), "3 x 400")])
def test_kitty_refuses_what_the_placeholders_cannot_name(args, named) -> None:
    with pytest.raises(RenderError, match=named):
        kitty.transmit(scene_frame(20, 20), *args)


def test_sixel_decodes_to_the_frame_within_its_percent_colours() -> None:
    frame = scene_frame()  # 199 rows: the last band is partial
    decoded = sixel_image(sixel.encode(frame))
    assert decoded.shape == (199, 301, 3)
    error = np.abs(decoded.astype(int) - frame[..., :3].astype(int))
    flat = (frame[..., :3] == frame[0, 0, :3]).all(axis=2)  # the background, a colour the palette holds exactly
    assert error[flat].max() <= 2  # percent registers: 255 / 100 levels a step
    assert np.percentile(error.max(axis=2), 99) <= 36  # rare anti-aliased shades fall to the colour cube


def test_sixel_of_flat_colours_is_exact_to_the_percent_and_runs_are_compressed() -> None:
    frame = np.zeros((13, 40, 4), np.uint8)
    frame[..., 3] = 255
    frame[:, :20, 0] = 255  # red left half, black right half
    frame[6:, :, 2] = 255  # blue in the lower rows
    text = sixel.encode(frame)
    assert "!20" in text  # a run of twenty columns is written once
    assert np.array_equal(sixel_image(text), frame[..., :3])


def test_sixel_refuses_what_is_not_a_frame() -> None:
    with pytest.raises(RenderError, match=r"sixel: expected a \(height, width, 4\) uint8 RGBA array"):
        sixel.encode(np.zeros((4, 4, 3), np.uint8))


@pytest.mark.parametrize(("env", "expected"), [
    ({"TERM": "xterm-kitty"}, "kitty"),
    ({"TERM": "xterm-256color", "KITTY_WINDOW_ID": "1"}, "kitty"),
    ({"TERM": "xterm-256color", "TERM_PROGRAM": "ghostty"}, "kitty"),
    ({"TERM": "foot"}, "sixel"),
    ({"TERM": "mlterm"}, "sixel"),
    ({"TERM": "xterm-256color", "TERM_PROGRAM": "WezTerm"}, "sixel"),
    ({"TERM": "xterm-256color"}, "halfblocks"),
    ({"TERM": "xterm-kitty", "TMUX": "/tmp/tmux-0/default,1,0"}, "halfblocks"),  # tmux does not pass them on
    ({"TERM": "tmux-256color"}, "halfblocks"),
    ({"TERM": "foot", "PHYSINK_GRAPHICS": "halfblocks"}, "halfblocks"),
    ({"TERM": "xterm", "PHYSINK_GRAPHICS": "sixel"}, "sixel"),
])
def test_the_protocol_is_chosen_from_the_environment(env, expected) -> None:
    assert choose(env) == expected


def test_a_bad_override_is_named() -> None:
    with pytest.raises(RenderError, match="PHYSINK_GRAPHICS='png'"):
        choose({"PHYSINK_GRAPHICS": "png"})


# -- what the terminal says it can do (issue 30) ----------------------------------------------------------------------

XTERM_VT340 = b"\x1bP>|XTerm(379)\x1b\\\x1b[?63;1;2;4;6;9;15;16;22;28;29c"  # xterm -ti vt340 (Debian 12)
XTERM = b"\x1bP>|XTerm(379)\x1b\\\x1b[?64;1;2;6;9;15;16;17;18;21;22;28;29c"  # xterm as a VT420: no Sixel
KITTY_026 = b"\x1b_Gi=31;OK\x1b\\\x1bP>|kitty(0.26.5)\x1b\\\x1b[?62;c"  # Debian 12's kitty
KITTY_035 = b"\x1b_Gi=31;OK\x1b\\\x1bP>|kitty(0.35.2)\x1b\\\x1b[?62;c"


@pytest.mark.parametrize(("answer", "expected", "noted"), [
    (XTERM_VT340, "sixel", False),
    (XTERM, "halfblocks", False),
    (KITTY_035, "kitty", False),
    (KITTY_026, "halfblocks", True),  # no Unicode placeholders before 0.28: half-blocks, and a note saying why
    (b"\x1b[?6c", "halfblocks", False),  # a VT102 (pyte)
])
def test_the_protocol_is_chosen_from_what_the_terminal_answers_whatever_term_says(answer, expected, noted) -> None:
    from physink_tui.tui.graphics import TerminalReply, choice

    reply = TerminalReply.parse(answer)
    assert reply is not None
    for term in ("xterm-kitty", "foot", "xterm-256color"):  # TERM does not decide once the terminal answered
        kind, note = choice({"TERM": term}, reply)
        assert kind == expected and (note is not None) == noted
    if noted:
        assert "0.26.5" in note and "0.28" in note


def test_no_answer_is_no_reply() -> None:
    from physink_tui.tui.graphics import TerminalReply

    assert TerminalReply.parse(b"") is None and TerminalReply.parse(b"\x1b_Gi=31;OK\x1b\\") is None


def answering(master: int, answer: bytes, asked: list[bytes]) -> None:
    """A terminal on the pty's ``master`` side: reads the queries until DA1's, then answers ``answer``."""
    import os
    import select

    data = b""
    while not data.endswith(b"\x1b[c"):
        if not select.select([master], [], [], 10)[0]:
            return
        data += os.read(master, 4096)
    asked.append(data)
    os.write(master, answer)


@pytest.mark.parametrize("answer", [XTERM_VT340, KITTY_026])
def test_probe_asks_the_terminal_and_reads_its_answers(answer) -> None:
    import os
    import pty
    import termios
    import threading

    from physink_tui.tui.graphics import QUERIES, TerminalReply, probe

    master, slave = pty.openpty()
    try:
        modes = termios.tcgetattr(slave)
        asked: list[bytes] = []
        terminal = threading.Thread(target=answering, args=(master, answer, asked))
        terminal.start()
        reply = probe(slave, slave, wait=30)
        terminal.join()
        assert asked == [QUERIES]
        assert reply == TerminalReply.parse(answer)
        assert termios.tcgetattr(slave) == modes  # echo and line editing back as they were
    finally:
        os.close(master)
        os.close(slave)


def test_probe_of_a_terminal_that_answers_nothing_is_none() -> None:
    import os
    import pty

    from physink_tui.tui.graphics import QUERIES, probe

    master, slave = pty.openpty()
    null = os.open(os.devnull, os.O_RDONLY)
    try:
        assert probe(slave, slave, wait=0.2) is None
        assert probe(null, slave) is None  # not a terminal: nothing is asked
        assert os.read(master, 4096) == QUERIES  # asked once, the first time
    finally:
        for fd in (master, slave, null):
            os.close(fd)
