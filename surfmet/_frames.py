"""Frame-index tables of a filmed law of motion (the layout of the paper's Table 3).

A text table, tab- or space-separated: a header ``k`` followed by one name per test, then
one row per mark with the frame index at which that test reached it (empty, ``nan`` or
``-`` for a missing reading).
"""

from __future__ import annotations

import itertools
import math
from pathlib import Path

from surfmet._errors import SurfmetFormatError


def read_frames_table(path: str | Path) -> tuple[list[int], dict[str, list[float]]]:
    """Read a frame-index table: header ``k`` and column names, then integer rows.

    Parameters
    ----------
    path : str or Path
        A text table, tab- or space-separated (``#`` starts a comment line): the header
        ``k`` and one name per test, then one row per mark with the frame index at which
        each test reached it (empty, ``nan``, ``na`` or ``-`` for a missing reading).

    Returns
    -------
    ks : list of int
        The row numbers k (increasing).
    cols : dict of str to list of float
        ``{column: frame indices}`` (NaN for missing readings), in the header's order.

    Raises
    ------
    SurfmetFormatError
        A missing or unreadable file, a header that is not ``k`` and distinct names, a
        row that is not numbers, row numbers that do not increase, fewer than 2 rows.

    Examples
    --------
    The paper's Table 3 (Alaci et al. 2022), shipped with surfmet:

    >>> from surfmet.data import path
    >>> from surfmet.mechanics.rotor_verdict import read_frames_table
    >>> ks, cols = read_frames_table(path("table3_frames.tsv"))
    >>> len(ks), list(cols)
    (25, ['as1', 'as2', 'as3', 's1', 's2', 's3'])
    >>> cols["as1"][:3]
    [2071.0, 2200.0, 2263.0]
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise SurfmetFormatError(f"{path}: no such file") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise SurfmetFormatError(f"{path}: cannot read it as text ({exc})") from None
    lines = [ln for ln in text.splitlines() if ln.strip() and not ln.lstrip().startswith("#")]
    if not lines:
        raise SurfmetFormatError(f"{path}: empty file")
    sep = "\t" if "\t" in lines[0] else None
    header = [h.strip() for h in lines[0].split(sep)]
    if header[0].lower() != "k" or len(header) < 2:
        raise SurfmetFormatError(
            f"{path}: the header must be 'k' followed by column names, got {lines[0]!r}"
        )
    names = header[1:]
    if len(set(names)) != len(names):
        raise SurfmetFormatError(f"{path}: repeated column names in {names}")
    ks: list[int] = []
    cols: dict[str, list[float]] = {n: [] for n in names}
    for lineno, line in enumerate(lines[1:], start=2):
        cells = [c.strip() for c in line.split(sep)] if sep else line.split()
        if len(cells) < len(header):
            cells += [""] * (len(header) - len(cells))
        if len(cells) > len(header):
            raise SurfmetFormatError(f"{path}:{lineno}: {len(cells)} cells for "
                                     f"{len(header)} columns")
        try:
            ks.append(int(cells[0]))
        except ValueError:
            raise SurfmetFormatError(f"{path}:{lineno}: row number {cells[0]!r} is not an "
                                     "integer") from None
        for name, cell in zip(names, cells[1:]):
            if cell.lower() in ("", "nan", "-", "na"):
                cols[name].append(math.nan)
                continue
            try:
                v = float(cell)
            except ValueError:
                raise SurfmetFormatError(
                    f"{path}:{lineno}: {cell!r} in column {name!r} is not a frame index"
                ) from None
            if not math.isfinite(v):
                raise SurfmetFormatError(f"{path}:{lineno}: {cell!r} is not finite")
            cols[name].append(v)
    if len(ks) < 2:
        raise SurfmetFormatError(f"{path}: no data rows")
    if any(b <= a for a, b in itertools.pairwise(ks)):
        raise SurfmetFormatError(f"{path}: row numbers k must increase")
    return ks, cols
