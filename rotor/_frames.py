"""The frame table of the rotor study: the paper's run-together rows split into numbers.

The paper's text prints each row of Table 3 with its numbers run together: row 1 reads
``120712314596511226``, i.e. ``1 | 2071 231 45 965 1 1226``.
:data:`rotor._paper.TABLE3_PRINTED_ROWS` holds the rows exactly as printed;
:func:`split_rows` recovers the numbers as the unique split in which every column increases
from row to row (each frame index must be later than the one above it). The split is
searched exhaustively, so the function also proves the split is unique.

Columns: ``as1..as3`` the asymmetric collar (tests 1-3), ``s1..s3`` the symmetric collar.
Each entry is the frame index (120 frames/s) at which the rotor had turned ``(k - 1)``
quarter turns.
"""

from __future__ import annotations

from collections.abc import Sequence
from functools import lru_cache

import numpy as np

from contact._errors import ContactInputError
from rotor._paper import TABLE3_COLUMNS, TABLE3_PRINTED_ROWS

__all__ = ["split_rows", "table3", "table3_tsv"]

def _splits(digits: str, parts: int, max_len: int) -> list[tuple[int, ...]]:
    """Every way to cut ``digits`` into ``parts`` numbers without leading zeros."""
    out: list[tuple[int, ...]] = []

    def rec(pos: int, acc: list[int]) -> None:
        if len(acc) == parts:
            if pos == len(digits):
                out.append(tuple(acc))
            return
        left = parts - len(acc)
        for size in range(1, max_len + 1):
            end = pos + size
            if end > len(digits) or len(digits) - end < left - 1:
                break
            piece = digits[pos:end]
            if len(piece) > 1 and piece[0] == "0":
                break
            rec(end, [*acc, int(piece)])

    rec(0, [])
    return out


def split_rows(
    rows: Sequence[str],
    n_columns: int = 6,
    max_digits: int = 4,
    first_ratio: tuple[float, float] | None = (1.0, 3.0),
    duration_factor: float | None = 2.0,
    max_paths: int = 10000,
) -> np.ndarray:
    """Split run-together rows into numbers: the unique split keeping every column increasing
    and physically plausible.

    Increasing columns alone do not settle Table 3. The first row has no row above it
    (``...45965...`` may be ``45 965``, ``4 596`` or ``45 96``), and a whole alternative
    exists in which every ``s2`` entry gains the ``1`` that starts the ``s3`` entry
    (``1131 351`` for ``113 1351``): both columns still increase. Two facts of the experiment
    settle it:

    * ``first_ratio``: the rotor starts from rest, so its first step cannot be quicker than
      its second, and from rest under constant or decaying acceleration it takes at most
      ``1/(sqrt(2) - 1) = 2.41`` times as long. The ratio of the first interval to the second
      must lie in these bounds in every column (3 leaves room for frame quantisation and a
      start a little behind the first mark).
    * ``duration_factor``: the columns are repeats of the same launch, so each column's
      duration ``f_last - f_first`` lies within this factor of the median column's.

    Parameters
    ----------
    rows : sequence of str
        Row ``k`` (1-based) is ``str(k)`` followed by the digits of its ``n_columns`` numbers.
    n_columns : int
        Numbers per row after the row number.
    max_digits : int
        Most digits one number may have.
    first_ratio : (float, float) or None
        Bounds on ``(f2 - f1)/(f3 - f2)`` in every column; None drops the condition.
    duration_factor : float or None
        Largest ratio of a column's duration to the median's (either way); None drops it.
    max_paths : int
        Give up when more increasing splits than this exist.

    Returns
    -------
    ndarray of int, shape (len(rows), n_columns)

    Raises
    ------
    ContactInputError
        A row does not start with its number, or no split, or more than one, satisfies the
        conditions.
    """
    cands: list[np.ndarray] = []
    for k, row in enumerate(rows, start=1):
        text = row.strip()
        if not text.isdigit():
            raise ContactInputError(f"row {k}: {row!r} is not a run of digits")
        if not text.startswith(str(k)):
            raise ContactInputError(f"row {k}: {row!r} does not start with its number {k}")
        opts = _splits(text[len(str(k)):], n_columns, max_digits)
        if not opts:
            raise ContactInputError(f"row {k}: no split into {n_columns} numbers")
        cands.append(np.array(opts, dtype=np.int64))
    if not cands:
        raise ContactInputError("no rows to split")

    # links[i][a, b]: candidate a of row i lies below candidate b of row i+1 in every column;
    # alive[i][a]: candidate a of row i has at least one increasing completion
    links = [np.all(cands[i][:, None, :] < cands[i + 1][None, :, :], axis=2)
             for i in range(len(cands) - 1)]
    alive = [np.ones(len(cands[-1]), bool)]
    count = [np.ones(len(cands[-1]), dtype=np.int64)]
    for i in range(len(cands) - 2, -1, -1):
        c = (links[i].astype(np.int64) * count[0][None, :]).sum(axis=1)
        count.insert(0, c)
        alive.insert(0, c > 0)
    n_increasing = int(count[0].sum())
    if n_increasing == 0:
        raise ContactInputError("no split keeps every column increasing")
    if n_increasing > max_paths:
        raise ContactInputError(f"{n_increasing} increasing splits; too many to check")

    paths: list[list[int]] = []

    def walk(i: int, path: list[int]) -> None:
        if i == len(cands):
            paths.append(list(path))
            return
        nxt = (np.flatnonzero(alive[0]) if i == 0
               else np.flatnonzero(links[i - 1][path[-1]] & alive[i]))
        for j in nxt:
            path.append(int(j))
            walk(i + 1, path)
            path.pop()

    walk(0, [])
    good = []
    for path in paths:
        table = np.vstack([cands[i][j] for i, j in enumerate(path)])
        if first_ratio is not None and len(table) >= 3:
            ratio = (table[1] - table[0]) / (table[2] - table[1])
            if not np.all((ratio >= first_ratio[0]) & (ratio <= first_ratio[1])):
                continue
        if duration_factor is not None and len(table) >= 2:
            dur = (table[-1] - table[0]).astype(float)
            med = float(np.median(dur))
            if np.any(dur > duration_factor * med) or np.any(dur < med / duration_factor):
                continue
        good.append(table)
    if not good:
        raise ContactInputError(
            f"none of the {n_increasing} increasing splits is physically plausible"
        )
    if len(good) > 1:
        raise ContactInputError(f"{len(good)} plausible splits; the split is not unique")
    return good[0]


@lru_cache(maxsize=1)
def _table() -> np.ndarray:
    return split_rows(TABLE3_PRINTED_ROWS)


def table3() -> dict[str, np.ndarray]:
    """Table 3 as ``{column: frame indices for rows 1..25}``.

    Row ``k`` of a column is the frame (120 frames/s) at which that launch had turned
    ``k - 1`` quarter turns.

    Returns
    -------
    dict of str to numpy.ndarray
        ``as1..as3`` (the asymmetric collar) and ``s1..s3`` (the symmetric one), 25 integer
        frame indices each; a fresh copy on every call.

    See Also
    --------
    table3_tsv : the same table as text.
    analyse_table : the law of motion of every column.

    References
    ----------
    .. [1] Alaci, Ciornei & Romanu, "Validation of Nonlinear Dependence of Rolling
       Friction Moment on the Normal Force for Elastic Materials", Materials 15 (2022) 2518,
       Table 3.

    Examples
    --------
    >>> from rotor import table3
    >>> table = table3()
    >>> list(table)
    ['as1', 'as2', 'as3', 's1', 's2', 's3']
    >>> s1 = table["s1"]
    >>> print(len(s1), s1[:3].tolist(), f"six turns in {(s1[-1] - s1[0]) / 120:.2f} s")
    25 [965, 1082, 1137] six turns in 5.85 s
    """
    t = _table()
    return {name: t[:, j].copy() for j, name in enumerate(TABLE3_COLUMNS)}


def table3_tsv() -> str:
    """Table 3 as tab-separated text: header ``k`` and the columns, one row per line.

    Returns
    -------
    str
        26 lines (the header and rows 1..25), each ending in a newline: the frame-table
        format that ``surfmet rotor`` reads.

    See Also
    --------
    table3 : the same table as arrays.

    Examples
    --------
    >>> from rotor import table3_tsv
    >>> text = table3_tsv()
    >>> lines = text.splitlines()
    >>> len(lines), lines[0].split()
    (26, ['k', 'as1', 'as2', 'as3', 's1', 's2', 's3'])
    >>> lines[1].split()
    ['1', '2071', '231', '45', '965', '1', '1226']
    """
    t = _table()
    lines = ["\t".join(("k", *TABLE3_COLUMNS))]
    for k, row in enumerate(t, start=1):
        lines.append("\t".join([str(k), *(str(int(v)) for v in row)]))
    return "\n".join(lines) + "\n"
