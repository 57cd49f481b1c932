"""The ``surfmet`` command: one entry point, one module per subcommand.

Each module in :data:`SUBCOMMANDS` defines ``add_parser(subparsers)``, which adds its parser
and sets ``func`` (``func(args) -> int``). Modules import heavy dependencies inside ``func``
so that ``surfmet --help`` and ``surfmet info`` stay fast.

Exit status: 0 ok, 1 user error (bad input, unreadable file), 2 internal error.
"""

from __future__ import annotations

import argparse
import errno
import importlib
import os
import re
import sys
from collections.abc import Sequence

from surfmet._version import __version__
from surfmet.cli._inputs import stating_inputs

SUBCOMMANDS = (
    "info",
    "formats",
    "roughness",
    "fit",
    "contact",
    "hertz_check",
    "rolling",
    "sweep",
    "rotor",
    "show",
    "report",
    "demo",
    "spectrum",
    "flat_contact",
    "rolling_contact",
    "scales",
    "adhesion",
)

EPILOG = """examples:
  surfmet info scan.nms --json
  surfmet roughness plate.x3p --level plane --json
  surfmet fit ball.x3p --shape sphere
  surfmet contact --radius 20mm --load 10N --materials steel,aluminium
  surfmet hertz-check plate.x3p --radius 20mm --load 10N --materials steel,aluminium
  surfmet rotor table3_frames.tsv
  surfmet spectrum plate.x3p --plot psd.png
  surfmet flat-contact plate.x3p --materials steel,aluminium --pressures 1MPa:100MPa:5
  surfmet scales surface.zip --tip-radius 20nm --plot scales.png
  surfmet adhesion --radius 10um --e-star 1GPa --work-of-adhesion 50mJ/m2 --range 2nm
  surfmet demo --out demo_out

Lengths accept unit suffixes (nm, um, µm, mm, m); a bare number is in metres. Speeds
accept m/s, mm/s, km/h (a bare number is m/s). A material's E and H need their unit
(steel:E=200GPa); a name not in the table with E and nu given is a custom material.
Pressures always need their unit (--hardness 1GPa, --e-star, --pressures); a bare
number there is refused.

One form per option in every command: the scan is the positional argument (--plate FILE
its alias); options with several values (--loads, --pressures) take lists (4N,5N,6N) and
log-spaced ranges (1N:100N:5; 9 values without the count; at most 100 values);
--periodic auto|yes|no (a bare --periodic is yes); --interaction defaults to dugdale;
--quiet (-q) silences the progress of every long command (off a terminal, one line per
stage).
"""


class UserError(Exception):
    """A command-line usage error (exit status 1)."""


class _Parser(argparse.ArgumentParser):
    # argparse exits with status 2 on usage errors; our convention reserves 2 for internal
    # errors, so usage errors become UserError (status 1).
    def error(self, message: str) -> None:  # type: ignore[override]
        raise UserError(f"{self.prog}: {message}")


def build_parser() -> argparse.ArgumentParser:
    """The full argument parser with every available subcommand."""
    parser = _Parser(
        prog="surfmet",
        description="Rough-surface metrology and contact mechanics.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("--version", action="version", version=f"surfmet {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    for name in SUBCOMMANDS:
        try:
            mod = importlib.import_module(f"surfmet.cli.{name}")
        except ModuleNotFoundError as exc:  # a misspelt or missing entry is never skipped
            if exc.name != f"surfmet.cli.{name}":
                raise
            raise ModuleNotFoundError(
                f"surfmet.cli.SUBCOMMANDS names {name!r}, but there is no module "
                f"surfmet/cli/{name}.py", name=exc.name) from None
        stating_inputs(mod.add_parser(sub))  # every command states what it was given
    return parser


# A value that starts like a negative number ("-5N", "-0.5mm"): argparse takes "-5" for a
# number but "-5N" for an unknown option.
_NEGATIVE = re.compile(r"^-(\d|\.\d)")


def negative_values(parser: argparse.ArgumentParser, argv: list[str]) -> list[str]:
    """``--load -5N`` as ``--load=-5N`` when the option takes a value, so that a
    negative-looking value reaches its type check and the domain error ("must be
    positive") is what the user sees, not "expected one argument"."""
    sub = None
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction) and argv:
            sub = action.choices.get(argv[0])
    options = {} if sub is None else sub._option_string_actions
    out: list[str] = []
    i = 0
    while i < len(argv):
        tok = argv[i]
        action = options.get(tok)
        if (action is not None and action.nargs != 0 and i + 1 < len(argv)
                and _NEGATIVE.match(argv[i + 1])):
            out.append(f"{tok}={argv[i + 1]}")
            i += 2
            continue
        out.append(tok)
        i += 1
    return out


def main(argv: Sequence[str] | None = None) -> int:
    """Run the CLI; returns the exit status."""
    from surfmet._errors import user_error_types

    argv = list(sys.argv[1:] if argv is None else argv)
    parser = None
    try:
        parser = build_parser()
        args = parser.parse_args(negative_values(parser, argv))
        if not getattr(args, "func", None):
            parser.print_help(sys.stderr)
            return 1
        rc = int(args.func(args) or 0)
        sys.stdout.flush()  # a full disk under stdout fails here, not after main returns
        for note in getattr(args, "deferred_notes", None) or ():  # surfmet.cli._values
            print(note, file=sys.stderr)
        return rc
    except UserError as exc:
        print(f"surfmet: error: {exc}", file=sys.stderr)
        return 1
    except user_error_types() as exc:
        from surfmet.cli._terms import cli_terms, command_options
        from surfmet.units import readable_quantities

        text = readable_quantities(cli_terms(str(exc), command_options(parser, argv)))
        print(f"surfmet: error: {text}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("surfmet: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        return 0
    except Exception as exc:
        if isinstance(exc, OSError) and exc.errno in _NO_ROOM:
            return _no_room(exc)
        if os.environ.get("SURFMET_DEBUG"):
            raise
        print(
            f"surfmet: internal error: {type(exc).__name__}: {exc} "
            "(set SURFMET_DEBUG=1 for the traceback, and please report it)",
            file=sys.stderr,
        )
        return 2


#: Errors of a write the storage refuses: no space, over the quota, over the file-size
#: limit. They are the environment's, not a fault of surfmet: one line and exit 1.
_NO_ROOM = (errno.ENOSPC, errno.EDQUOT, errno.EFBIG)


def _no_room(exc: OSError) -> int:
    """The one line of a write the storage refused (exit 1), standard output to a full
    disk included. Standard output's unwritten rest, if any, is sent to the null device,
    so that the interpreter's own flush at exit does not print a second error."""
    try:
        sys.stdout.flush()
    except OSError:
        try:
            null = os.open(os.devnull, os.O_WRONLY)
            os.dup2(null, sys.stdout.fileno())
            os.close(null)
        except (OSError, ValueError, AttributeError):
            pass
    print(f"surfmet: error: cannot write the output: {exc.strerror or exc}; free some "
          "space and run again", file=sys.stderr)
    return 1


__all__ = ["SUBCOMMANDS", "UserError", "build_parser", "main"]
