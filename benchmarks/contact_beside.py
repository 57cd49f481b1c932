"""Our steady-rolling solver beside CONTACT on the same case and the same grid.

CONTACT is the reference code for rolling contact with friction by E. A. H. Vollebregt
and J. J. Kalker (open source, Apache-2.0, https://github.com/eve70a/CONTACT); its input
format, sign conventions and solvers are described in its user guide (Vollebregt,
*User guide for CONTACT, Rolling and sliding contact with friction*, Vtech CMCC, the
``doc/user-guide.tex`` of that repository, chapters "Module 3" and "Data units and sign
conventions"). This script writes CONTACT input decks for the case of
``benchmarks/rolling_contact.py`` (``free``): a steel ball (R = 20 mm) rolling on
aluminium at 5 N with mu = 0.3, on an n x n grid over [-1.25 a, 1.25 a]^2 (a the Hertz
radius), runs CONTACT when ``CONTACT_EXE`` names its executable, reads its totals, and
runs ours on the identical grid (:func:`contact.tangential.sphere_grid`).

Mapping of the case onto CONTACT (module 3, non-Hertzian, ``IPOTCN = 1``, ``IBASE = 1``):

- body 1 (the upper body, which receives the tractions and whose slip relative to body 2
  defines the creepage) is the steel ball, body 2 the aluminium flat: the same as our
  body 1 (:mod:`contact.halfspace.cerruti`), so Kalker's K has the same sign (-0.0791);
- rolling direction ``CHI = 0`` (the contact moves along +x, the leading edge is at the
  largest x), the step ``DQ = DX``: CONTACT's steady-state slip is then
  s_I = w + (u_I - u_{I+1})/dx, the same upwind difference as
  :func:`contact.tangential._kinematics.rolling_slip`; a positive creepage ``CKSI`` is
  our positive ``xi`` and ``FX`` is the same force on the ball;
- h = (x^2 + y^2)/(2 R) at the element centres (``B1 = B3 = 1/(2R)``), piecewise-constant
  tractions with analytical half-space coefficients (``C = 2``), Coulomb friction
  (``L = 0``, FSTAT = FKIN = mu), normal force prescribed (``N = 1``);
- solvers: CONTACT's defaults (``G = 0``): NormCG (FFT-preconditioned BCCG) for the
  pressure, SteadyGS for steady rolling, the Panagiotopoulos process for the coupling
  (``MAXOUT`` > 1), Newton-Raphson on ``CKSI`` for free rolling (``F = 1``, FX = 0);
  ``EPS = 1e-6`` as our tolerance.

Cases per grid: ``normal`` (T = 0, frictionless normal problem), ``free`` (T = 3, F = 1,
FX = 0) and ``creep`` (T = 3, F = 0, the creepages of ``--creepages``). CONTACT's wall
time is the process's (``time.perf_counter`` around it; its own timer table, 0.1 s
resolution, is read as well). Ours: :func:`contact.bem.solve_normal` for the normal solve
(as in ``rolling_contact.py``) and :func:`contact.tangential.steady_rolling`.

Run (wall times on a shared machine are noisy; both sides run in the same period)::

    CONTACT_EXE=/path/to/contact PYTHONPATH=$PWD python3 benchmarks/contact_beside.py \\
        --sizes 32,64,128 [--keep DIR] [--json FILE]

Build CONTACT with ``../shared/tools/contact_oracle/build.sh CONTACT_GIT_DIR OUT_DIR``
(gfortran, FFTW); the project does not need it.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

RADIUS, LOAD, MU = 0.02, 5.0, 0.3
HALF = 1.25  # half-width of the grid over the Hertz radius
EPS = 1e-6
MM, MPA = 1e-3, 1e6  # CONTACT's units: mm, N, N/mm^2


@dataclass(frozen=True)
class Case:
    """One CONTACT run: ``kind`` is "normal", "free" or "creep" (with ``creepage``)."""

    kind: str
    creepage: float = 0.0

    @property
    def name(self) -> str:
        return self.kind if self.kind != "creep" else f"creep{self.creepage:.0e}"


def pair():
    """Materials (body 1 steel ball, body 2 aluminium), the pair constants and Hertz a."""
    from contact._hertz import hertz_sphere
    from contact._materials import material
    from contact.tangential import pair_constants

    steel, al = material("steel"), material("aluminium")
    c = pair_constants(steel, al)
    return steel, al, c, hertz_sphere(RADIUS, LOAD, c.e_star).a


def deck(n: int, case: Case, solver: str = "default") -> str:
    """The CONTACT input deck (module 3) of ``case`` on the n x n grid, mm-N units.

    ``solver``: "default" (G = 0: SteadyGS for steady rolling) or "gdsteady" (G = 5,
    CONTACT's experimental GDsteady with its built-in default parameters).
    """
    steel, al, _, a = pair()
    half = HALF * a / MM
    dx = 2.0 * half / n
    g1, g2 = (m.E / (2.0 * (1.0 + m.nu)) / MPA for m in (steel, al))
    t, f = {"normal": (0, 0), "free": (3, 1), "creep": (3, 0)}[case.kind]
    gdigit = {"default": 0, "gdsteady": 5}[solver]
    lines = [
        f"% {case.name}: steel ball R = {RADIUS / MM:g} mm on aluminium, FN = {LOAD:g} N, "
        f"mu = {MU:g}, {n} x {n} grid over [-{HALF:g} a, {HALF:g} a]^2",
        " 3  MODULE",
        f"  20{t}1{f}0     P-B-T-N-F-S   PVTIME, BOUND, TANG, NORM, FORCE, STRESS",
        "  022020     L-D-C-M-Z-E   FRCLAW, DISCNS, INFLCF, MATER, RZNORM, EXRHS",
        f" 0{gdigit}01301   H-G-I-A-O-W-R   HEAT, GAUSEI, IESTIM, MATFIL, OUTPUT, FLOW, RETURN",
        f"  999  100  30  30  {EPS:g}     MAXGS, MAXIN, MAXNR, MAXOUT, EPS",
    ]
    if gdigit == 5:
        lines.append("  0.90  0.10  1  1.0  1.0  1.0  1.0  0.90     FDECAY, BETATH, KDOWFB, "
                     "D_IFC, D_LIN, D_CNS, D_SLP, POW_S")
    lines += [
        f"  {LOAD!r}  {case.creepage!r}  0.0  0.0     FN, CKSI (F=0) or FXREL (F=1), "
        "CETA, CPHI",
        f"  {MU!r}  {MU!r}     FSTAT, FKIN",
    ]
    if t > 0:
        lines.append(f"  0.0  {dx!r}  1.0     CHI, DQ, VELOC")
    lines += [
        f"  {steel.nu!r}  {al.nu!r}  {g1!r}  {g2!r}     POISS 1,2, GG 1,2 (body 1 steel)",
        "  1     IPOTCN",
        f"  {n}  {n}  {-half!r}  {-half!r}  {dx!r}  {dx!r}     MX, MY, XL, YL, DX, DY",
        "  1  1     IBASE, IPLAN",
        f"  {0.5 / (RADIUS / MM)!r}  0.0  {0.5 / (RADIUS / MM)!r}  0.0  0.0  0.0     B1-B6",
        " 0  MODULE",
        "",
    ]
    return "\n".join(lines)


def _after(lines: list[str], marker: str, offset: int) -> list[str]:
    k = max(i for i, s in enumerate(lines) if marker in s)
    return lines[k + offset].split()


def parse_out(text: str) -> dict:
    """Totals of the last case in a CONTACT ``.out`` file, converted to SI."""
    if "ERROR" in text or "Diverges" in text:
        bad = next(s for s in text.splitlines() if "ERROR" in s or "Diverges" in s)
        raise RuntimeError(f"CONTACT failed: {bad.strip()}")
    lines = text.splitlines()
    top = [float(v) for v in _after(lines, "TOTAL FORCES", 2)]
    second_head = lines[max(i for i, s in enumerate(lines) if "TOTAL FORCES" in s) + 3]
    second = [float(v) for v in _after(lines, "TOTAL FORCES", 4)]
    stats = [int(v) for v in _after(lines, "NPOT   NCON", 1)]
    out = {"fn": top[0], "fx": top[1], "approach": second[3] * MM, "pmax": second[4] * MPA,
           "n_contact": stats[1], "n_adhesion": stats[2], "n_slip": stats[3]}
    if "CREEP X" in second_head:
        out["creepage"] = second[1]
    wall = [s for s in lines if s.startswith("|Total ")]
    if wall:
        out["timer_wall"] = float(wall[-1].split("|")[5])
    return out


def parse_mat(path: Path, dx: float) -> dict:
    """Fx, Fn and pmax (SI) summed from a CONTACT ``.mat`` element table (6 digits)."""
    # header lines first, then the element table after its column line "% I IGS H ..."
    lines = path.read_text().splitlines()
    top = max(i for i, s in enumerate(lines) if s.startswith("%") and " IGS " in s)
    rows = np.array([[float(v) for v in s.split()] for s in lines[top + 1:] if s.strip()])
    pn, px = rows[:, 4], rows[:, 5]
    area = dx * dx  # mm^2
    return {"fn_mat": float(pn.sum() * area), "fx_mat": float(px.sum() * area),
            "pmax_mat": float(pn.max() * MPA)}


def run_contact(exe: str, n: int, case: Case, workdir: Path, timeout: float = 300.0,
                solver: str = "default") -> dict:
    """Write the deck, run CONTACT on it, return its totals (SI) and wall time (s)."""
    name = f"ball_n{n}_{case.name}" + ("" if solver == "default" else f"_{solver}")
    (workdir / f"{name}.inp").write_text(deck(n, case, solver))
    t = time.perf_counter()
    subprocess.run([exe, "2", name], cwd=workdir, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, timeout=timeout, check=True)
    wall = time.perf_counter() - t
    out = parse_out((workdir / f"{name}.out").read_text())
    mat = workdir / f"{name}.0001.mat"
    if mat.exists():
        _, _, _, a = pair()
        out.update(parse_mat(mat, 2.0 * HALF * a / MM / n))
    out["wall"] = wall
    return out


def run_ours(n: int, creepages: list[float]) -> dict:
    """Our normal solve, free rolling and prescribed creepages on the same grid."""
    from contact.bem import solve_normal
    from contact.tangential import Creepage, sphere_grid, steady_rolling

    _, _, c, a = pair()
    grid = sphere_grid(RADIUS, HALF * a, n)
    res: dict = {}
    t = time.perf_counter()
    nr = solve_normal(grid, e_star=c.e_star, load=LOAD)
    res["normal"] = {"wall": time.perf_counter() - t, "pmax": nr.pmax,
                     "approach": nr.approach, "n_contact": int(np.count_nonzero(nr.contact))}
    runs = [("free", {"fx": 0.0})] + [(Case("creep", x).name, {"creepage": Creepage(x)})
                                       for x in creepages]
    for name, kw in runs:
        t = time.perf_counter()
        r = steady_rolling(grid, c, LOAD, MU, **kw)
        res[name] = {"wall": time.perf_counter() - t, "creepage": r.creepage.xi, "fx": r.fx,
                     "pmax": r.pmax, "approach": r.approach,
                     "n_contact": int(np.count_nonzero(r.p > 0)), "n_adhesion": r.n_stick,
                     "n_slip": r.n_slip}
    return res


def _value(v, unit: str, source: str, digits: int | None = None) -> dict:
    if digits is not None and source.startswith(".out"):
        v = float(f"{v:.{digits}g}")  # as printed, without the mm -> m rounding noise
    out = {"value": v, "unit": unit, "from": source}
    if digits is not None:
        out["significant_digits"] = digits
    return out


def reference(exe: str, sizes: list[int], creepages: list[float], folder: Path) -> None:
    """Run the decks into ``folder`` and write ``contact_reference.json`` (SI, CONTACT only).

    Kept: the decks (``.inp``) and CONTACT's printed outputs (``.out``); the element
    tables (``.mat``) are read for Fx and pmax (6 significant digits per element) and
    deleted. Creepage and approach come from the ``.out`` (4 significant digits).
    """
    steel, al, _, a = pair()
    folder.mkdir(parents=True, exist_ok=True)
    cases = [Case("free")] + [Case("creep", x) for x in creepages]
    grids = []
    for n in sizes:
        entry: dict = {"n": n, "dx": _value(2.0 * HALF * a / n, "m", "deck"), "cases": {}}
        for case in cases:
            r = run_contact(exe, n, case, folder)
            mat = folder / f"ball_n{n}_{case.name}.0001.mat"
            mat.unlink()
            entry["cases"][case.name] = {
                "deck": f"ball_n{n}_{case.name}.inp",
                "creepage": _value(r.get("creepage", case.creepage), "1",
                                   ".out CREEP X" if case.kind == "free" else "prescribed",
                                   4 if case.kind == "free" else None),
                "fx": _value(0.0 if case.kind == "free" else r["fx_mat"], "N",
                             "prescribed" if case.kind == "free" else ".mat sum(PX) dx dy", 6),
                "pmax": _value(r["pmax_mat"], "Pa", ".mat max(PN)", 6),
                "approach": _value(r["approach"], "m", ".out APPROACH", 4),
                "n_contact": _value(r["n_contact"], "elements", ".out NCON"),
                "n_adhesion": _value(r["n_adhesion"], "elements", ".out NADH"),
                "n_slip": _value(r["n_slip"], "elements", ".out NSLIP"),
            }
        grids.append(entry)
    banner = next(s for s in (folder / f"ball_n{sizes[0]}_free.out").read_text().splitlines()
                  if "Version" in s)
    doc = {
        "source": "CONTACT by E. A. H. Vollebregt and J. J. Kalker (Apache-2.0, "
                  "github eve70a/CONTACT), " + banner.strip(" |").strip(),
        "produced_by": "benchmarks/contact_beside.py --reference (see README.md here)",
        "case": {
            "radius": _value(RADIUS, "m", "deck"), "load": _value(LOAD, "N", "deck"),
            "mu": _value(MU, "1", "deck"),
            "body1": {"name": steel.name, "G": _value(steel.E / (2 * (1 + steel.nu)), "Pa",
                                                      "deck"), "nu": _value(steel.nu, "1", "deck")},
            "body2": {"name": al.name, "G": _value(al.E / (2 * (1 + al.nu)), "Pa", "deck"),
                      "nu": _value(al.nu, "1", "deck")},
            "half_width": _value(HALF * a, "m", "deck"),
            "grid": "n x n element centres over [-half_width, half_width]^2, "
                    "h = (x^2 + y^2)/(2 radius)",
            "rolling": "steady state, CHI = 0 (+x), DQ = dx, eta = phi = 0",
        },
        "grids": grids,
    }
    (folder / "contact_reference.json").write_text(json.dumps(doc, indent=1) + "\n")


def _warm() -> None:
    # compiled kernels load from the numba cache on first use: not the solvers' time
    from contact.bem import solve_normal
    from contact.tangential import sphere_grid, steady_rolling

    _, _, c, a = pair()
    g = sphere_grid(RADIUS, HALF * a, 16)
    solve_normal(g, e_star=c.e_star, load=LOAD)
    steady_rolling(g, c, LOAD, MU, fx=0.0)


def _fmt(v, spec: str) -> str:
    width = int(spec.split(".")[0].rstrip("dfe") or 0)
    return "-".rjust(width) if v is None else format(v, spec)


def table(rows: list[dict]) -> None:
    """Print the side-by-side table (C = CONTACT, S = surfmet)."""
    head = (f"{'n':>4}{'C norm s':>9}{'C roll s':>9}{'S norm s':>9}{'S roll s':>9}"
            f"{'C creep':>11}{'S creep':>11}{'C fx(1e-4)':>11}{'S fx(1e-4)':>11}"
            f"{'C pmax MPa':>11}{'S pmax MPa':>11}{'C slip':>7}{'S slip':>7}")
    print(head)
    for r in rows:
        c, s = r.get("contact", {}), r["ours"]
        cf, sf = c.get("free", {}), s["free"]
        key = Case("creep", 1e-4).name
        print(f"{r['n']:4d}{_fmt(c.get('normal', {}).get('wall'), '9.2f')}"
              f"{_fmt(cf.get('wall'), '9.2f')}{s['normal']['wall']:9.2f}{sf['wall']:9.2f}"
              f"{_fmt(cf.get('creepage'), '11.4e')}{sf['creepage']:11.4e}"
              f"{_fmt(c.get(key, {}).get('fx_mat'), '11.5f')}"
              f"{_fmt(s.get(key, {}).get('fx'), '11.5f')}"
              f"{_fmt(cf['pmax_mat'] / MPA if 'pmax_mat' in cf else None, '11.3f')}"
              f"{sf['pmax'] / MPA:11.3f}{_fmt(cf.get('n_slip'), '7d')}{sf['n_slip']:7d}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="32,64,128")
    ap.add_argument("--creepages", default="1e-4,1e-3", help="prescribed xi ('' for none)")
    ap.add_argument("--timeout", type=float, default=300.0, help="per CONTACT run (s)")
    ap.add_argument("--keep", type=Path, help="folder for the CONTACT decks and outputs")
    ap.add_argument("--json", type=Path, help="write every number (SI) to this file")
    ap.add_argument("--no-ours", action="store_true", help="CONTACT only")
    ap.add_argument("--reference", type=Path,
                    help="write the decks, outputs and contact_reference.json here and stop")
    ap.add_argument("--solver", choices=("default", "gdsteady"), default="default",
                    help="CONTACT's steady-rolling solver: SteadyGS (default) or GDsteady")
    args = ap.parse_args()
    sizes = [int(v) for v in args.sizes.split(",")]
    creepages = [float(v) for v in args.creepages.split(",") if v.strip()]
    exe = os.environ.get("CONTACT_EXE")
    if not exe:
        print("CONTACT_EXE is not set: build CONTACT with ../shared/tools/contact_oracle/"
              "build.sh CONTACT_GIT_DIR OUT_DIR and point CONTACT_EXE at the executable")
        sys.exit(0)
    if args.reference:
        reference(exe, sizes, creepages, args.reference)
        return
    cases = [Case("normal"), Case("free")] + [Case("creep", x) for x in creepages]
    if not args.no_ours:
        _warm()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        work = args.keep or Path(tmp)
        work.mkdir(parents=True, exist_ok=True)
        for n in sizes:
            row: dict = {"n": n, "contact": {}}
            for case in cases:
                try:
                    row["contact"][case.name] = run_contact(exe, n, case, work, args.timeout,
                                                              args.solver)
                except (subprocess.TimeoutExpired, RuntimeError) as err:
                    print(f"n = {n} {case.name}: CONTACT {type(err).__name__}: {err}")
            row["ours"] = {} if args.no_ours else run_ours(n, creepages)
            rows.append(row)
            if not args.no_ours:
                table([row])
    if not args.no_ours:
        print("\nall sizes:")
        table(rows)
    if args.json:
        args.json.write_text(json.dumps(rows, indent=1))


if __name__ == "__main__":
    main()
