"""Run one function over many items: serially, over local processes, or on a Dask cluster.

``batch_map(func, items)`` returns ``[func(item) for item in items]`` in the input order,
with three guarantees whatever the engine:

* **the same results**: every item is computed by the same top-level function with the
  same arguments, in a fresh call, with single-threaded BLAS in every engine (Dask's
  workers run that way; a multi-threaded BLAS splits its sums by thread count and would
  change the last bits), so the numbers are bitwise those of the serial run;
* **a failure stays in its row**: an exception, or a worker process that dies (a crash,
  the kernel's out-of-memory killer), turns into ``on_error(item, message)`` in that
  item's place and the batch goes on;
* **progress** on stderr (:func:`progress_bar`): a bar on a terminal; with
  ``progress=True`` plain lines elsewhere (logs, pipes), where a bar's carriage returns
  would garble the text.

Engines:

``workers=1``
    in this process.
``workers=N`` (default: the CPUs this process may use)
    a :class:`concurrent.futures.ProcessPoolExecutor` of N processes started by the
    ``forkserver`` method where the platform has it (``spawn`` elsewhere): never ``fork``,
    which can deadlock a child when the parent holds threads (numba, BLAS, tqdm's monitor).
``scheduler="tcp://host:port"`` (or a :class:`distributed.Client`)
    the tasks go to a Dask distributed cluster (Rocklin 2015, *Dask: parallel computation
    with blocked algorithms and task scheduling*, Proc. SciPy). The workers must have
    surfmet installed and see the same file paths (a shared file system). A worker that
    dies is retried on another by the scheduler; an item that kills workers repeatedly
    comes back as ``KilledWorker`` in its row.

``func`` must be picklable for the two parallel engines: a module-level function, or a
:func:`functools.partial` of one (for example ``partial(roughness_file, level="plane")``).
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable, Iterable
from typing import Any

from surfmet._errors import SurfmetInputError


class _SingleThreadedBlas:
    """``func(item)`` with BLAS/LAPACK limited to one thread (threadpoolctl); picklable
    whenever ``func`` is."""

    def __init__(self, func: Callable[[Any], Any]) -> None:
        self.func = func

    def __call__(self, item: Any) -> Any:
        from threadpoolctl import threadpool_limits

        with threadpool_limits(limits=1, user_api="blas"):
            return self.func(item)


def default_workers() -> int:
    """The number of CPUs this process may run on (at least 1)."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):  # pragma: no cover - macOS, Windows
        return max(1, os.cpu_count() or 1)


def error_row(item: Any, message: str) -> dict[str, Any]:
    """The default row for a failed item: ``{"file", "status": "error", "error"}``."""
    return {"file": str(item), "status": "error", "error": message}


def _describe(exc: BaseException) -> str:
    from surfmet._errors import user_error_types

    if isinstance(exc, user_error_types()):
        return str(exc)
    return f"internal error: {type(exc).__name__}: {exc}"


class _Lines:
    """Progress where stderr is not a terminal (logs, pipes, CI): one plain line per stage,
    ``desc: k/n (t s)`` when it ends, and on a long stage one more line every
    :attr:`EVERY` seconds, so a log is neither flooded (a line per step) nor silent."""

    #: Seconds between the lines of a long stage.
    EVERY = 60.0

    def __init__(self, total: int | None, desc: str) -> None:
        import time

        self.total, self.desc, self.n = total, desc, 0
        self._start = self._last = time.monotonic()
        self._closed = False

    def _line(self, now: float) -> None:
        of = f"/{self.total}" if self.total else ""
        print(f"{self.desc}: {self.n}{of} ({now - self._start:.1f} s)", file=sys.stderr,
              flush=True)
        self._last = now

    def update(self, n: int = 1) -> None:
        import time

        self.n += n
        now = time.monotonic()
        if now - self._last >= self.EVERY and not (self.total and self.n >= self.total):
            self._line(now)

    def set_postfix_str(self, text: str, refresh: bool = True) -> None:
        return None

    def close(self) -> None:
        import time

        if not self._closed:
            self._closed = True
            self._line(time.monotonic())

    def __enter__(self) -> _Lines:
        return self

    def __exit__(self, exc_type: Any, *exc: Any) -> None:
        if exc_type is None:  # a stage cut short by an error says nothing more
            self.close()


def progress_bar(total: int | None, desc: str, show: bool | None) -> Any:
    """Progress on stderr: ``show=False`` nothing; on a terminal a tqdm bar; elsewhere
    (logs, pipes, CI) plain lines when ``show=True`` and nothing when ``show=None`` (the
    API's default: a library call stays quiet unless asked)."""
    from tqdm.auto import tqdm

    if show is False:
        return tqdm(total=total, disable=True)
    if sys.stderr.isatty():
        return tqdm(total=total, desc=desc, file=sys.stderr, leave=False,
                    dynamic_ncols=True)
    if show:
        return _Lines(total, desc)
    return tqdm(total=total, disable=True)




def batch_map(
    func: Callable[[Any], Any],
    items: Iterable[Any],
    *,
    workers: int | None = None,
    scheduler: Any = None,
    on_error: Callable[[Any, str], Any] = error_row,
    progress: bool | None = None,
    desc: str = "",
    connect_timeout: float = 10.0,
    on_result: Callable[[int, Any], Any] | None = None,
) -> list[Any]:
    """``[func(item) for item in items]``, in parallel, failures kept in their rows.

    Parameters
    ----------
    func : callable
        Picklable for the parallel engines (see the module docstring).
    items : iterable
        Work items (file paths...).
    workers : int, optional
        Local processes; default :func:`default_workers`. ``1`` runs in this process.
        Ignored when ``scheduler`` is given (the cluster decides).
    scheduler : str or distributed.Client, optional
        Address of a Dask scheduler (``"tcp://10.0.0.5:8786"``), or a client.
    on_error : callable
        ``on_error(item, message)`` gives the row of an item whose call raised or whose
        worker died. Default :func:`error_row`.
    progress : bool, optional
        Force the progress bar on or off; default: shown when stderr is a terminal.
    desc : str
        Label of the progress bar.
    connect_timeout : float
        Seconds to wait for the Dask scheduler before giving up.
    on_result : callable, optional
        ``on_result(index, result)`` is called in this process as soon as each item's
        result (or error row) arrives, in completion order: the hook for writing rows
        incrementally, so that an interrupted batch keeps what it finished.

    Returns
    -------
    list
        One result per item, in the order of ``items``.

    Raises
    ------
    SurfmetInputError
        ``workers`` < 1, or a scheduler that cannot be reached.

    Examples
    --------
    A failure becomes its item's row and the batch goes on (``workers=1``: serial):

    >>> from surfmet.sweep import batch_map
    >>> batch_map(abs, [-1, 2, -3], workers=1)
    [1, 2, 3]
    >>> batch_map(int, ["1", "x"], workers=1)[1]["status"]
    'error'
    """
    items = list(items)
    if workers is not None and int(workers) < 1:
        raise SurfmetInputError(f"workers must be at least 1, got {workers}")
    if not items:
        return []
    func = _SingleThreadedBlas(func)
    done = on_result if on_result is not None else _ignore
    if scheduler is not None:
        return _dask_map(func, items, scheduler, on_error, progress, desc, connect_timeout,
                         done)
    n = default_workers() if workers is None else int(workers)
    n = min(n, len(items))
    if n == 1:
        return _serial_map(func, items, on_error, progress, desc, done)
    return _process_map(func, items, n, on_error, progress, desc, done)


def _ignore(index: int, result: Any) -> None:
    return None


def _call(func: Callable[[Any], Any], item: Any, on_error: Callable[[Any, str], Any]) -> Any:
    try:
        return func(item)
    except Exception as exc:  # one bad item must not stop the batch
        return on_error(item, _describe(exc))


def _serial_map(func, items, on_error, progress, desc, done) -> list[Any]:
    out = []
    with progress_bar(len(items), desc, progress) as bar:
        for k, item in enumerate(items):
            out.append(_call(func, item, on_error))
            done(k, out[-1])
            bar.update(1)
    return out


#: How often (s) a worker process checks that the process that started it is alive.
WATCH_INTERVAL = 0.5


def _start_time(pid: int) -> str | None:
    """A process's start time as the kernel states it (Linux ``/proc``), to tell it from a
    later process given the same id; None where it cannot be read."""
    try:
        with open(f"/proc/{pid}/stat", encoding="ascii", errors="replace") as fh:
            return fh.read().rsplit(")", 1)[1].split()[19]
    except (OSError, IndexError):
        return None


def _alive(pid: int, started: str | None) -> bool:
    if started is not None:
        return _start_time(pid) == started
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def _follow_owner(pid: int, started: str | None) -> None:
    """Worker initializer: end this worker when the process that owns the pool is gone.

    A pool's workers are children of the forkserver, not of the owner, so when the owner
    is killed (SIGKILL, the out-of-memory killer) nothing tells them: they would finish
    their item, wait for the next one for ever, and keep the forkserver alive with them.
    A daemon thread checks the owner every :data:`WATCH_INTERVAL` s and exits the worker
    at once (``os._exit``: nothing to flush; the owner is the one that writes results).
    """
    import threading
    import time

    def watch() -> None:
        while _alive(pid, started):
            time.sleep(WATCH_INTERVAL)
        os._exit(1)

    threading.Thread(target=watch, name="surfmet-owner-watch", daemon=True).start()


def _is_main_test(test: Any) -> bool:
    """Whether an ``if`` test is ``__name__ == "__main__"`` (either way round)."""
    import ast

    if not (isinstance(test, ast.Compare) and len(test.ops) == 1
            and isinstance(test.ops[0], ast.Eq)):
        return False
    sides = {type(n).__name__ + ":" + str(getattr(n, "id", getattr(n, "value", "")))
             for n in (test.left, test.comparators[0])}
    return sides == {"Name:__name__", "Constant:__main__"}


def unguarded_main() -> tuple[str, int] | None:
    """(script, line) when this call comes from a script's top level outside
    ``if __name__ == "__main__":``, else None.

    Worker processes are started by ``forkserver`` or ``spawn``, which import the main
    script again in the new process (Python's "safe importing of the main module"): an
    unguarded script starts its work again there, and the pool's workers die
    bootstrapping. A script run as ``python -m package`` (``package.__main__``) and
    interactive sessions are not imported again, and pass.
    """
    import ast

    main = sys.modules.get("__main__")
    file = getattr(main, "__file__", None)
    spec = getattr(main, "__spec__", None)
    if not file or (spec is not None and spec.name.rpartition(".")[2] == "__main__"):
        return None
    frame = sys._getframe(1)
    while frame is not None and not (frame.f_code.co_name == "<module>"
                                     and frame.f_globals is vars(main)):
        frame = frame.f_back
    if frame is None:
        return None
    line = frame.f_lineno
    try:
        with open(file, encoding="utf-8") as fh:
            tree = ast.parse(fh.read())
    except (OSError, SyntaxError, ValueError):
        return None
    for node in tree.body:
        if isinstance(node, ast.If) and _is_main_test(node.test) and \
                node.lineno <= line <= (node.end_lineno or line):
            return None
    return file, line


def _pool(n: int) -> Any:
    """A process pool of ``n`` workers that end with the process that made it."""
    from concurrent.futures import ProcessPoolExecutor

    me = os.getpid()
    return ProcessPoolExecutor(max_workers=n, mp_context=_mp_context(),
                               initializer=_follow_owner, initargs=(me, _start_time(me)))


def _mp_context() -> Any:
    import multiprocessing as mp

    methods = mp.get_all_start_methods()
    return mp.get_context("forkserver" if "forkserver" in methods else "spawn")


def _process_map(func, items, n, on_error, progress, desc, done) -> list[Any]:
    import pickle
    from concurrent.futures import as_completed
    from concurrent.futures.process import BrokenProcessPool

    try:
        pickle.dumps(func)
    except Exception as exc:
        raise SurfmetInputError(
            f"the batch function cannot be sent to worker processes ({exc}); use a "
            "module-level function or a functools.partial of one, or workers=1"
        ) from None
    where = unguarded_main()
    if where is not None:
        raise SurfmetInputError(
            f"{where[0]}, line {where[1]}: worker processes import this script again and "
            "it would start them again there (every row would read 'worker process "
            "died'): put the script's work under `if __name__ == \"__main__\":` (see "
            "docs/quickstart.md, section 3), or use workers=1")
    results: list[Any] = [None] * len(items)
    broken: list[int] = []
    with progress_bar(len(items), desc, progress) as bar:
        pool = _pool(n)
        try:
            futures = {pool.submit(func, item): k for k, item in enumerate(items)}
            for fut in as_completed(futures):
                k = futures[fut]
                try:
                    results[k] = fut.result()
                except BrokenProcessPool:
                    broken.append(k)
                    continue  # re-run below, each alone, to find the culprit
                except Exception as exc:
                    results[k] = on_error(items[k], _describe(exc))
                done(k, results[k])
                bar.update(1)
        except BaseException:
            # Ctrl-C or a bug here: drop the queued items instead of waiting for them all
            pool.shutdown(wait=False, cancel_futures=True)
            raise
        pool.shutdown(wait=True)
        # A dead worker breaks the whole pool and fails every pending item. Re-run those
        # one per fresh single-process pool: the innocent ones succeed, the item that
        # kills its process again gets the error row.
        for k in sorted(broken):
            with _pool(1) as solo:
                try:
                    results[k] = solo.submit(func, items[k]).result()
                except BrokenProcessPool:
                    results[k] = on_error(items[k], "the worker process died while "
                                          "processing this item (a crash, or out of memory)")
                except Exception as exc:
                    results[k] = on_error(items[k], _describe(exc))
            done(k, results[k])
            bar.update(1)
    return results


def check_scheduler(address: Any) -> None:
    """Refuse, before any connection, a Dask scheduler address that is not one
    (``tcp://HOST:PORT``, ``tls://...``, ``HOST:PORT``): a client built on it fails half-way
    and its finaliser hangs 20 s and prints a traceback at exit. A
    :class:`distributed.Client` passes.

    Raises
    ------
    SurfmetInputError
        In one line, naming the address and the form expected.
    """
    from surfmet._extras import require

    distributed = require("distributed", "dask", "--scheduler (a Dask cluster)")
    if isinstance(address, distributed.Client):
        return
    from distributed.comm import get_address_host_port, parse_address

    try:
        if not isinstance(address, str) or not address.strip():
            raise ValueError("it is empty" if isinstance(address, str) else "not text")
        scheme, _ = parse_address(address)
        if scheme != "inproc":  # an in-process address has no host and port
            get_address_host_port(address)
    except (TypeError, ValueError) as exc:
        raise SurfmetInputError(
            f"--scheduler {address!r} is not a Dask scheduler address ({exc}); give "
            "tcp://HOST:PORT, e.g. tcp://10.0.0.5:8786") from None


def _dask_map(func, items, scheduler, on_error, progress, desc, connect_timeout, done
              ) -> list[Any]:
    from surfmet._extras import require

    distributed = require("distributed", "dask", "--scheduler (a Dask cluster)")
    Client, as_completed = distributed.Client, distributed.as_completed

    own = not isinstance(scheduler, Client)
    if own:
        check_scheduler(scheduler)
        try:
            client = Client(scheduler, timeout=f"{connect_timeout}s", set_as_default=False)
        except (OSError, TimeoutError, ValueError) as exc:
            raise SurfmetInputError(
                f"cannot reach the Dask scheduler at {scheduler!r}: {exc}"
            ) from None
    else:
        client = scheduler
    try:
        # pure=False: identical items are computed (and reported) once each, in place
        futures = client.map(func, items, pure=False)
        index = {f.key: k for k, f in enumerate(futures)}
        results: list[Any] = [None] * len(items)
        with progress_bar(len(items), desc, progress) as bar, client.as_current():
            for fut in as_completed(futures):
                k = index[fut.key]
                try:
                    results[k] = fut.result()
                except Exception as exc:
                    results[k] = on_error(items[k], _describe(exc))
                fut.release()
                done(k, results[k])
                bar.update(1)
        return results
    finally:
        if own:
            client.close()

