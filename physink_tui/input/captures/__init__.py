"""Captures in the hid-recorder text format: parsing, streaming events, writing.

- `capture.py`: reads and writes whole captures; decodes no reports.
- `capture_types.py`: the values a parsed capture is made of and the parser's limits.
- `parser.py`: parses capture lines chunk by chunk into compact columns (numpy; `events.py` converts runs of ``E:``
  lines).
- `plain.py`: reads a plainly well-formed capture (≤ 8 MB, every line plain) without numpy, or says it is not plain;
  `physink decode`'s fast path (`commands/decode_plain.py`, `input/hid/distinct.py`), anything else goes to `parser.py`.
- `writer.py`: writes captures exactly as hid-tools' ``hid-recorder`` does.
"""
