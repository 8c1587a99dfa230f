"""`physink decode`'s plain path (no numpy) writes, byte for byte, what the numpy path writes, stdout and summary,
and hands every capture it cannot read plainly to the full parser."""

from __future__ import annotations

import io
import subprocess
import sys
from pathlib import Path

import pytest
from shared_data import shared_path

from physink_tui.commands.decode import _decoder_of, stream_decode, summary, write_jsonl
from physink_tui.commands.decode_plain import write_plain
from physink_tui.errors import PhysinkError
from physink_tui.input.captures.parser import parse_capture_text
from physink_tui.input.captures.plain import read_plain, report_bytes

HID_DIR = shared_path("hid", module_level=True)
ROOT = Path(__file__).resolve().parents[1]
WACOM = ROOT / "tests" / "recorded_hid" / "wacom-ff0d-strokes.hid"


def _numpy_path(text: str) -> tuple[str, str]:
    capture = parse_capture_text(text, "c.hid")
    out = io.StringIO()
    results = stream_decode(capture, write_jsonl, out)
    return out.getvalue(), summary(capture, results)


def _plain_path(text: str) -> tuple[str, str] | None:
    capture = read_plain(text.encode(), "c.hid")
    if capture is None:
        return None
    decoders = [(device.index, _decoder_of(capture.path, device)) for device in capture.devices]
    out = io.StringIO()
    write_plain(capture, decoders, out)
    return out.getvalue(), summary(capture, [(index, decoder, None) for index, decoder in decoders])


def _both(text: str) -> tuple[tuple[str, str], tuple[str, str] | None]:
    return _numpy_path(text), _plain_path(text)


@pytest.mark.parametrize("path", sorted(HID_DIR.glob("*.hid")), ids=lambda p: p.name)
def test_shared_captures_decode_the_same_both_ways(path: Path) -> None:
    text = path.read_bytes().decode("utf-8", errors="replace").removeprefix("\ufeff")
    try:
        full = _numpy_path(text)
    except PhysinkError as exc:  # a capture the full path refuses is refused plainly too, with the same words
        with pytest.raises(PhysinkError) as plain_exc:
            if _plain_path(text) is None:
                raise exc
        assert str(plain_exc.value) == str(exc)
        return
    plain = _plain_path(text)
    if plain is not None:
        assert plain == full


def test_most_shared_captures_take_the_plain_path() -> None:
    """The plain path is the usual one, not an exception: every shared capture that decodes is plain except the
    few with damaged lines or glitched stamps (the full parser reports those)."""
    paths = sorted(HID_DIR.glob("*.hid"))
    plain = [p for p in paths if read_plain(p.read_bytes(), str(p)) is not None]
    assert len(plain) >= 0.9 * len(paths)


def _capture(events: str, header: str | None = None) -> str:
    lines = WACOM.read_text().splitlines()
    head = header if header is not None else "\n".join(x for x in lines if not x.startswith("E:"))
    return head + "\n" + events


def _wacom_events(k: int = 40) -> list[str]:
    return [x for x in WACOM.read_text().splitlines() if x.startswith("E:")][:k]


def test_edge_stamps_and_reports_agree_or_fall_back() -> None:
    events = _wacom_events()
    cases = {
        "plain": "\n".join(events) + "\n",
        "no final newline": "\n".join(events),
        "stamps without a fraction and with 7 decimals": "\n".join(
            e.replace(e.split(" ")[1], s) for e, s in zip(events, ["3", "3.1234567", "4.5", "00004.60", "5"] * 8,
                                                               strict=False)) + "\n",
        "tiny stamps (printed with an exponent)": "\n".join(
            e.replace(e.split(" ")[1], f"0.0000{k}{k}") for k, e in enumerate(events[:9], 1)) + "\n",
        "upper-case hex": "\n".join(e.upper() for e in events) + "\n",
        "comments between events": "\n".join(f"{e}\n# a decoded report" for e in events) + "\n",
        "an empty report and a truncated one": "\n".join(
            [*events[:5], "E: 000009.000000 0", "E: 000009.100000 2 02 00", *events[5:]]) + "\n",
        "time going backwards": "\n".join([*events[10:20], *events[:10]]) + "\n",
        "a glitched stamp": "\n".join(
            [*events[:5], events[5].replace(events[5].split(" ")[1], "000099.000000"), *events[6:]]) + "\n",
        "a bad line": "\n".join([*events[:5], "E: 1.0 3 02 00", *events[5:]]) + "\n",
        "CRLF": "\r\n".join(events) + "\r\n",
        "two spaces": "\n".join([*events[:5], events[5].replace(" ", "  ", 1), *events[6:]]) + "\n",
    }
    fell_back = []
    for name, body in cases.items():
        full, plain = _both(_capture(body))
        if plain is None:
            fell_back.append(name)
        else:
            assert plain == full, name
    assert fell_back == ["a glitched stamp", "a bad line", "CRLF", "two spaces"]


def test_two_devices_in_one_capture_agree() -> None:
    lines = WACOM.read_text().splitlines()
    head = [x for x in lines if not x.startswith("E:")]
    events = _wacom_events(30)
    text = "\n".join(["D: 0", *head, *events[:10], "D: 1", *head, *events[10:20], "D: 0", *events[20:]]) + "\n"
    full, plain = _both(text)
    assert plain is not None and plain == full
    assert "device 1:" in plain[1]


def test_report_bytes_reads_only_the_exact_form() -> None:
    assert report_bytes("3 02 0a FF") == b"\x02\x0a\xff"
    assert report_bytes("0") == b""
    for bad in ("3 02 0a", "3 020a ff", "2 02  0a", "2 02 0a ", "x 02", "2 02 0g", "0 ", "2 02\t0a", "1 ٠٢"):
        assert report_bytes(bad) is None, bad


def test_the_decode_command_does_not_import_numpy() -> None:
    """Start-up is most of a small capture's decoding: `physink decode` of a plain capture never imports numpy."""
    probe = ("import sys; from physink_tui.cli import main; status = main(['decode', sys.argv[1]]); "
             "sys.stderr.write('numpy imported' if 'numpy' in sys.modules else 'no numpy'); sys.exit(status)")
    done = subprocess.run([sys.executable, "-c", probe, str(WACOM)], capture_output=True, text=True, timeout=120,
                          cwd=ROOT)
    assert done.returncode == 0, done.stderr
    assert done.stderr.endswith("no numpy")
    assert done.stdout.count("\n") > 1000


def test_a_capture_past_the_plain_size_streams_through_the_numpy_path(monkeypatch, capsys) -> None:
    """A capture larger than `PLAIN_MAX_BYTES` is read once (its first bytes are not lost) and decoded the same."""
    from physink_tui.cli import main
    from physink_tui.commands import decode

    assert main(["decode", str(WACOM)]) == 0
    plain = capsys.readouterr()
    taken = []
    real = decode.stream_decode

    def counted(*args, **kwargs):  # the numpy path, noted
        taken.append(1)
        return real(*args, **kwargs)

    monkeypatch.setattr(decode, "PLAIN_MAX_BYTES", 1000)
    monkeypatch.setattr(decode, "stream_decode", counted)
    assert main(["decode", str(WACOM)]) == 0
    streamed = capsys.readouterr()
    assert taken == [1]
    assert streamed.out == plain.out and streamed.err == plain.err

