"""Scan of profile-element rules against the Mitutoyo printout's RSm and Rc (issue 38).

The SurfTest export ``mitutoyo_2_mock.xlsx`` (``../shared/realdata``) prints RSm 419.9 µm
and Rc 13.306 µm for its exported R-profile (6664 points at 1.5 µm, λc 2.5 mm, N = 4,
ISO 1997). Every other per-sampling-length parameter agrees with the points to its
printed digit, so the sampling lengths are the instrument's; this script tabulates what
each reading of the profile-element rule (ISO 4287:1997 3.2.3-3.2.5, 4.1.4, 4.3.1; the
SJ-210 / SJ-410 manuals' "profile element restrictions") gives on those points, so the
search is reproducible. It is written apart from ``profiles._elements``: its ISO default
reproduces that module's 416.6 µm / 13.217 µm, and its ``first`` reading the printout.
Run from the repository root (about 20 s; ``--grid`` adds about a minute)::

    python3 benchmarks/mitutoyo_rsm_rules.py [--all] [--grid] [--mixed]

A. The product of independent choices (``RULES``), elements complete inside each
   sampling length:

   ``form``: ``merge`` (ISO 4287: insignificant peaks/valleys absorbed by their
   neighbours) or ``exclude`` (the raw elements between mean-line up-crossings that fail
   a restriction are left out, the manual's wording "excluded from the calculation");
   ``height``: ``zpzv`` (peak and valley each exceed Zmin, the manual's setting (1)) or
   ``zt`` (the element height Zp + Zv does, setting (2)); ``width``: each peak and valley
   at least 1 % of the sampling length (``run``, ISO), the element width (``element``, the
   manual) or ``none``; ``zref``: Zmin is 10 % of each sampling length's Rz, the printed
   (mean) Rz, Rz1max or Rt; ``level``: elements bounded by mean-line crossings or by
   crossings of +Zmin (a hysteresis band, the "c level" of Gwyddion / MountainsMap);
   ``start``: peak first (up-crossings) or valley first; ``scope``: per sampling length
   and averaged, pooled over the four, over the evaluation length, or found over the
   evaluation length and given to the sampling length holding the element's start,
   middle or end; ``cross``: crossings interpolated or at the first point past them.
B. ISO merging per sampling length with each ``start`` (``up``, ``down``, ``auto``: by
   the sign at the sampling length's start, ``first``: from its first crossing) and each
   treatment of the ends (``complete``, ``start``: the start of the sampling length opens
   the first element, ``across``: the last one is closed beyond the end, ``both``), on the
   exported profile and with a least-squares line or the mean removed per sampling length
   or over the evaluation length.
C. The significance decisions nearest the thresholds (how robust the element set is).
D. ``--grid``: height discrimination 5-25 % of Rz, width 0.5-3 % of the sampling length.
E. ``--mixed``: every assignment of the B readings (without ``first``) to the four
   sampling lengths separately.
"""

from __future__ import annotations

import argparse
import itertools
import sys
from pathlib import Path
from typing import Any

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
from tests.mitutoyo_printout import read_printout  # noqa: E402

PRINTED_RSM, PRINTED_RC = 419.9, 13.306  # µm, the export's certificate sheet
N_SAMPLING = 4

RULES = {
    "form": ("merge", "exclude"),
    "height": ("zpzv", "zt"),
    "width": ("run", "element", "none"),
    "zref": ("Rz_i", "Rz", "Rz1max", "Rt"),
    "level": ("mean", "+c"),
    "start": ("up", "down"),
    "scope": ("per-lr", "pooled", "ln", "ln-start", "ln-mid", "ln-end"),
    "cross": ("interp", "point"),
}


def _crossing(z: np.ndarray, x: np.ndarray, i: int, level: float, interp: bool) -> float:
    """Position where the profile crosses ``level`` between points i-1 and i."""
    if not interp or i == 0:
        return float(x[i])
    return float(x[i - 1] + (x[i] - x[i - 1]) * (level - z[i - 1]) / (z[i] - z[i - 1]))


def _runs(z: np.ndarray) -> list[tuple[int, int, int]]:
    """(sign, first, end) of the runs of one sign about the mean line (z >= 0: peak)."""
    s = np.where(z >= 0, 1, -1)
    ch = np.flatnonzero(s[1:] != s[:-1]) + 1
    return [(int(s[a]), int(a), int(b)) for a, b in zip(np.r_[0, ch], np.r_[ch, z.size])]


def _boundaries(z: np.ndarray, x: np.ndarray, zmin: np.ndarray, wmin: float,
                rule: dict[str, str]) -> list[tuple[float, int]]:
    """(position, index) where elements open, peak first (``z`` already flipped for 'down').

    ``exclude``: every up-crossing of the level. ``merge``: runs whose extreme reaches
    ``zmin`` (taken at the run's first point) and, with ``width='run'``, whose width
    reaches ``wmin`` are significant; one-sign runs separated only by insignificant ones
    are one peak (valley); an element opens where a significant peak follows a
    significant valley. Runs cut by the stretch
    ends are judged on what is visible; only elements between two openings count.
    """
    interp = rule["cross"] == "interp"
    level = zmin if rule["level"] == "+c" else np.zeros_like(z)
    if rule["form"] == "exclude":
        i = np.flatnonzero((z[:-1] < level[:-1]) & (z[1:] >= level[1:])) + 1
        return [(_crossing(z, x, int(k), float(level[k]), interp), int(k)) for k in i]
    out, prev = [], 0
    for sg, a, b in _runs(z):
        ext = float(np.max(np.abs(z[a:b])))
        x1 = _crossing(z, x, b, 0.0, interp) if b < z.size else float(x[-1])
        width = x1 - _crossing(z, x, a, 0.0, interp)
        if ext < zmin[a] or (rule["width"] == "run" and width < wmin):
            continue
        if sg > 0 and prev < 0:
            k = a + int(np.argmax(z[a:b] >= level[a:b]))
            out.append((_crossing(z, x, k, float(level[k]), interp), k))
        prev = sg
    return out


def elements(z: np.ndarray, x: np.ndarray, zmin: np.ndarray, wmin: float, rule: dict[str, str]
             ) -> list[tuple[float, float, float]]:
    """(x0, Xs, Zt) of the elements of one stretch that pass the rule's restrictions."""
    if rule["start"] == "down":
        z = -z
    bounds = _boundaries(z, x, zmin, wmin, rule)
    out = []
    for (x0, a), (x1, b) in itertools.pairwise(bounds):
        seg = z[a:b]
        zp, zv = float(seg.max()), float(-seg.min())
        if rule["form"] == "exclude":
            if rule["height"] == "zpzv" and not (zp >= zmin[a] and zv >= zmin[a]):
                continue
            if rule["height"] == "zt" and zp + zv < zmin[a]:
                continue
            if rule["width"] == "run":
                down = a + int(np.argmax(seg < 0))
                xd = _crossing(z, x, down, 0.0, rule["cross"] == "interp")
                if min(xd - x0, x1 - xd) < wmin:
                    continue
        if rule["width"] == "element" and x1 - x0 < wmin:
            continue
        out.append((x0, x1 - x0, zp + zv))
    return out


def section_elements(z: np.ndarray, x: np.ndarray, zmin: np.ndarray, a: int, b: int,
                     wmin: float, rule: dict[str, Any]) -> list[tuple[float, float, float]]:
    """Elements of the sampling length z[a:b] under the rule's ``ends`` and ``start``.

    ``ends``: ``complete`` (between two openings inside), ``start`` (the sampling length's
    start opens its first element: the ISO 4287 note that the portion at its beginning is
    a peak or valley), ``across`` (the last element opened inside is closed beyond the
    end), ``both``. ``start='auto'``: peak first if the sampling length begins above the
    mean line, valley first otherwise; ``start='first'``: the other way round, elements
    paired from the first mean-line crossing inside the sampling length (the run cut by
    its start is left out): the rule that reproduces the printout.
    """
    if rule["start"] == "auto":
        rule = {**rule, "start": "up" if z[a] >= 0 else "down"}
    elif rule["start"] == "first":
        rule = {**rule, "start": "down" if z[a] >= 0 else "up"}
    ends = rule.get("ends", "complete")
    stop = z.size if ends in ("across", "both") else b
    sign = -1.0 if rule["start"] == "down" else 1.0
    bounds = _boundaries(sign * z[a:stop], x[a:stop], zmin[a:stop], wmin, rule)
    if ends in ("start", "both"):
        first = (float(x[a] - 0.5 * (x[1] - x[0])), 0)
        if not bounds or bounds[0][1] > 0:
            bounds = [first, *bounds]
    bounds = [q for k, q in enumerate(bounds) if q[1] < b - a or (k and bounds[k - 1][1] < b - a)]
    out = []
    for (x0, i0), (x1, i1) in itertools.pairwise(bounds):
        seg = z[a + i0:a + i1]
        out.append((x0, x1 - x0, float(seg.max() - seg.min())))
    return out


def evaluate(z: np.ndarray, x: np.ndarray, rule: dict[str, Any]) -> tuple[float, float, int]:
    """RSm, Rc (µm) and the number of elements of the profile under ``rule``.

    ``scope`` ``ln-start`` / ``ln-end`` / ``ln-mid``: elements found over the whole
    evaluation length (each run judged by the discrimination of the sampling length it
    starts in), each given to the sampling length holding its start, its end or its
    middle, and RSm, Rc averaged over the sampling lengths.
    """
    n = z.size
    cut = [round(k * n / N_SAMPLING) for k in range(N_SAMPLING + 1)]
    secs = [slice(a, b) for a, b in itertools.pairwise(cut)]
    lr = (x[-1] - x[0] + (x[1] - x[0])) / N_SAMPLING
    rz_i = [float(z[s].max() - z[s].min()) for s in secs]
    ref = {"Rz": float(np.mean(rz_i)), "Rz1max": max(rz_i), "Rt": float(z.max() - z.min())}
    zmin = np.empty(n)
    for s, rz in zip(secs, rz_i):
        zmin[s] = float(rule.get("h", 0.1)) * ref.get(rule["zref"], rz)
    wmin = float(rule.get("w", 0.01)) * lr
    if rule["scope"].startswith("ln"):
        el = elements(z, x, zmin, wmin, rule)
        if rule["scope"] == "ln":
            per = [el]
        else:
            where = {"ln-start": 0.0, "ln-mid": 0.5, "ln-end": 1.0}[rule["scope"]]
            k = [min(int((e[0] + where * e[1] - x[0] + 0.5 * (x[1] - x[0])) // lr),
                     N_SAMPLING - 1) for e in el]
            per = [[e for e, kk in zip(el, k) if kk == i] for i in range(N_SAMPLING)]
    else:
        per = [section_elements(z, x, zmin, s.start, s.stop, wmin, rule)
               if rule["form"] == "merge" else elements(z[s], x[s], zmin[s], wmin, rule)
               for s in secs]
    count = sum(len(e) for e in per)
    if rule["scope"] != "pooled" and rule["scope"] != "ln":
        rsm = np.mean([np.mean([e[1] for e in p]) for p in per if p])
        rc = np.mean([np.mean([e[2] for e in p]) for p in per if p])
    else:
        flat = [e for p in per for e in p]
        rsm = np.mean([e[1] for e in flat]) if flat else np.nan
        rc = np.mean([e[2] for e in flat]) if flat else np.nan
    return float(rsm), float(rc), count


def profile() -> tuple[np.ndarray, np.ndarray]:
    """The export's R-profile and its positions (µm; the first point at one step)."""
    pr = read_printout(ROOT.parent / "shared" / "realdata" / "mitutoyo_2_mock.xlsx")
    z = pr.z * 1e6
    return z, np.arange(1, z.size + 1) * pr.dx * 1e6


def scan() -> list[tuple[dict[str, str], float, float, int]]:
    """Every rule of ``RULES`` evaluated on the export's profile (µm)."""
    z, x = profile()
    rows = []
    for values in itertools.product(*RULES.values()):
        rule = dict(zip(RULES, values))
        if rule["form"] == "merge" and rule["height"] == "zt":
            continue  # merging is by the peaks' and valleys' own heights
        rows.append((rule, *evaluate(z, x, rule)))
    return rows


def grid() -> list[tuple[dict[str, Any], float, float, int]]:
    """ISO merging per sampling length over a fine grid of discrimination constants.

    Height 5-25 % of each sampling length's Rz in 0.5 % steps, width 0.5-3 % of the
    sampling length in 0.1 % steps, peak first or from the first crossing, elements
    complete inside the sampling length or closed across its end.
    """
    z, x = profile()
    rows = []
    for st, ends in itertools.product(("up", "first"), ("complete", "across")):
        for h, w in itertools.product(np.arange(10, 51) / 200, np.arange(5, 31) / 1000):
            rule = {"form": "merge", "height": "zpzv", "width": "run", "zref": "Rz_i",
                    "level": "mean", "start": st, "scope": "per-lr", "cross": "interp",
                    "ends": ends, "h": round(float(h), 4), "w": round(float(w), 4)}
            rows.append((rule, *evaluate(z, x, rule)))
    return rows


def mixed_ends() -> tuple[int, list[tuple[float, str, float, float]]]:
    """Each sampling length with its own ``start``/``ends`` reading (12**4 combinations).

    Without the ``first`` reading: the combinations that hit both printed values are then
    the ones that take, in each sampling length, the elements ``first`` would.

    Returns the number of combinations that give both printed values (RSm to 0.05 µm,
    Rc to 0.0005 µm; per-sampling-length means or pooled) and the closest five.
    """
    z, x = profile()
    n = z.size
    cut = [round(k * n / N_SAMPLING) for k in range(N_SAMPLING + 1)]
    options = list(itertools.product(("up", "down", "auto"),
                                     ("complete", "start", "across", "both")))
    zmin = np.empty(n)
    for a, b in itertools.pairwise(cut):
        zmin[a:b] = 0.1 * float(z[a:b].max() - z[a:b].min())
    wmin = 0.01 * (x[-1] - x[0] + x[1] - x[0]) / N_SAMPLING
    table = []  # per sampling length: (sum Xs, sum Zt, count) for each option
    for a, b in itertools.pairwise(cut):
        row = []
        for st, ends in options:
            rule = {"form": "merge", "height": "zpzv", "width": "run", "level": "mean",
                    "cross": "interp", "start": st, "ends": ends}
            el = section_elements(z, x, zmin, a, b, wmin, rule)
            row.append((sum(e[1] for e in el), sum(e[2] for e in el), len(el)))
        table.append(np.array(row))
    hits, best = 0, []
    for combo in itertools.product(range(len(options)), repeat=N_SAMPLING):
        t = np.array([table[i][c] for i, c in enumerate(combo)])
        for how, rsm, rc in (("per-lr", np.mean(t[:, 0] / t[:, 2]), np.mean(t[:, 1] / t[:, 2])),
                             ("pooled", t[:, 0].sum() / t[:, 2].sum(),
                              t[:, 1].sum() / t[:, 2].sum())):
            if abs(rsm - PRINTED_RSM) <= 0.05 and abs(rc - PRINTED_RC) <= 0.0005:
                hits += 1
            score = abs(rsm / PRINTED_RSM - 1) + abs(rc / PRINTED_RC - 1)
            names = " | ".join("/".join(options[c]) for c in combo)
            best.append((float(score), f"{how}: {names}", float(rsm), float(rc)))
    best.sort()
    return hits, best[:5]


def ends_and_mean_lines() -> list[tuple[str, str, str, float, float, int]]:
    """ISO merging per sampling length: every ``start``/``ends`` reading on four mean lines.

    ``filter``: the exported R-profile as it is (the Gaussian mean line); ``ls-lr`` and
    ``mean-lr``: a least-squares line or the mean removed in each sampling length;
    ``ls-ln``: a least-squares line removed over the evaluation length.
    """
    z, x = profile()
    n = z.size
    cut = [round(k * n / N_SAMPLING) for k in range(N_SAMPLING + 1)]
    lines = {"filter": z.copy(), "ls-lr": z.copy(), "mean-lr": z.copy(),
             "ls-ln": z - np.polyval(np.polyfit(x, z, 1), x)}
    for a, b in itertools.pairwise(cut):
        lines["ls-lr"][a:b] -= np.polyval(np.polyfit(x[a:b], z[a:b], 1), x[a:b])
        lines["mean-lr"][a:b] -= z[a:b].mean()
    rows = []
    starts, ends_ = ("up", "down", "auto", "first"), ("complete", "start", "across", "both")
    for (name, zz), st, ends in itertools.product(lines.items(), starts, ends_):
        rule = {"form": "merge", "height": "zpzv", "width": "run", "zref": "Rz_i",
                "level": "mean", "start": st, "scope": "per-lr", "cross": "interp",
                "ends": ends}
        rows.append((name, st, ends, *evaluate(zz, x, rule)))
    return rows


def margins() -> list[tuple[float, float, float]]:
    """(x, height margin, width margin) of the runs nearest the default thresholds (µm).

    A run's margin is its extreme minus 10 % of its sampling length's Rz, and its width
    minus 1 % of the sampling length; the closest decisions show how far the element set
    is from changing (denser sampling moves a height by about 1e-3 µm, a crossing by
    well under a step).
    """
    z, x = profile()
    n = z.size
    cut = [round(k * n / N_SAMPLING) for k in range(N_SAMPLING + 1)]
    wmin = 0.01 * (x[-1] - x[0] + x[1] - x[0]) / N_SAMPLING
    out = []
    for a, b in itertools.pairwise(cut):
        zs, xs = z[a:b], x[a:b]
        zmin = 0.1 * float(zs.max() - zs.min())
        for _, i0, i1 in _runs(zs):
            x0 = _crossing(zs, xs, i0, 0.0, True)
            x1 = _crossing(zs, xs, i1, 0.0, True) if i1 < zs.size else float(xs[-1])
            out.append((x0, float(np.abs(zs[i0:i1]).max()) - zmin, x1 - x0 - wmin))
    near_h = sorted(out, key=lambda q: abs(q[1]))[:3]
    near_w = sorted((q for q in out if q[1] >= 0), key=lambda q: abs(q[2]))[:3]
    return near_h + near_w


def close(row: tuple[Any, ...]) -> float:
    """Relative distance of a row's (..., RSm, Rc, n) from the printout."""
    return abs(row[-3] / PRINTED_RSM - 1) + abs(row[-2] / PRINTED_RC - 1)


def _line(label: str, rsm: float, rc: float, n: int) -> str:
    return (f"{label} {rsm:8.1f} {100 * (rsm / PRINTED_RSM - 1):+6.2f}% {rc:8.3f}"
            f" {100 * (rc / PRINTED_RC - 1):+6.2f}% {n:3d}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--all", action="store_true", help="print every rule, not the closest")
    ap.add_argument("--grid", action="store_true",
                    help="also scan the discrimination constants (minutes)")
    ap.add_argument("--mixed", action="store_true",
                    help="also mix the end readings between sampling lengths")
    args = ap.parse_args()
    rows = sorted((r for r in scan() if np.isfinite(r[1])), key=close)
    print(f"printed: RSm {PRINTED_RSM} µm, Rc {PRINTED_RC} µm\n")
    print(f"A. {len(rows)} rules (closest first)")
    print(" ".join(f"{k:>8}" for k in RULES) + "      RSm    dRSm       Rc     dRc   n")
    for rule, *res in rows if args.all else rows[:15]:
        print(_line(" ".join(f"{v:>8}" for v in rule.values()), *res))
    print("\nB. ISO merging per sampling length: ends and mean lines")
    for name, st, ends, *res in ends_and_mean_lines():
        print(_line(f"{name:>8} {st:>5} {ends:>9}", *res))
    print("\nC. decisions nearest the thresholds (x, height margin, width margin; µm)")
    for q in margins():
        print(f"   x {q[0]:8.1f}  height {q[1]:+8.4f}  width {q[2]:+7.1f}")
    if args.grid:
        g = sorted(grid(), key=close)
        hits = [r for r in g if abs(r[1] - PRINTED_RSM) <= 0.05
                and abs(r[2] - PRINTED_RC) <= 0.0005]
        print(f"\nD. {len(g)} grid rules, {len(hits)} give both printed values; closest:")
        for st in sorted({r[0]["start"] + " " + r[0]["ends"] for r in hits}):
            h = [r[0]["h"] for r in hits if r[0]["start"] + " " + r[0]["ends"] == st]
            w = [r[0]["w"] for r in hits if r[0]["start"] + " " + r[0]["ends"] == st]
            print(f"   hits {st}: height {100 * min(h):.1f}-{100 * max(h):.1f} % of Rz, "
                  f"width {100 * min(w):.1f}-{100 * max(w):.1f} % of the sampling length")
        for rule, *res in g[:10]:
            label = " ".join(str(rule[k]) for k in ("start", "ends", "h", "w"))
            print(_line(f"{label:>28}", *res))
    if args.mixed:
        hits, best = mixed_ends()
        print(f"\nE. ends mixed between sampling lengths: {hits} combinations give both")
        for _, label, rsm, rc in best:
            print(f"   {rsm:7.1f} {rc:8.3f}  {label}")


if __name__ == "__main__":
    main()
