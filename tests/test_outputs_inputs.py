"""Issue 11, outputs and inputs: a fresh output folder per run, every OSError one line, stdout pipes and full
disks, inputs read once (pipes, FIFOs), files of the wrong kind named, bad timelines and strokes named by path."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import threading
from pathlib import Path

import pytest

from physink_tui.cli import main

ROOT = Path(__file__).resolve().parent.parent
JOURNAL = ROOT / "tests" / "journals" / "bouncing_below_b.physink.jsonl"
CAPTURE = ROOT / "tests" / "recorded_hid" / "uclogic-v1-strokes.hid"
ENV = {**os.environ, "PYTHONPATH": str(ROOT)}


def physink(*args: str, **kw) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "physink_tui", *args], env=ENV, text=True,
                          capture_output="stdout" not in kw, timeout=120, **kw)


def one_line_error(err: str, *fragments: str) -> None:
    """One ``physink:`` line on stderr (after any progress lines), naming each fragment; no traceback."""
    errors = [line for line in err.splitlines() if line.startswith("physink:")]
    assert "Traceback" not in err and len(errors) == 1 and err.endswith(errors[0] + "\n"), err
    for fragment in fragments:
        assert fragment in errors[0], err


@pytest.fixture(scope="module")
def replayed(tmp_path_factory) -> Path:
    """A replay of a demonstrated journal: project.json and timeline.json with a timeline."""
    out = tmp_path_factory.mktemp("replayed")
    assert main(["replay", str(JOURNAL), "--out", str(out)]) == 0
    return out


# --- outputs ----------------------------------------------------------------------------------------------------

def test_a_reused_out_folder_holds_only_this_runs_files(tmp_path, capsys) -> None:
    out = tmp_path / "out"
    out.mkdir()
    for stale in ("timeline.json", "timeline.txt", "project.json", ".project.json.k1ll3d.tmp"):
        (out / stale).write_text("old run\n")
    (out / "notes.txt").write_text("mine\n")
    (out / ".other.tmp").write_text("not ours\n")

    assert main(["replay", str(CAPTURE), "--out", str(out)]) == 0  # a capture: gestures only, no project

    assert sorted(p.name for p in out.iterdir()) == [".other.tmp", "gestures.jsonl", "notes.txt"]


def test_out_naming_an_existing_file_says_so(tmp_path, capsys) -> None:
    (tmp_path / "f").write_text("x")
    assert main(["replay", str(CAPTURE), "--out", str(tmp_path / "f")]) == 1
    one_line_error(capsys.readouterr().err, str(tmp_path / "f"), "not a folder")


def test_out_under_a_regular_file_is_one_line(tmp_path, capsys) -> None:
    (tmp_path / "f").write_text("x")
    assert main(["demo", "--out", str(tmp_path / "f" / "sub")]) == 1
    one_line_error(capsys.readouterr().err, str(tmp_path / "f" / "sub"), "Not a directory")


@pytest.mark.parametrize("name", ["gestures.jsonl", "timeline.json", "timeline.txt"])
def test_a_file_that_cannot_be_written_is_one_line_naming_it(tmp_path, capsys, name: str) -> None:
    # A folder in the way of an output file: a real OSError (EISDIR) from the rename, as root too.
    (tmp_path / name).mkdir()
    assert main(["replay", str(JOURNAL), "--out", str(tmp_path)]) == 1
    one_line_error(capsys.readouterr().err, str(tmp_path / name), "cannot write")
    assert not [p for p in tmp_path.iterdir() if p.name.endswith(".tmp")]


NO_DAC = ["setpriv", "--inh-caps=-dac_override,-dac_read_search", "--bounding-set=-dac_override,-dac_read_search", "--"]


@pytest.mark.skipif(shutil.which("setpriv") is None, reason="needs util-linux setpriv to drop CAP_DAC_OVERRIDE")
@pytest.mark.parametrize("command", [["demo", "--out"], ["replay", str(JOURNAL), "--out"]])
def test_a_read_only_output_folder_is_one_line(tmp_path, command: list[str]) -> None:
    # chmod does not stop root: the command runs without CAP_DAC_OVERRIDE, so 0o500 gives a real EACCES.
    out = tmp_path / "out"
    out.mkdir(mode=0o500)
    try:
        done = subprocess.run([*NO_DAC, sys.executable, "-m", "physink_tui", *command, str(out)], env=ENV,
                              text=True, capture_output=True, timeout=120, cwd=ROOT)
    finally:
        out.chmod(0o700)
    assert done.returncode == 1, done.stderr
    one_line_error(done.stderr, str(out), "Permission denied")


def _can_mount() -> bool:
    if shutil.which("unshare") is None:
        return False
    probe = subprocess.run(["unshare", "-m", "sh", "-c", "mount -t tmpfs -o size=4k tmpfs /mnt"],
                           capture_output=True, timeout=60)
    return probe.returncode == 0


@pytest.mark.skipif(not _can_mount(), reason="needs unshare and mount (root) for a private full or read-only tmpfs")
@pytest.mark.parametrize(("options", "command", "cause"), [
    ("size=64k", ["demo", "--out"], "No space left on device"),
    ("ro", ["replay", str(JOURNAL), "--out"], "Read-only file system"),
])
def test_a_full_or_read_only_file_system_is_one_line(tmp_path, options: str, command: list[str], cause: str) -> None:
    # A tmpfs mounted in a private mount namespace: real ENOSPC and EROFS, gone when the command ends.
    out = tmp_path / "out"
    out.mkdir()
    line = f"mount -t tmpfs -o {options} tmpfs {out} && exec {sys.executable} -m physink_tui {' '.join(command)} {out}"
    done = subprocess.run(["unshare", "-m", "sh", "-c", line], env=ENV, text=True, capture_output=True, timeout=120,
                          cwd=ROOT)
    assert done.returncode == 1, done.stderr
    one_line_error(done.stderr, str(out), cause)


@pytest.mark.parametrize("command", [["decode", str(CAPTURE)], ["recognize", "STROKES"]])
def test_a_full_stdout_is_one_line(tmp_path, command: list[str]) -> None:
    strokes = tmp_path / "s.jsonl"
    strokes.write_text('{"strokes": [[[0, 0], [10, 0], [20, 0], [30, 0]]]}\n' * 2000)
    with open("/dev/full", "w") as full:
        done = physink(*[str(strokes) if a == "STROKES" else a for a in command], stdout=full,
                       stderr=subprocess.PIPE)
    assert done.returncode == 1
    one_line_error(done.stderr, "<stdout>", "No space left on device")


def test_a_full_stdout_still_writes_the_files(tmp_path) -> None:
    with open("/dev/full", "w") as full:
        done = physink("replay", str(JOURNAL), "--out", str(tmp_path), stdout=full, stderr=subprocess.PIPE)
    assert done.returncode == 1 and "No space left on device" in done.stderr and "Traceback" not in done.stderr
    assert {"project.json", "timeline.json", "gestures.jsonl"} <= {p.name for p in tmp_path.iterdir()}


def test_a_closed_stdout_pipe_ends_printing_quietly_and_the_files_are_written(tmp_path) -> None:
    # `physink replay J --out D | head -1`
    child = subprocess.Popen([sys.executable, "-m", "physink_tui", "replay", str(JOURNAL), "--out", str(tmp_path)],
                             env=ENV, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    assert child.stdout is not None and child.stderr is not None
    first = child.stdout.readline()
    child.stdout.close()
    err = child.stderr.read().decode()
    assert child.wait(timeout=120) == 0
    assert first.strip() and "Traceback" not in err and "Broken pipe" not in err, err
    assert {"project.json", "timeline.json", "timeline.txt", "gestures.jsonl"} <= {p.name for p in tmp_path.iterdir()}


# --- inputs -----------------------------------------------------------------------------------------------------

def _bash(line: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(["bash", "-c", line], env=ENV, text=True, capture_output=True, timeout=120)


def test_replay_reads_a_pipe_once(tmp_path) -> None:
    done = _bash(f"{sys.executable} -m physink_tui replay <(cat {JOURNAL}) --out {tmp_path}")
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "timeline.json").exists()


def test_timeline_and_equiv_read_pipes_once(replayed: Path) -> None:
    project, timeline = replayed / "project.json", replayed / "timeline.json"
    done = _bash(f"{sys.executable} -m physink_tui timeline <(cat {project}) --format json")
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout)["events"]
    done = _bash(f"{sys.executable} -m physink_tui equiv --json <(cat {project}) <(cat {timeline})")
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout)["equivalent"] is True


def test_replay_reads_a_fifo(tmp_path) -> None:
    fifo = tmp_path / "journal.fifo"
    os.mkfifo(fifo)

    def feed() -> None:
        with open(fifo, "wb") as f:
            f.write(JOURNAL.read_bytes())

    writer = threading.Thread(target=feed, daemon=True)
    writer.start()
    done = physink("replay", str(fifo), "--out", str(tmp_path / "out"))
    writer.join(timeout=60)  # hang guard
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "out" / "project.json").exists()


def test_replay_names_a_project_as_a_project(replayed: Path, tmp_path, capsys) -> None:
    assert main(["replay", str(replayed / "project.json"), "--out", str(tmp_path)]) == 1
    one_line_error(capsys.readouterr().err, "this is a project (.physink.json); replay takes a journal")


def test_replay_names_a_timeline_as_a_timeline(replayed: Path, tmp_path, capsys) -> None:
    assert main(["replay", str(replayed / "timeline.json"), "--out", str(tmp_path / "out")]) == 1
    one_line_error(capsys.readouterr().err, "this is a timeline (timeline.json); replay takes a journal")


def test_replay_names_an_empty_file(tmp_path, capsys) -> None:
    (tmp_path / "e.physink.jsonl").write_bytes(b"")
    assert main(["replay", str(tmp_path / "e.physink.jsonl"), "--out", str(tmp_path / "out")]) == 1
    one_line_error(capsys.readouterr().err, "empty file")


def test_replay_accepts_a_journal_with_a_bom(tmp_path, capsys) -> None:
    journal = tmp_path / "bom.physink.jsonl"
    journal.write_bytes(b"\xef\xbb\xbf" + JOURNAL.read_bytes())
    assert main(["replay", str(journal), "--out", str(tmp_path / "out")]) == 0, capsys.readouterr().err
    assert (tmp_path / "out" / "timeline.json").exists()


@pytest.mark.parametrize(("bad", "fragment"), [
    (b"\xff\xfe{}\n", ":2: not UTF-8"),
    (b'{"strokes": [[[' + b"9" * 400 + b", 0], [1, 2]]]}\n", ":2: stroke 0 point 0"),
    (b"[" * 100_000 + b"\n", ":2: not usable JSON"),
    (b'{"strokes": [[[1e308, 0], [10, 0], [20, 1e308]]]}\n', ":2: stroke 0 point 0"),
])
def test_recognize_names_a_bad_line_and_keeps_the_lines_before(tmp_path, bad: bytes, fragment: str) -> None:
    strokes = tmp_path / "s.jsonl"
    strokes.write_bytes(b'{"strokes": [[[0, 0], [10, 0], [20, 0], [30, 0]]]}\n' + bad)
    done = physink("recognize", str(strokes))
    assert done.returncode == 1
    one_line_error(done.stderr, f"{strokes}{fragment}")
    assert json.loads(done.stdout)["kind"] == "line"


def _mutated(timeline: dict, change) -> dict:
    doc = json.loads(json.dumps(timeline))
    change(doc["events"])
    return doc


CONTACT = 2  # the first contact event of the replayed timeline (checked below)
TIMELINE_CHANGES = {
    "sides-not-a-list": (lambda ev: ev[CONTACT].update(sides=5), "events[2].sides: expected a list"),
    "regions-not-a-list": (lambda ev: ev[1].update(regions={"a": 1}), "events[1].regions: expected a list"),
    "cause-an-object": (lambda ev: ev[1].update(causes=[{"id": "e1"}]), "events[1].causes[0]: expected an event id"),
    "point-an-object": (lambda ev: ev[CONTACT].update(point={"x": 1, "y": 2}), "events[2].point: expected null or"),
    "huge-coordinate": (lambda ev: ev[1]["trajectory"][0].__setitem__(1, 1e308), "events[1].trajectory[0][1]"),
    "label-a-number": (lambda ev: ev[CONTACT]["components"][0].update(label=7), "events[2].components[0].label"),
    "user-label-a-list": (lambda ev: ev[0].update(user_label=[1]), "events[0].user_label"),
    "nan-t0": (lambda ev: ev[0].update(t0=float("nan")), "events[0].t0: expected a finite number"),
    "infinite-x": (lambda ev: ev[1]["trajectory"][0].__setitem__(1, float("inf")), "got Infinity"),
}


@pytest.mark.parametrize("case", sorted(TIMELINE_CHANGES))
@pytest.mark.parametrize("command", [["timeline", "FILE", "--format", "json"], ["timeline", "FILE", "--format", "dot"],
                                     ["equiv", "--json", "FILE", "FILE"], ["equiv", "FILE", "FILE"]])
def test_a_bad_timeline_is_one_line_naming_the_json_path(replayed, tmp_path, capsys, case, command) -> None:
    timeline = json.loads((replayed / "timeline.json").read_text())
    assert timeline["events"][CONTACT]["type"] == "contact"
    change, fragment = TIMELINE_CHANGES[case]
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps(_mutated(timeline, change)))
    assert main([str(bad) if a == "FILE" else a for a in command]) == 1
    out, err = capsys.readouterr()
    one_line_error(err, str(bad), fragment)
    assert out == "" and "nan" not in out.lower()


@pytest.mark.parametrize("case", ["nan-t0", "cause-an-object", "huge-coordinate", "label-a-number"])
def test_a_bad_timeline_inside_a_project_is_one_line(replayed, tmp_path, capsys, case) -> None:
    project = json.loads((replayed / "project.json").read_text())
    project["timeline"] = _mutated(project["timeline"], TIMELINE_CHANGES[case][0])
    bad = tmp_path / "bad.physink.json"
    bad.write_text(json.dumps(project))
    for command in (["timeline", str(bad), "--format", "dot"], ["equiv", "--json", str(bad), str(bad)]):
        assert main(command) == 1
        one_line_error(capsys.readouterr().err, str(bad), "timeline")


def test_a_bad_journal_through_a_pipe_is_named_by_the_pipe(tmp_path) -> None:
    bad = tmp_path / "bad.physink.jsonl"
    bad.write_bytes(b"".join(JOURNAL.read_bytes().splitlines(keepends=True)[:3]) + b'{"t": 1, "bogus": 2}\n')
    done = _bash(f"{sys.executable} -m physink_tui replay <(cat {bad}) --out {tmp_path / 'out'}")
    assert done.returncode == 1
    one_line_error(done.stderr, "/dev/fd/", "line 4")
    assert "physink-input-" not in done.stderr and not (tmp_path / "out").exists()


@pytest.mark.parametrize(("source", "fragment"), [
    (JOURNAL, "this is a journal (.physink.jsonl)"),
    (CAPTURE, "this is a capture (.hid)"),
    (None, "empty file"),
])
def test_timeline_names_a_file_of_the_wrong_kind(tmp_path, capsys, source: Path | None, fragment: str) -> None:
    path = tmp_path / "in.json"
    path.write_bytes(b"" if source is None else source.read_bytes())
    assert main(["timeline", str(path)]) == 1
    one_line_error(capsys.readouterr().err, str(path), fragment, "takes a timeline JSON file or a project")


def test_recognize_reads_a_stroke_with_its_times_when_every_point_has_one(tmp_path, monkeypatch) -> None:
    """`physink recognize` gives the recogniser the pen's times where every point of a stroke carries one (as sketch
    mode does, so the learned ranker sees the pen slow at corners), and none where a point lacks its time."""
    import physink_tui.scene.recognition.recognize as recognize

    seen: list[list[float] | None] = []
    real = recognize.recognize_stroke

    def spy(points, times=None, **kw):  # type: ignore[no-untyped-def]
        seen.append(None if times is None else list(times))
        return real(points, times, **kw)

    monkeypatch.setattr(recognize, "recognize_stroke", spy)
    strokes = tmp_path / "s.jsonl"
    strokes.write_text('{"strokes": [[[0, 0, 0.0], [10, 0, 0.01], [20, 0, 0.02], [30, 0, 0.03]]]}\n'
                       '{"strokes": [[[0, 0, 0.0], [10, 0], [20, 0, 0.02], [30, 0, 0.03]]]}\n')
    assert main(["recognize", str(strokes)]) == 0
    assert seen == [[0.0, 0.01, 0.02, 0.03], None]
