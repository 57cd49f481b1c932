"""Writing an output file whole or not at all.

Every file surfmet writes (reports, figures, CSV and JSON tables, scans, saved fields) is
written to a temporary file beside its target, flushed to the disk and then renamed over
the target; a rename within one file system is atomic (POSIX ``rename(2)``). A full
disk, a kill or an exception half-way therefore never leaves a truncated file that looks
complete, and an earlier file of that name is kept until the new one is whole. A write
the operating system refuses (no space, a file size limit, no permission) is one
:class:`~surfmet._errors.SurfmetWriteError` naming the file.
"""

from __future__ import annotations

import contextlib
import os
import secrets
from collections.abc import Iterator
from pathlib import Path
from typing import IO, Any

from surfmet._errors import SurfmetWriteError

__all__ = ["atomic_open", "atomic_path", "check_writable", "output_lock", "real_target",
           "write_bytes", "write_text"]


def real_target(path: str | os.PathLike[str]) -> Path:
    """The file a write to ``path`` must change: ``path`` itself, or, where it is a
    symbolic link (or lies in a linked folder), the file the link points to (which may not
    exist yet). Renaming a new file over the link itself would cut the link and leave its
    target unchanged; and two names of one file must share one lock."""
    return Path(os.path.realpath(path))


def check_writable(path: str | os.PathLike[str] | None, what: str = "output") -> None:
    """Refuse, before any work, an output path that cannot be written (a missing folder,
    a folder in its place, no permission), so that a long computation is not lost at the
    end. ``what`` names the option in the message (e.g. ``"-o"``).

    A temporary file is created beside it and removed again (the way the output will be
    written): whatever the operating system would refuse at the end is refused now.

    Raises
    ------
    SurfmetInputError
        In one line, naming ``what`` and the path.
    """
    from surfmet._errors import SurfmetInputError

    if path is None:
        return
    p = real_target(path)
    if p.is_dir():
        raise SurfmetInputError(f"{what} {path}: is a folder; give a file name")
    parent = p.parent if str(p.parent) else Path(".")
    if not parent.is_dir():
        raise SurfmetInputError(f"{what} {path}: folder {parent} does not exist")
    if p.exists() and not os.access(p, os.W_OK):
        raise SurfmetInputError(f"{what} {path}: cannot write there (permission denied)")
    try:
        tmp = _temporary(p)
    except (OSError, SurfmetWriteError) as exc:
        why = getattr(exc, "strerror", None) or str(exc)
        raise SurfmetInputError(f"{what} {path}: cannot write there ({why})") from None
    with contextlib.suppress(OSError):
        tmp.unlink()


def _temporary(target: Path) -> Path:
    """A new, empty file beside ``target``, hidden, keeping its extension (writers such as
    matplotlib and numpy choose the format from it), with the permissions a plain
    ``open`` would give (0666 less the umask)."""
    for _ in range(100):
        tmp = target.with_name(f".{target.stem}.part-{secrets.token_hex(4)}{target.suffix}")
        try:
            os.close(os.open(tmp, os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o666))
            return tmp
        except FileExistsError:
            continue
    raise SurfmetWriteError(f"cannot write {target}: no free temporary name beside it")


def _fsync(path: Path) -> None:
    with open(path, "rb+") as fh:
        os.fsync(fh.fileno())


def _error(target: Path, exc: OSError) -> SurfmetWriteError:
    why = exc.strerror or str(exc) or type(exc).__name__
    kept = " (the earlier file is kept)" if target.exists() else ""
    return SurfmetWriteError(f"cannot write {target}: {why}; nothing was written{kept}")


@contextlib.contextmanager
def atomic_path(path: str | os.PathLike[str]) -> Iterator[Path]:
    """The path of a temporary file to write ``path``'s content to; renamed over ``path``
    when the block ends without an error, removed otherwise.

    Raises
    ------
    SurfmetWriteError
        The operating system refused a write (disk full, file too large, permission).
    """
    target = real_target(path)
    try:
        tmp = _temporary(target)
    except OSError as exc:
        raise _error(Path(path), exc) from None
    try:
        yield tmp
        _fsync(tmp)
        os.replace(tmp, target)
    except OSError as exc:
        with contextlib.suppress(OSError):
            tmp.unlink()
        raise _error(Path(path), exc) from None
    except BaseException:
        with contextlib.suppress(OSError):
            tmp.unlink()
        raise


@contextlib.contextmanager
def atomic_open(path: str | os.PathLike[str], mode: str = "w", **kwargs: Any) -> Iterator[IO]:
    """``open(path, mode, **kwargs)`` through :func:`atomic_path` (a write mode)."""
    with atomic_path(path) as tmp, open(tmp, mode, **kwargs) as fh:
        yield fh


def write_bytes(path: str | os.PathLike[str], data: bytes) -> Path:
    """Write ``data`` to ``path`` whole or not at all."""
    with atomic_open(path, "wb") as fh:
        fh.write(data)
    return Path(path)


def write_text(path: str | os.PathLike[str], text: str, encoding: str = "utf-8") -> Path:
    """Write ``text`` to ``path`` whole or not at all."""
    with atomic_open(path, "w", encoding=encoding, newline="") as fh:
        fh.write(text)
    return Path(path)


@contextlib.contextmanager
def output_lock(path: str | os.PathLike[str]) -> Iterator[None]:
    """Hold an exclusive lock on the output ``path`` for the block, so that two runs
    never write one file at once (POSIX ``flock`` on a hidden ``.NAME.lock`` beside the
    file itself, :func:`real_target`, so that a symbolic link to it takes the same lock;
    removed at the end; released by the kernel if the process dies).

    Raises
    ------
    SurfmetInputError
        Another process holds the lock (its id is named).
    """
    import fcntl

    from surfmet._errors import SurfmetInputError

    target = Path(path)
    real = real_target(path)
    lock = real.with_name(f".{real.name}.lock")
    while True:
        fd = os.open(lock, os.O_CREAT | os.O_RDWR, 0o666)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            holder = os.read(fd, 32).decode("ascii", "replace").strip() or "another process"
            os.close(fd)
            raise SurfmetInputError(
                f"{target} is being written by another run (process {holder}); wait for it "
                "to finish or write to another file") from None
        try:
            # a run that just finished may have removed the file we opened: lock the
            # file that is there now
            same = os.fstat(fd).st_ino == os.stat(lock).st_ino
        except FileNotFoundError:
            same = False
        if same:
            break
        os.close(fd)
    try:
        os.ftruncate(fd, 0)
        os.write(fd, str(os.getpid()).encode("ascii"))
        yield
    finally:
        with contextlib.suppress(OSError):
            lock.unlink()
        os.close(fd)
