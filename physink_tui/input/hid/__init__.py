"""Tablet HID: report descriptors, pen layouts, decoders, device readers (hidraw, hidapi, pyusb), vendor init and
device facts.

From raw report bytes to `PenSample`, in small modules with one job each. `input/` is grouped by what the modules
serve: `input/hid/` (descriptors, layouts, decoders, readers, vendor init, device facts), `input/captures/` (the
hid-recorder format), `input/serial_tablets/` (ISDV4), `input/pen/` (one pen's samples to gestures), and at its top
the source contract, hot-plug, scripted sources, the virtual pen and journals.

In `input/hid/`:

- `usages.py`: usage pages and usages a pen needs, names for text; `canonical()` maps Wacom's 0xFF0D page onto the
  Digitizer usages it mirrors (0xFF0D0130/0131 → X/Y)
- `descriptor.py`: `ReportDescriptor.from_bytes`: main/global/local items, long items, push/pop, report ids, usage
  min/max, extended usages, signed logical/physical ranges, unit and exponent (4-bit nibble as the kernel reads it),
  arrays and variables, padding. Fatal problems raise `DescriptorError` with the byte offset; what the kernel logs
  and skips (an unknown main item, a reserved item type) is skipped too and kept in `ReportDescriptor.warnings`,
  which `HidPenDecoder` puts in its stats, so `physink decode`'s summary prints them; the kernel's limits guard
  against hostile input (report size ≤ 256 bits, count ≤ 12,288, report ≤ 16 KiB)
- `pen_layout.py`: `PenLayout`: for one report id the bits of X, Y, pressure, tilt (degrees via physical range and
  unit) and each switch. `pen_layouts()` finds Digitizer pen reports, Wacom 0xFF0D reports and "mouse mode" pen
  reports (a Mouse application with absolute X/Y plus Tip Pressure or In Range: B1 = tip, B2/B3 = barrel buttons).
  Finger/puck collections and reports with Contact Id are not pens
- `vendor_layouts.py`: what descriptors do not say: the UC-Logic/Huion v1 report 0x07, the Huion v2 12-byte report
  0x08 (24-bit X/Y, tilt, pad reports 0xE0/0xF0 in byte 1), older Wacom Graphire and PenPartner protocols, the
  `(vid, pid)` profile table, and family quirks (two-button pens whose descriptors call the second button
  Eraser/Invert; in-range polarity learnt per device). A Huion/UC-Logic interface that declares only the vendor
  report 0x08 (recorded after the kernel switched it on, with no vendor-init note) gets the v2 layout with maxima
  from the device facts, or, where several models share the id and the name does not choose, ranges inferred from
  the largest values seen, with a warning
- `device_facts.py`: the public facts table `physink_tui/data/device_facts.tsv` (our own format, written from
  `../shared/data/tablets/tablets.tsv`): model, VID:PID, report length, X/Y/pressure maxima, report family;
  `match_device` picks a model by id, by the device name, or says why it cannot
- `fixed_layouts.py`: devices whose own descriptor is all vendor bytes and which Linux drives by replacing it
  (ViewSonic PD1011, 0543:e621): their pen layout written from the facts of the replacement (offsets, bits, maxima),
  used when the descriptor is the device's own
- `pen_decoder.py`: compiles a layout once into a generated Python function (constant offsets, masks and shifts; the
  whole report read as one integer). Keeps the state real tablets force: ranges widened past lying logical maxima
  (as libinput does, only from in-range reports) and learnt in-range polarity
- `decoder.py`: `HidPenDecoder`: one device's layouts and compiled decoders, routes each report by id, counts every
  report that gives no sample by reason (unknown id, not a pen report, truncated, pad/dial report, non-pen tool) and
  remembers the first
- `batch.py`: `decode_batch`: the same layouts over a whole capture with numpy (byte matrices per report id,
  vectorised shift-and-mask); ranges and polarity taken from the whole capture, or given (`learned`) when a capture
  is decoded a chunk at a time. Agrees with the streaming decoder wherever no range widens
- `distinct.py`: `decode_distinct`: each distinct report of a capture decoded once, in plain Python, by `batch.py`'s
  whole-capture rules (ranges widened to every in-range value, the touching reports' in-range polarity), with how
  often each occurs; a layout's raw values read by one function generated for it (`raw_reader`). `physink decode`'s
  plain path: no numpy to import
- `chunks.py`: `decode_in_chunks`: a long run of reports through `decode_batch` 65,536 at a time, sample for sample
  what one batch gives: a run longer than a chunk is first read through for what the whole run teaches (ranges; the
  in-range polarity, then the x/y ranges, when a layout learns it). `physink decode` streams with it: memory stays
  flat in the capture's size

Captures (`input/captures/`) and the sample:

- `captures/capture.py`: `Capture`: hid-recorder text format, read (both `E:` time forms, CRLF, comments, `D:`
  devices; broken lines kept as `BadLine`s) as objects for the callers that want events
- `captures/capture_types.py`: the values a capture is made of (`CaptureEvent`, `CaptureDevice`, `BadLine`,
  `CaptureColumns`: the reports as arrays, offsets and one byte string)
- `captures/parser.py`: `CaptureParser`: the line checks, fed a chunk of lines at a time (`parse_capture_file` reads
  1 MB at a time); runs of `E:` lines go to `captures/events.py` (strictly formed runs, checked and read a column at
  a time with numpy), else one regex over the run, else line by line with the error each bad line gets
- `captures/plain.py`: `read_plain`: a capture whose every line is plain (header lines through `CaptureParser`'s
  checks, `E:` lines each a stamp and a ``<length> <hex bytes>`` text, checked once per distinct text) read without
  numpy, or None for anything the full parser would report or repair (a bad line, a glitched stamp, stray spaces, CR)
- `captures/writer.py`: captures written atomically
- `pen/sample.py`: `PenSample`, a `NamedTuple`: immutable and slotted like a frozen dataclass, but 4x cheaper to
  build (0.5 µs vs 2.0 µs measured), which matters at one sample per report

Rules the decoder keeps, and why:

- Reports longer than declared are decoded from their declared bits (KYE, Huion, Aiptek send extra bytes); shorter
  ones are counted as truncated, never guessed.
- Padding and constant bits are never read, so non-zero padding (XP-Pen's 0xA0 in byte 1) changes nothing.
- `tip` comes from the Tip Switch (or Eraser touching), else B1 in mouse mode, else pressure above its minimum. A
  barrel button together with a zero-pressure "tip" is a click (UC-Logic mouse mode, Waltop), not a touch. Pressure
  is 0 whenever the tip is up (some pens report a pressure floor while hovering).
- `range` comes from In Range; without one (Huion's mouse mode) every report is in range and leaving shows only as
  the reports stopping. In the UC-Logic family the polarity is learnt: a report with the tip, pressure or a button
  active shows which bit value means "in range".
- Eraser is the Invert bit (eraser end in range) or the Eraser bit (eraser touching), except in families whose pens
  have no eraser and whose descriptors call the second barrel button Eraser or Invert.
- Two reports per position (10moons: a vendor report and a digitizer report): only the one the descriptor describes
  as a pen becomes a sample.
"""
