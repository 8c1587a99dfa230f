"""Pen input: HID descriptors and decoding, captures, devices; no scene or UI logic.

Each source runs on its own thread and puts items on a queue; live, `session/source_pump.SourcePump` turns them into
journal entries for the runner, and the session's `PenInput` is their one consumer.

- `sources.py`: the contract: readers put frozen `RawReport` / `SampleReady` / `SourceEnded` items on a
  `queue.Queue` from their own thread and never raise into the consumer; `PenSource` protocol
- `hid/hidraw.py`: hidraw discovery from sysfs (`PHYSINK_SYSFS_ROOT` / `PHYSINK_DEV_ROOT` move the roots, for
  tests), `open_error()` with the udev fix in one line
- `hid/readers.py`, `hid/usb_reader.py`, `hid/threaded_reader.py`: `ThreadedReader` (the shared thread and
  end-of-source bookkeeping, its own module so the two reader modules need not import each other), `HidrawReader`
  (select on the node and a wake-up pipe, monotonic timestamps), `HidapiReader`, `PyusbInterruptReader` (when hidraw
  is unavailable), `open_reader()` for `auto`, a path or VID:PID
- `hid/vendor_init.py`: UC-Logic/Huion initialisation through pyusb: raw string descriptors 0xC8 (v2) then 0x64
  (v1), parameters into `TabletParams`; the result is also written into captures as a `# physink vendor-init:`
  comment that `decode` and `replay` read back
- `reconnecting.py`: hot-plug: passes each unplugging on as `SourceEnded(error=DeviceError)` (the stroke ends
  cleanly) and reopens the device when it returns
- `serial_tablets/isdv4.py`, `serial_tablets/reader.py`: Wacom ISDV4/W8001 serial tablets: query handshake (38400
  then 19200 baud), 9-byte pen packets with 7-bit chunks, resynchronisation on the sync bit with bad bytes counted
- `scripted_sources.py`: `ProgrammaticPenSource` (the TUI's mouse, tests) and `CaptureReplaySource`
- `pen/mapping.py`: `TabletMapping`: used area, rotation, left-handed, proportions kept by cropping the tablet to
  the canvas aspect, display tablets one to one; header (de)serialisation
- `pen/state.py`: `PenState` enum, `VALID_TRANSITIONS`, `apply()` raising `PenStateError` naming an impossible
  transition, `route()` walking a skipped state, libinput-style tip hysteresis (down above 5 %, up below 1 %)
- `pen/gestures.py`: `GestureEngine`: strokes, taps, dwells (400 ms within a small radius; a stroke that starts with
  a dwell is a drag), eraser strokes, device lost mid-stroke, backward timestamps held and counted
- `pen/smoothing.py`: optional two-tap position average while touching (half a sample of lag)
- `pen/pen_input.py`: `PenInput`, the input side's single consumer (inside the session): routes items by device to
  decoder, mapping, smoother and gesture engine; `tick(t)` lets time pass without a sample (a dwell completes,
  stamped when it completed); `ink()` the strokes being drawn
- `journal_replay.py`: `pen_input_for(header)`: the input side a journal header describes, missing mapping keys as
  the identity (the session uses it too; `logged_pen_input_for` gives a `LoggedPenInput` that keeps the gestures it
  returns, so `physink replay` lists the gestures of the session's own decoding: a journal is read and decoded
  once); a journal's HID and pen lines through it, `device` lines adding decoders, commands and utterances listed
- `journal_compose.py`: journals built from captures plus scripted entries (commands, speech, mouse `pen` lines)
  merged by time, written through `JournalWriter` (`physink demo`, `tests/scenarios/make_journals.py`); here rather
  than in `formats/` so the formats never import `input`
- `virtual_pen.py`, `hid/report_encoder.py`, `hid/reference_descriptors.py`, `hid/descriptor_builder.py`: the
  virtual pen: scripted strokes to realistic reports for any layout, the four hand-written reference descriptors
- `replay_clock.py`: the input time of a replay paced in real time (the TUI's journal feed): runs with the wall
  clock but waits at the next recorded input's time until that input has been handed over
- `hid/pad.py`: pad buttons (ExpressKeys) in a tablet's reports, from the descriptor's Button-page fields or the
  Huion/UC-Logic vendor frame; what a button does is the caller's (the kiosk's)

Device tests run the real reader code over `os.pipe()`, `os.openpty()` and `SOCK_SEQPACKET` socket pairs; tests that
need a real tablet carry the `hardware` marker and skip themselves. `packaging/udev/` holds the rules that give the
seated user access to tablets (see its README).
"""
