"""Acceptance tests of the HID pen decoder on the real descriptors and captures of the shared data folder."""

# The files are read in place from ``../shared/data/hid`` next to the repository and never copied into it
# (their licences differ); the module skips itself when that folder is not there. What is expected of each
# file is read from the folder's README (its quirks list and per-file sections), not hard-coded per file,
# except for the in-range polarities of README item 4, which are prose.

from __future__ import annotations

import bisect
import itertools
import math
import re
from dataclasses import dataclass
from functools import cache
from pathlib import Path

import pytest
from shared_data import shared_path

from physink_tui.errors import DescriptorError
from physink_tui.input.captures.capture import Capture, CaptureEvent
from physink_tui.input.hid.decoder import HidPenDecoder
from physink_tui.input.hid.descriptor import ReportDescriptor
from physink_tui.input.pen.sample import PenSample

HID_DIR = shared_path("hid", module_level=True)

README_PATH = HID_DIR / "README.md"
FILES = sorted(HID_DIR.glob("*.hid"))

MIN_SAMPLES = 20
DIAGONAL = math.sqrt(2.0)
MAX_STEP = 0.05 * DIAGONAL  # largest move between two touching samples less than GAP_S apart
GAP_S = 0.1  # segments are spliced with 1 s gaps, strokes run at 100+ Hz
TIP_DOWN_WINDOW = 3  # pressure must rise within this many samples of a tip-down transition
TIP_DOWN_TOLERANCE = 0.01  # fraction of tip-down transitions allowed to break that rule


# -- the README ---------------------------------------------------------------------------------------


@cache
def readme_text() -> str:
    return README_PATH.read_text(encoding="utf-8") if README_PATH.is_file() else ""


@cache
def readme_sections() -> dict[str, str]:
    """Per-file sections of the README (``### `name` `` up to the next heading), keyed by file name."""
    sections = {}
    for m in re.finditer(r"^### `([^`]+)`\n(.*?)(?=^#{1,3} |\Z)", readme_text(), re.M | re.S):
        sections[m.group(1)] = m.group(2)
    return sections


_PEN_LINE = re.compile(r"^  - id 0x([0-9a-f]{2}) \(([^,]+), (\d+) bytes\): (.*)$", re.M)
_PEN_USAGES = re.compile(r"Tip Switch|Tip Pressure|In Range")
_FIELD_X = re.compile(r"(?:: |, )X@")
_FIELD_Y = re.compile(r"(?:: |, )Y@")


def readme_pen_reports(name: str) -> list[tuple[int, str]]:
    """``(report id, collection name)`` of each report the README lists with pen usages and X/Y.

    Lines such as ``  - id 0x07 (Pen, 8 bytes): Tip Switch@bit8, ..., X@16:16[0..40000], Y@32:16[...]``.
    """
    found = []
    for m in _PEN_LINE.finditer(readme_sections().get(name, "")):
        fields = ": " + m.group(4)
        if _PEN_USAGES.search(fields) and _FIELD_X.search(fields) and _FIELD_Y.search(fields):
            found.append((int(m.group(1), 16), m.group(2)))
    return found


def readme_reports_seen(name: str) -> list[tuple[int, int, int, str]]:
    """``(report id, length, count, remark)`` from the section's "reports seen" line.

    E.g. ``0x09/8B x48141 declared as 6B; 0x12/8B x40`` gives ``(9, 8, 48141, "declared as 6B")``, ...
    """
    m = re.search(r"^- reports seen [^:]*: (.*)$", readme_sections().get(name, ""), re.M)
    if not m:
        return []
    seen = []
    for part in m.group(1).split(";"):
        pm = re.match(r"\s*0x([0-9a-f]{2})/(\d+)B x(\d+)\s*(.*)$", part)
        if pm:
            seen.append((int(pm.group(1), 16), int(pm.group(2)), int(pm.group(3)), pm.group(4).strip()))
    return seen


def readme_byte1_values(name: str) -> dict[int, set[int]]:
    """Report id -> the byte-1 values the section lists (``byte1 values for id 0x07 (top): 0xa1:10589``)."""
    values: dict[int, set[int]] = {}
    pattern = r"^- byte1 values for id 0x([0-9a-f]{2}) \(top\): (.*)$"
    for m in re.finditer(pattern, readme_sections().get(name, ""), re.M):
        values[int(m.group(1), 16)] = {int(v, 16) for v in re.findall(r"0x([0-9a-f]{1,2}):\d+", m.group(2))}
    return values


def readme_huion_v2_files() -> list[str]:
    """File names of the Huion "v2" captures the README's Gaps section lists (``Files: `digimend__...```)."""
    m = re.search(r"Huion \"v2\".*?Files: (.*?)\n\s*-", readme_text(), re.S)
    if not m:
        return []
    names = re.findall(r"`([^`]+)`", m.group(1))
    return [n.replace("...", "digimend_", 1) + ".hid" if n.startswith("...") else n + ".hid" for n in names]


# -- decoding, once per capture -------------------------------------------------------------------------


def _has_events(path: Path) -> bool:
    with path.open(encoding="utf-8", errors="replace") as f:
        return any(line.startswith("E:") for line in f)


CAPTURES = [p for p in FILES if _has_events(p)]


@dataclass(frozen=True)
class Decoded:
    """One capture decoded event by event with ``HidPenDecoder(descriptor, vid, pid)``."""

    decoder: HidPenDecoder
    events: tuple[CaptureEvent, ...]
    results: tuple[PenSample | None, ...]  # one per event
    segment_lines: tuple[int, ...]  # line numbers of the ``# segment:`` comments
    segment_names: tuple[str, ...]

    @property
    def samples(self) -> list[tuple[CaptureEvent, PenSample]]:
        return [(e, s) for e, s in zip(self.events, self.results, strict=True) if s is not None]

    def segment_of(self, line: int) -> int:
        """Index of the segment an event line belongs to (-1 before the first segment comment)."""
        return bisect.bisect_right(self.segment_lines, line) - 1

    def segment_name(self, line: int) -> str:
        i = self.segment_of(line)
        return self.segment_names[i] if i >= 0 else ""


@cache
def decoded(name: str) -> Decoded:
    path = HID_DIR / name
    capture = Capture.from_file(path)
    device = capture.devices[0]
    decoder = HidPenDecoder(device.descriptor, device.vid, device.pid)
    results = tuple(decoder.decode(e.data, e.t, e.line) for e in capture.events)
    seg_lines, seg_names = [], []
    with path.open(encoding="utf-8", errors="replace") as f:
        for lineno, line in enumerate(f, 1):
            if line.startswith("# segment:"):
                seg_lines.append(lineno)
                seg_names.append(line[len("# segment:") :].strip())
    return Decoded(decoder, capture.events, results, tuple(seg_lines), tuple(seg_names))


def _line_list(events: list[CaptureEvent], limit: int = 8) -> str:
    shown = ", ".join(f"line {e.line} [{e.data.hex(' ')}]" for e in events[:limit])
    return shown + (f" and {len(events) - limit} more" if len(events) > limit else "")


# -- the folder and its README ----------------------------------------------------------------------------


def test_folder_holds_descriptors_and_captures() -> None:
    assert FILES, f"no *.hid files in {HID_DIR}"
    assert CAPTURES, "no capture with E: events"


def test_readme_describes_every_file() -> None:
    assert readme_text(), f"{README_PATH} is missing or empty"
    missing = [p.name for p in FILES if p.name not in readme_sections()]
    assert not missing, f"README has no per-file section for {missing}"


# -- a) captures with events --------------------------------------------------------------------------------


@pytest.mark.parametrize("path", CAPTURES, ids=[p.name for p in CAPTURES])
def test_capture_decodes_to_normalised_samples(path: Path) -> None:
    d = decoded(path.name)
    samples = [s for _, s in d.samples]
    assert len(samples) > MIN_SAMPLES, f"only {len(samples)} pen samples from {len(d.events)} reports"
    bad = []
    for e, s in d.samples:
        values = (s.x, s.y, s.p)
        if not all(math.isfinite(v) and 0.0 <= v <= 1.0 for v in values):
            bad.append((e, f"x/y/p {values}"))
        for tilt in (s.tilt_x, s.tilt_y):
            if tilt is not None and not (math.isfinite(tilt) and -90.0 <= tilt <= 90.0):
                bad.append((e, f"tilt {tilt}"))
    assert not bad, f"{len(bad)} samples out of range, first: line {bad[0][0].line} {bad[0][1]}"

    stats = d.decoder.stats
    assert stats.reports == len(d.events)
    assert stats.samples == len(samples)
    assert stats.samples + sum(stats.ignored.values()) == stats.reports


@pytest.mark.parametrize("path", CAPTURES, ids=[p.name for p in CAPTURES])
def test_pen_moves_continuously_while_touching(path: Path) -> None:
    samples = decoded(path.name).samples
    jumps = []
    for (e0, a), (e1, b) in itertools.pairwise(samples):
        if a.tip and b.tip and 0.0 <= b.t - a.t < GAP_S:
            dist = math.hypot(b.x - a.x, b.y - a.y)
            if dist >= MAX_STEP:
                jumps.append((e0, e1, dist))
    if jumps:
        e0, e1, dist = jumps[0]
        pytest.fail(
            f"{len(jumps)} jumps of >= {MAX_STEP:.3f} while touching, first: line {e0.line} -> "
            f"line {e1.line} ({dist:.3f}; {e0.data.hex(' ')} -> {e1.data.hex(' ')})"
        )


@pytest.mark.parametrize("path", CAPTURES, ids=[p.name for p in CAPTURES])
def test_tip_agrees_with_pressure(path: Path) -> None:
    samples = decoded(path.name).samples
    pressure_without_tip = [e for e, s in samples if not s.tip and s.p != 0.0]
    assert not pressure_without_tip, (
        f"{len(pressure_without_tip)} samples with p > 0 but tip False: {_line_list(pressure_without_tip)}"
    )

    transitions, dry = 0, []
    for i, (e, s) in enumerate(samples):
        if s.tip and (i == 0 or not samples[i - 1][1].tip):
            transitions += 1
            if not any(later.p > 0.0 for _, later in samples[i : i + TIP_DOWN_WINDOW]):
                dry.append(e)
    print(f"{path.name}: {transitions} tip-down transitions, {len(dry)} without pressure")
    allowed = int(TIP_DOWN_TOLERANCE * transitions)
    assert len(dry) <= allowed, (
        f"{len(dry)} of {transitions} tip-down transitions (at most {allowed} allowed) have no pressure "
        f"within {TIP_DOWN_WINDOW} samples: {_line_list(dry)}"
    )


@pytest.mark.parametrize("path", CAPTURES, ids=[p.name for p in CAPTURES])
def test_time_never_decreases_within_a_segment(path: Path) -> None:
    d = decoded(path.name)
    samples = d.samples
    within, across = [], 0
    for (e0, a), (e1, b) in itertools.pairwise(samples):
        if b.t < a.t:
            if d.segment_of(e0.line) == d.segment_of(e1.line):
                within.append(e1)
            else:
                across += 1
    print(f"{path.name}: time goes back {across} times across segments, {len(within)} times within")
    assert not within, f"time goes backwards inside a segment {len(within)} times: {_line_list(within)}"


# README "Things a decoder must expect" and "Gaps": facts about particular files.

HUION_V2 = [p for p in CAPTURES if p.name in readme_huion_v2_files()]


def test_readme_names_a_present_huion_v2_capture() -> None:
    assert readme_huion_v2_files(), "README Gaps section lists no Huion v2 files"
    assert HUION_V2, f"none of {readme_huion_v2_files()} is in the folder"


@pytest.mark.parametrize("path", HUION_V2, ids=[p.name for p in HUION_V2])
def test_huion_v2_reports_decode_through_the_v2_layout(path: Path) -> None:
    d = decoded(path.name)
    assert d.decoder.layouts[0x08].source == "huion-v2"
    pen = [(e, s) for e, s in zip(d.events, d.results, strict=True) if e.data[0] == 0x08 and e.data[1] & 0x80
           and e.data[1] & 0xF0 not in (0xE0, 0xF0)]
    assert pen, "no v2 pen reports (byte 1 bit 7 set) in the capture"
    undecoded = [e for e, s in pen if s is None]
    assert not undecoded, f"{len(undecoded)} v2 pen reports gave no sample: {_line_list(undecoded)}"
    assert all(s.report == 0x08 and s.range for _, s in pen)
    # byte 1 bit 0 is the tip; 24-bit X = bytes 2-3 + byte 8, so a v2 tablet covers the full 0..1 range
    assert all(s.tip == bool(e.data[1] & 0x01) for e, s in pen if not e.data[1] & 0x06)
    assert max(s.x for _, s in pen) > 0.5 and max(s.y for _, s in pen) > 0.5


@pytest.mark.parametrize("path", HUION_V2, ids=[p.name for p in HUION_V2])
def test_huion_v2_pad_reports_are_not_pen_samples(path: Path) -> None:
    d = decoded(path.name)
    pad = [(e, s) for e, s in zip(d.events, d.results, strict=True)
           if e.data[0] == 0x08 and e.data[1] in (0xE0, 0xF0, 0xF1)]
    assert pad, "no pad (0xE0) or strip/dial (0xF0/0xF1) reports in the capture"
    as_pen = [e for e, s in pad if s is not None]
    assert not as_pen, f"{len(as_pen)} pad/strip/dial reports became pen samples: {_line_list(as_pen)}"
    assert sum(n for reason, n in d.decoder.stats.ignored.items() if "pad" in reason) == len(pad)


# README item 4: byte 1 of report 0x07 while the pen is in range and when it leaves, per device.
POLARITY = [
    # (file, segment name part or "" for all, byte 1 in range, byte 1 when leaving, README phrase)
    ("digimend__Huion_K26__if0.hid", "", {0xC0, 0xC1}, {0x80}, "Huion K26"),
    ("digimend__UC-Logic_WP1700U__if0.hid", "dumps_proprietary/", {0xC0, 0xC1}, {0x80},
     "UC-Logic WP1700U `dumps_proprietary/`"),
    ("digimend__Ugee_M708__if0.hid", "dumps2/", {0x80, 0x81}, {0xC0}, "Ugee M708 `dumps2/`"),
]
POLARITY = [case for case in POLARITY if (HID_DIR / case[0]).is_file()]


@pytest.mark.parametrize("case", POLARITY, ids=[c[0] for c in POLARITY])
def test_uclogic_family_in_range_polarity(case: tuple[str, str, set[int], set[int], str]) -> None:
    name, segment, in_range, leaving, phrase = case
    item4 = re.search(r"^4\. In Range polarity.*?(?=^\d+\. )", readme_text(), re.M | re.S)
    assert item4 and phrase in item4.group(0), f"README item 4 no longer mentions {phrase!r}"
    d = decoded(name)
    reports = [(e, s) for e, s in zip(d.events, d.results, strict=True)
               if e.data[0] == 0x07 and segment in d.segment_name(e.line)]
    hovering = [(e, s) for e, s in reports if e.data[1] in in_range]
    leaving_ = [(e, s) for e, s in reports if e.data[1] in leaving]
    assert hovering and leaving_, f"no in-range or leaving 0x07 reports in segment {segment!r}"

    wrong_in = [e for e, s in hovering if s is None or not s.range]
    wrong_out = [e for e, s in leaving_ if s is None or s.range or s.tip]
    assert not wrong_in, (
        f"{len(wrong_in)} of {len(hovering)} in-range reports (byte 1 in "
        f"{sorted(hex(v) for v in in_range)}) decoded as out of range: {_line_list(wrong_in)}"
    )
    assert not wrong_out, (
        f"{len(wrong_out)} of {len(leaving_)} leaving reports (byte 1 in "
        f"{sorted(hex(v) for v in leaving)}) decoded as in range: {_line_list(wrong_out)}"
    )


TEN_MOONS = [p for p in CAPTURES if p.name.startswith("digimend__10moons")]


def test_readme_states_the_10moons_double_reports() -> None:
    assert re.search(r"10moons sends a vendor 0x01 report and a digitizer 0x05 report", readme_text())
    assert TEN_MOONS, "no 10moons capture in the folder"


@pytest.mark.parametrize("path", TEN_MOONS, ids=[p.name for p in TEN_MOONS])
def test_10moons_two_reports_per_position_give_one_sample(path: Path) -> None:
    d = decoded(path.name)
    pairs = 0
    rows = list(zip(d.events, d.results, strict=True))
    for (e0, s0), (e1, s1) in itertools.pairwise(rows):
        if e0.data[0] == 0x01 and e1.data[0] == 0x05 and e0.data[1:] == e1.data[1:]:
            pairs += 1
            assert s0 is None, f"vendor report 0x01 at line {e0.line} became a sample"
            assert s1 is not None, f"digitizer report 0x05 at line {e1.line} gave no sample"
    positions = sum(1 for e in d.events if e.data[0] == 0x05)
    assert pairs > MIN_SAMPLES
    assert pairs == positions, f"{positions - pairs} 0x05 reports without their 0x01 twin"
    assert d.decoder.stats.samples == positions


LONGER_THAN_DECLARED = [
    (p, rid, length, declared)
    for p in CAPTURES
    for rid, length, _, remark in readme_reports_seen(p.name)
    if (m := re.fullmatch(r"declared as (\d+)B", remark)) and (declared := int(m.group(1))) < length
    and rid in {r for r, _ in readme_pen_reports(p.name)}
]


def test_readme_lists_pen_reports_longer_than_declared() -> None:
    assert any(p.name.startswith("digimend__KYE") and rid == 0x09 for p, rid, _, _ in LONGER_THAN_DECLARED)


@pytest.mark.parametrize(
    "case", LONGER_THAN_DECLARED, ids=[f"{p.name}-0x{rid:02x}" for p, rid, _, _ in LONGER_THAN_DECLARED]
)
def test_reports_longer_than_declared_decode(case: tuple[Path, int, int, int]) -> None:
    path, rid, length, declared = case
    d = decoded(path.name)
    assert d.decoder.layouts[rid].length == declared
    long_reports = [(e, s) for e, s in zip(d.events, d.results, strict=True)
                    if e.data[0] == rid and len(e.data) == length]
    assert long_reports
    undecoded = [e for e, s in long_reports if s is None]
    assert not undecoded, (
        f"{len(undecoded)} {length}-byte reports 0x{rid:02x} not decoded: {_line_list(undecoded)}"
    )


XP_PEN_PADDING = [
    (p, rid)
    for p in CAPTURES
    if "XP-Pen" in p.name
    for rid, values in readme_byte1_values(p.name).items()
    if {0xA0, 0xA1} <= values
]


def test_readme_lists_xp_pen_padding_bit_captures() -> None:
    assert XP_PEN_PADDING, "README lists no XP-Pen capture whose byte 1 is 0xa0/0xa1"


@pytest.mark.parametrize("case", XP_PEN_PADDING, ids=[f"{p.name}-0x{rid:02x}" for p, rid in XP_PEN_PADDING])
def test_xp_pen_padding_bit_does_not_disturb_tip_or_range(case: tuple[Path, int]) -> None:
    path, rid = case
    d = decoded(path.name)
    checked, wrong = 0, []
    for e, s in zip(d.events, d.results, strict=True):
        if e.data[0] == rid and e.data[1] in (0xA0, 0xA1):
            checked += 1
            expected_tip = e.data[1] == 0xA1
            if s is None or s.tip != expected_tip or not s.range or s.eraser or s.b1 or s.b2:
                wrong.append(e)
    assert checked > MIN_SAMPLES
    assert not wrong, f"{len(wrong)} of {checked} 0xa0/0xa1 reports decoded wrongly: {_line_list(wrong)}"


UNDECLARED = [
    (p, rid)
    for p in CAPTURES
    for rid, _, _, remark in readme_reports_seen(p.name)
    if remark == "NOT declared"
]


@pytest.mark.parametrize("case", UNDECLARED, ids=[f"{p.name}-0x{rid:02x}" for p, rid in UNDECLARED])
def test_undeclared_report_ids_are_counted_not_decoded(case: tuple[Path, int]) -> None:
    path, rid = case
    d = decoded(path.name)
    rows = [(e, s) for e, s in zip(d.events, d.results, strict=True) if e.data[0] == rid]
    assert rows and all(s is None for _, s in rows)
    assert d.decoder.stats.ignored[f"unknown report id 0x{rid:02x}"] == len(rows)


# -- b) every descriptor ----------------------------------------------------------------------------------


@cache
def device_of(name: str):
    return Capture.from_file(HID_DIR / name).devices[0]


@pytest.mark.parametrize("path", FILES, ids=[p.name for p in FILES])
def test_descriptor_parses(path: Path) -> None:
    device = device_of(path.name)
    descriptor = ReportDescriptor.from_bytes(device.descriptor)
    assert descriptor.raw == device.descriptor
    assert descriptor.reports


# Multi-touch "Touch Screen" reports that the README lists among the pen-relevant ones are finger contacts
# (Finger collections with Contact Ids), which a pen decoder rightly leaves out.
PEN_EXPECTATIONS = [
    (p, sorted({rid for rid, coll in readme_pen_reports(p.name) if coll != "Touch Screen"})) for p in FILES
]
PEN_EXPECTATIONS = [(p, ids) for p, ids in PEN_EXPECTATIONS if ids]


def test_readme_pen_expectations_cover_most_files() -> None:
    assert len(PEN_EXPECTATIONS) >= len(FILES) // 2, f"only {len(PEN_EXPECTATIONS)} files with pen reports"


@pytest.mark.parametrize("case", PEN_EXPECTATIONS, ids=[p.name for p, _ in PEN_EXPECTATIONS])
def test_every_pen_report_of_the_readme_has_a_layout(case: tuple[Path, list[int]]) -> None:
    path, expected = case
    device = device_of(path.name)
    error = None
    try:
        layouts = HidPenDecoder(device.descriptor, device.vid, device.pid).layouts
    except DescriptorError as exc:
        error, layouts = exc, {}
    wanted = [f"0x{r:02x}" for r in expected]
    assert error is None, f"expected pen layouts for {wanted}, decoder raised: {error}"
    missing = [f"0x{r:02x}" for r in expected if r not in layouts]
    summaries = [lay.summary() for lay in layouts.values()]
    assert not missing, f"no layout for pen reports {missing}; layouts: {summaries}"


NO_STANDARD = [p for p in FILES if "no standard pen report" in readme_sections().get(p.name, "")]


def test_readme_lists_files_without_standard_pen_report() -> None:
    assert NO_STANDARD


@pytest.mark.parametrize("path", NO_STANDARD, ids=[p.name for p in NO_STANDARD])
def test_no_standard_pen_report_means_vendor_layout_or_clear_error(path: Path) -> None:
    device = device_of(path.name)
    try:
        layouts = HidPenDecoder(device.descriptor, device.vid, device.pid).layouts
    except DescriptorError as exc:
        assert "no pen report" in str(exc)
        return
    vendor = [lay for lay in layouts.values() if lay.source not in ("descriptor", "mouse-mode")]
    summaries = [lay.summary() for lay in layouts.values()]
    assert vendor, f"only standard layouts {summaries} for a vendor-only descriptor"
