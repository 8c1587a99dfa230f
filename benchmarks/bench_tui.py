"""Benchmark: the TUI's scene view while a stroke is drawn on a 120x40 terminal, pen-to-screen latency, and key
response while a tablet streams 1,000 samples a second.

The app runs headless (Textual's ``run_test``: the whole app, its compositor and the session's runner thread, no
real terminal writing). A thread pushes pen samples through the mouse pen source (the same path a tablet's
samples take after decoding: `SourcePump` to the runner, the session, a view, the scene view) at RATE a second,
drawing a long zig-zag stroke. Measured:

- redraws: scene-view frames drawn a second during the stroke (render with skia, 2x2 supersampling, half blocks),
  with the runner publishing at most --max-fps views a second (the app's default, 60), and
  the wall time of one redraw;
- latency: from a sample being pushed to the first scene-view frame whose ink includes it;
- keys: while a tablet's HID reports stream in at 1,000 a second (the bundled egg cracker's capture, 5,000
  reports: decoded, turned into strokes and recognised in the session), from a key press to its reaction: ``?`` to the
  help screen being up (the UI thread's), and ``d`` / ``s`` to the view showing demo / sketch mode (through the
  session, which builds the demonstration's world of the scene drawn so far), right after the help screen closed
  and alone.

Usage: .venv/bin/python benchmarks/bench_tui.py [--seconds S] [--runs N] [--max-fps F] [--presses N] [--key-runs N]
"""

from __future__ import annotations

import argparse
import asyncio
import statistics
import threading
import time

from physink_tui.commands.demo import demo_journal
from physink_tui.formats.journal.entries import HidEntry
from physink_tui.tui.app import TuiOptions, make_app
from physink_tui.tui.screens.modals import HelpScreen
from physink_tui.tui.widgets.scene_view import SceneView

SIZE = (120, 40)


def _percentile(values: list[float], q: float) -> float:
    values = sorted(values)
    return values[min(len(values) - 1, int(q * len(values)))] if values else float("nan")


async def one_run(seconds: float, rate: float, max_fps: float) -> dict[str, float]:
    app = make_app(TuiOptions(tablet=False, journal=False, recover=False, max_fps=max_fps))
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause(0.5)
        scene = app.main.query_one(SceneView)
        pushed: list[float] = []
        shown: list[float] = []
        draws: list[float] = []
        original = scene._draw

        def draw() -> None:
            original()
            now = time.perf_counter()
            view = scene.view
            draws.append(now)
            inked = len(view.ink[0]) if view is not None and view.ink else 0
            while len(shown) < min(inked, len(pushed)):
                shown.append(now)

        scene._draw = draw
        mouse = app.live.mouse
        stop = threading.Event()

        def pen() -> None:
            k = 0
            start = time.perf_counter()
            mouse.push(0.1, 0.5, tip=False)
            while not stop.is_set():
                due = start + k / rate
                delay = due - time.perf_counter()
                if delay > 0:
                    time.sleep(delay)
                u = (k / rate) / seconds
                x = 0.1 + 0.8 * u
                y = 0.5 + 0.3 * (((k // 40) % 2) * 2 - 1) * ((k % 40) / 40 - 0.5)
                pushed.append(time.perf_counter())
                mouse.push(x, y, p=0.6, tip=True)
                k += 1
            mouse.push(x, y, tip=False)

        thread = threading.Thread(target=pen)
        first_draw = len(draws)
        cpu0, t0 = time.process_time(), time.perf_counter()
        thread.start()
        await pilot.pause(seconds)
        stop.set()
        thread.join()
        wall = time.perf_counter() - t0
        cpu = time.process_time() - cpu0
        frames = len(draws) - first_draw
        draw_ms = [s * 1000 for s in scene.draw_seconds[-frames:]] if frames else []
        latency = [(s - p) * 1000 for p, s in zip(pushed, shown, strict=False)]
        return {"fps": frames / wall, "draw_ms": statistics.median(draw_ms) if draw_ms else float("nan"),
                "latency_p50": _percentile(latency, 0.5), "latency_p95": _percentile(latency, 0.95),
                "cpu": cpu / wall, "samples": len(pushed)}


async def _until(condition, timeout: float = 5.0) -> None:
    deadline = time.perf_counter() + timeout
    while not condition():
        if time.perf_counter() > deadline:
            raise TimeoutError("no reaction within 5 s")
        await asyncio.sleep(0.001)


async def key_run(presses: int, rate: float, help_first: bool = True) -> tuple[list[float], list[float]]:
    """Key press to reaction while the bundled egg cracker's HID reports stream in at ``rate`` a second (once;
    decoded, followed to strokes and recognised in the session, as a live tablet's are). With ``help_first`` each
    ``d``/``s`` comes right after the help screen was opened and closed (measured too), so it waits for the main
    screen's repaint; without, it comes alone."""
    header, entries = demo_journal()
    reports = [e for e in entries if isinstance(e, HidEntry)]
    app = make_app(TuiOptions(header=header, tablet=False, journal=False, recover=False))
    ui: list[float] = []
    times: list[float] = []
    async with app.run_test(size=SIZE) as pilot:
        await pilot.pause(0.5)
        submit = app.live.submit
        stop = threading.Event()

        def stream() -> None:
            k, start = 0, time.perf_counter()
            while not stop.is_set() and k < len(reports):
                delay = start + k / rate - time.perf_counter()
                if delay > 0:
                    time.sleep(delay)
                submit(reports[k])
                k += 1

        thread = threading.Thread(target=stream)
        thread.start()
        for i in range(presses):
            if help_first:
                t0 = time.perf_counter()
                app.simulate_key("question_mark")  # the UI's own reaction: the help screen is up
                await _until(lambda: isinstance(app.screen, HelpScreen))
                ui.append((time.perf_counter() - t0) * 1000)
                app.simulate_key("escape")
                await _until(lambda: not isinstance(app.screen, HelpScreen))
            else:
                await pilot.pause(0.1)
            want = "demo" if i % 2 == 0 else "sketch"
            t0 = time.perf_counter()
            app.simulate_key("d" if want == "demo" else "s")  # the session's: the view in the new mode
            await _until(lambda want=want: getattr(app.live.runner.latest_view(), "mode", None) == want)
            times.append((time.perf_counter() - t0) * 1000)
            await pilot.pause(0.2)
        stop.set()
        thread.join()
    return ui, times


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--seconds", type=float, default=3.0)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--rate", type=float, default=200.0, help="pen samples a second while drawing")
    parser.add_argument("--max-fps", type=float, default=60.0)
    parser.add_argument("--presses", type=int, default=15, help="(each about 0.3 s, within the 5 s stream)")
    parser.add_argument("--key-runs", type=int, default=3, help="key measurements, pooled")
    args = parser.parse_args()
    runs = [asyncio.run(one_run(args.seconds, args.rate, args.max_fps)) for _ in range(args.runs)]
    print(f"scene view on {SIZE[0]}x{SIZE[1]}, stroke at {args.rate:g} samples/s, views <= {args.max_fps:g}/s, "
          f"{args.runs} runs of {args.seconds:g} s (medians):")
    for key, unit in (("fps", "redraws/s"), ("draw_ms", "ms per redraw"), ("latency_p50", "ms pen->screen p50"),
                      ("latency_p95", "ms pen->screen p95"), ("cpu", "CPU (cores)")):
        values = [r[key] for r in runs]
        print(f"  {statistics.median(values):8.2f} {unit}   (runs: {', '.join(f'{v:.1f}' for v in values)})")
    ui: list[float] = []
    after_help: list[float] = []
    alone: list[float] = []
    for _ in range(args.key_runs):
        shown, keys = asyncio.run(key_run(args.presses, 1000.0))
        ui += shown
        after_help += keys
        alone += asyncio.run(key_run(args.presses, 1000.0, help_first=False))[1]
    print(f"while 1,000 HID reports/s stream ({args.key_runs} runs of {args.presses} presses each, pooled):")
    for what, values in (("? -> help screen up", ui), ("d/s right after the help closed -> the view's new mode",
                                                         after_help), ("d/s alone -> the view's new mode", alone)):
        print(f"  {what}: p50 {_percentile(values, 0.5):.1f} ms, p95 {_percentile(values, 0.95):.1f} ms, "
              f"max {max(values):.1f} ms")


if __name__ == "__main__":
    main()
