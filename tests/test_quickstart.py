"""The quick start runs as written (issue 16, item 16).

Every ```python block of docs/quickstart.md is executed, in document order and in one
namespace (the blocks build on each other), in a temporary working folder that holds the
shipped data at ``surfmet/data`` as a checkout does; every ```sh line that calls
``surfmet`` goes through the command line's ``main`` in the same folder and must exit 0.
A block is left out only when the line just above it is the marker
``<!-- quickstart-test: skip (REASON) -->`` and the reason is a Dask scheduler or the
network. The README's ``surfmet`` commands must parse (the demo they run is
tests/test_demo.py's).
"""

from __future__ import annotations

import contextlib
import glob
import io
import re
import shlex
import textwrap
import time
import warnings
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
QUICKSTART = ROOT / "docs" / "quickstart.md"
README = ROOT / "README.md"
SKIP = re.compile(r"<!--\s*quickstart-test:\s*skip\s*\((.+?)\)\s*-->")
FENCE = re.compile(r"^\s*```(\w*)\s*$")


@dataclass(frozen=True)
class Block:
    lang: str
    code: str
    line: int            # 1-based line of the opening fence
    skip: str | None     # the reason given by the marker above it


def code_blocks(path: Path) -> list[Block]:
    """The fenced code blocks of a Markdown file, with the skip marker above each."""
    lines = path.read_text(encoding="utf-8").splitlines()
    out: list[Block] = []
    i = 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        start = i
        i += 1
        body = []
        while i < len(lines) and not lines[i].lstrip().startswith("```"):
            body.append(lines[i])
            i += 1
        above = next((t for t in reversed(lines[:start]) if t.strip()), "")
        marker = SKIP.search(above)
        out.append(Block(m.group(1), textwrap.dedent("\n".join(body)), start + 1,
                         marker.group(1) if marker else None))
        i += 1
    return out


def shell_commands(code: str) -> list[list[str]]:
    """The ``surfmet`` commands of a shell block as argument lists (continuations joined,
    comments dropped, ``&&`` chains split); other commands (pip, pytest) are left out."""
    joined = re.sub(r"\\\n", " ", code)
    commands = []
    for line in joined.splitlines():
        for part in line.split("&&"):
            words = shlex.split(part, comments=True)
            if words[:3] in (["python3", "-m", "surfmet"], ["python", "-m", "surfmet"]):
                words = ["surfmet", *words[3:]]
            if words and words[0] == "surfmet":
                commands.append(words[1:])
    return commands


def run_cli(words: list[str]) -> int:
    """Run one command in-process: globs expanded, ``> FILE`` captures stdout."""
    from surfmet.cli import main

    target = None
    if ">" in words:
        k = words.index(">")
        words, target = words[:k], words[k + 1]
    argv = []
    for w in words:
        argv.extend(sorted(glob.glob(w)) or [w] if any(c in w for c in "*?[") else [w])
    buf = io.StringIO()
    with contextlib.redirect_stdout(buf):
        rc = main(argv)
    if target is not None:
        Path(target).write_text(buf.getvalue(), encoding="utf-8")
    return rc


BLOCKS = code_blocks(QUICKSTART)


def test_the_quickstart_has_code_and_only_justified_skips():
    langs = [b.lang for b in BLOCKS]
    assert langs.count("python") >= 15 and langs.count("sh") >= 12
    for b in BLOCKS:
        assert b.lang in ("python", "sh"), f"line {b.line}: a block without a language"
        if b.skip is not None:
            assert re.search(r"dask|scheduler|network", b.skip, re.I), (b.line, b.skip)


@pytest.mark.slow
@pytest.mark.campaign
def test_the_quickstart_runs_as_written(tmp_path, monkeypatch):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    (tmp_path / "surfmet").mkdir()
    (tmp_path / "surfmet" / "data").symlink_to(ROOT / "surfmet" / "data")
    monkeypatch.chdir(tmp_path)
    namespace: dict = {"__name__": "quickstart"}
    ran = 0
    for b in BLOCKS:
        if b.skip is not None:
            continue
        t0 = time.perf_counter()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # the doc shows calls; their warnings are output
            if b.lang == "python":
                exec(compile(b.code, f"quickstart.md:{b.line}", "exec"), namespace)
            else:
                for words in shell_commands(b.code):
                    rc = run_cli(words)
                    assert rc == 0, f"quickstart.md:{b.line}: surfmet {shlex.join(words)} -> {rc}"
        plt.close("all")
        ran += 1
        print(f"quickstart.md:{b.line} {b.lang} {time.perf_counter() - t0:.1f} s")
    assert ran == sum(b.skip is None for b in BLOCKS)
    # the files the doc says it writes are there, and not empty
    for name in ("copy.x3p", "trace.x3p", "table.csv", "table.json", "psd.png", "plate.png",
                 "trace.png", "pressure.png", "radial.png", "report.html", "hertz.html",
                 "result.npz", "hertz.png", "sweep.csv", "sweep_contact.csv", "residuals.png",
                 "surfmet_demo/summary.json"):
        assert (tmp_path / name).stat().st_size > 0, name


def test_the_readme_commands_parse():
    from surfmet.cli import build_parser

    parser = build_parser()
    commands = [c for b in code_blocks(README) if b.lang == "sh"
                for c in shell_commands(b.code)]
    assert commands, "the README shows no surfmet command"
    for words in commands:
        args = parser.parse_args(words)
        assert callable(args.func), words
