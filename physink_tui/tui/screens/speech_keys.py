"""The main screen's push-to-talk: the `v` key toggles listening and holding the pen's barrel button listens until it
is released: `SpeechKeys`, a helper the screen owns. What it is doing or heard reaches the screen as `SpeechStatus`
messages (posted from its threads); starting and stopping, which block, run in the screen's ``speech`` workers.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from functools import partial

from textual.message import Message
from textual.screen import Screen

from physink_tui.input.speech.microphone import StreamFactory
from physink_tui.session.view import SessionView
from physink_tui.tui.live import LiveSession
from physink_tui.tui.push_to_talk import PushToTalk, barrel_held
from physink_tui.tui.widgets.bars import StatusBar


@dataclass
class SpeechStatus(Message):
    """What push-to-talk is doing or heard (posted from its threads)."""

    text: str


def _labels(view: SessionView | None) -> list[str]:
    """The labels speech listens for: the components' in ``view``."""
    return [] if view is None else list(view.scene.labels().values())


class SpeechKeys:
    """Push-to-talk for ``screen``: `attach` it to a live session, then `toggle` on the key and `follow` each view
    (the barrel button held or released)."""

    def __init__(self, screen: Screen[None]) -> None:
        self._screen = screen
        self.talk: PushToTalk | None = None
        self._barrel = False  # the barrel button held, as last followed

    def attach(self, live: LiveSession, stream: StreamFactory | None) -> None:
        """Listen for ``live`` on ``stream`` (default: the microphone); stopping the session stops listening."""
        self.talk = PushToTalk(live.runner, lambda text: self._screen.post_message(SpeechStatus(text)),
                               stream=stream)
        live.on_stop(self.talk.stop)

    def toggle(self, view: SessionView | None, status: StatusBar) -> None:
        """The key: listen, or stop listening (and hear what was said), for the labels of ``view``."""
        if self.talk is None:
            return
        status.set(speech="speech: stopping…" if self.talk.listening else "speech: starting…")
        self._run(self.talk.toggle, view)

    def follow(self, view: SessionView) -> None:
        """Listen while some pen of ``view`` holds its barrel button; stop when it is released."""
        if self.talk is None or barrel_held(view.pens) == self._barrel:
            return
        self._barrel = self.talk.button_pressed = not self._barrel
        self._run(self.talk.follow_button, view)

    def _run(self, what: Callable[[list[str]], None], view: SessionView | None) -> None:
        self._screen.run_worker(partial(what, _labels(view)), thread=True, group="speech")
