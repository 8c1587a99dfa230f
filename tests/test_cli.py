"""The ``physink`` command line: every subcommand parses, unbuilt ones say so, errors become one line."""

from __future__ import annotations

import argparse

import pytest

from physink_tui import cli
from physink_tui.errors import DescriptorError

# The smallest valid argument list for each subcommand of the DESIGN.md CLI table.
SAMPLE_ARGV: dict[str, list[str]] = {
    "demo": ["demo", "--headless", "--out", "out"],
    "tui": ["tui", "p.physink.json", "--device", "056a:0357", "--replay", "s.physink.jsonl"],
    "kiosk": ["kiosk", "--out", "out", "--serial", "/dev/ttyS0"],
    "devices": ["devices"],
    "record": ["record", "--device", "auto", "-o", "c.hid"],
    "decode": ["decode", "c.hid", "--format", "text"],
    "replay": ["replay", "s.physink.jsonl", "--out", "out", "--video", "--frames"],
    "recognize": ["recognize", "strokes.jsonl"],
    "timeline": ["timeline", "p.physink.json", "--format", "dot"],
    "equiv": ["equiv", "a.json", "b.json", "--json"],
    "simulate": ["simulate", "p.json", "--out", "o", "--budget", "10", "--workers", "2", "--seed", "7"],
    "listen": ["listen", "u.wav", "--labels", "ball,cup", "--vosk-model", "model"],
    "export": ["export", "p.physink.json", "--video", "v.gif", "--frames", "f", "--timeline", "t.txt"],
}


def test_every_subcommand_is_built() -> None:
    assert set(cli.HANDLERS) == set(SAMPLE_ARGV)


@pytest.mark.parametrize("command", sorted(SAMPLE_ARGV))
def test_every_subcommand_parses_its_options(command: str) -> None:
    args = cli.build_parser().parse_args(SAMPLE_ARGV[command])
    assert args.command == command


def test_unbuilt_subcommand_says_so_in_one_line_and_exits_2(
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    # every subcommand is built today; the mechanism stays for the next one DESIGN.md adds
    command = "listen"
    monkeypatch.setattr(cli, "HANDLERS", {**cli.HANDLERS, command: "physink_tui.commands.not_written:run"})
    assert cli.main(SAMPLE_ARGV[command]) == 2
    out, err = capsys.readouterr()
    assert out == ""
    assert err.count("\n") == 1
    assert err == f"physink {command}: not available yet (physink_tui.commands.not_written is not written yet)\n"


def test_help_lists_every_subcommand(capsys: pytest.CaptureFixture[str]) -> None:
    assert cli.main(["--help"]) == 0
    out = capsys.readouterr().out
    for command in SAMPLE_ARGV:
        assert f"\n    {command} " in out or f"\n    {command}\n" in out, command


def test_bad_usage_exits_2(capsys: pytest.CaptureFixture[str]) -> None:
    assert cli.main([]) == 2
    assert cli.main(["no-such-command"]) == 2
    assert cli.main(["decode", "c.hid", "--format", "xml"]) == 2
    assert cli.main(["simulate", "p", "--out", "o", "--budget", "0"]) == 2
    assert cli.main(["record", "-o", "c.hid", "--device", "auto", "--serial", "/dev/ttyS0"]) == 2
    assert "usage: physink" in capsys.readouterr().err


def _raise_descriptor_error(args: argparse.Namespace) -> int:
    raise DescriptorError("bad", offset=3)


def _raise_keyboard_interrupt(args: argparse.Namespace) -> int:
    raise KeyboardInterrupt


def _print_args(args: argparse.Namespace) -> int:
    print(args.command, args.file, args.format)
    return 0


def test_built_subcommand_is_imported_lazily_and_gets_the_args(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setitem(cli.HANDLERS, "decode", f"{__name__}:_print_args")
    assert cli.main(["decode", "c.hid", "--format", "text"]) == 0
    assert capsys.readouterr().out == "decode c.hid text\n"


def test_physink_error_becomes_one_line_and_exit_1(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setitem(cli.HANDLERS, "decode", f"{__name__}:_raise_descriptor_error")
    assert cli.main(["decode", "c.hid"]) == 1
    out, err = capsys.readouterr()
    assert out == ""
    assert err == "physink: bad (at descriptor byte 3)\n"


def test_keyboard_interrupt_exits_130(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(cli.HANDLERS, "decode", f"{__name__}:_raise_keyboard_interrupt")
    assert cli.main(["decode", "c.hid"]) == 130


def test_handler_whose_module_is_not_written_says_not_available(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setitem(cli.HANDLERS, "decode", "physink_tui.commands.not_written_yet:run")
    assert cli.main(["decode", "c.hid"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert err.startswith("physink decode: not available yet (")
