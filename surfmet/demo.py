"""``surfmet demo``: the whole story of Alaci et al. (2022) on the scans shipped with surfmet.

:func:`run_demo` reads the bundled stand-ins for the paper's two scans
(``surfmet/data/paper_plate.x3p`` and ``paper_ball.x3p``, synthetic surfaces with the
statistics of the paper's Table 2, written by surfmet's own X3P writer; see
``examples/paper_2022/make_surfaces.py``), and then, calling the library for every step:

1. roughness: the R-parameters of every row of both scans with the settings of ISO 4288
   (least-squares line on the plate, parabola on the ball, Gaussian filter λc = 0.8 mm),
   their medians against Table 2, and the plate's areal parameters before and after spike
   removal (the spikes are why the paper's Table 1 has Sq/Sa up to 4.3);
2. the ball's radius: least-squares sphere with its standard uncertainty, against the
   nominal 20 mm, and circle fits of the row and the column through the apex (the form
   deviation the paper's Fig. 16 shows);
3. the Hertz check at the paper's 10 N (:func:`surfmet.hertz_check.hertz_check`): verdict
   and reasons;
4. a contact solve at the rotor's load per ball (elastic-perfectly-plastic, on the same
   paired roughness);
5. a short rolling-resistance sweep (:func:`surfmet.rolling.rolling_resistance`);
6. the law-of-motion analysis of Table 3 (:func:`contact.rotor.groups.analyse_table`) on
   ``surfmet/data/table3_frames.tsv``, the paper's table re-typed and split
   (:mod:`contact.rotor.frames`), with the paper's parabolas reproduced.

Figures and ``summary.json`` (every dimensional value ``{"value": v, "unit": "..."}``)
go to the output folder; :func:`story` turns the summary into the text ``surfmet demo``
prints.

The paper's own numbers that the story quotes (Table 2's means, the Hertz check's 0.936 µm
and 136 µm, the parabolas φ_s and φ_a) are re-typed below from the paper's text.
"""

from __future__ import annotations

import json
import math
import os
import sys
import time
from collections.abc import Callable
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np

from surfmet.errors import SurfmetInputError
from surfmet.units import format_length, quantity

#: The marker ``summary.json`` carries, by which a previous demo output is recognised.
GENERATOR = "surfmet demo"
SUMMARY = "summary.json"

RADIUS = 0.02  # m, nominal radius of the rotor's balls
MATERIALS = "steel,aluminium"
CHECK_LOAD = 10.0  # N, the load of the paper's Hertz check ("the rotor weight")
LC = "0.8mm"  # ISO 4288 cut-off for Ra in 0.1-2 µm
PLATE_LEVEL = "plane"  # a least-squares line on each row
BALL_LEVEL = "poly:2"  # a parabola takes the ball's curvature off each row

#: Table 2 of the paper, means of its three profiles (µm).
PAPER_TABLE2_MEAN_UM = {
    "plate": {"Ra": (1.776 + 1.263 + 2.165) / 3, "Rq": (2.342 + 1.629 + 2.639) / 3,
              "Rz": (11.220 + 9.277 + 13.566) / 3, "Rt": (16.256 + 11.337 + 13.566) / 3},
    "ball": {"Ra": (0.209 + 0.230 + 0.192) / 3, "Rq": (0.330 + 0.329 + 0.290) / 3},
}
#: The paper's Hertz check at 10 N (Section 3): approach and contact radius (m).
PAPER_HERTZ = {"delta": 0.936e-6, "a": 136e-6}
#: The paper's parabolas (Section 4): phi = c2 t^2 + c1 t + c0 (rad, t in s).
PAPER_PARABOLAS = {"phi_s": (0.821, 1.134, -0.527), "phi_a": (0.951, 1.0254, -0.249)}

ROW_PARAMETERS = ("Ra", "Rq", "Rz", "Rt")

#: Every figure the demo can write, in the order of the story.
FIGURES = {
    "plate_height_map": "plate_height_map.png",
    "plate_profile": "plate_profile.png",
    "plate_abbott_firestone": "plate_abbott_firestone.png",
    "psd": "psd.png",
    "ball_form": "ball_form.png",
    "hertz_check": "hertz_check.png",
    "contact_pressure": "contact_pressure.png",
    "rolling": "rolling.png",
    "rotor_law_of_motion": "rotor_law_of_motion.png",
    "rotor_residuals": "rotor_residuals.png",
}


def data_file(name: str) -> Path:
    """Path of a file shipped in ``surfmet/data``."""
    path = Path(str(resources.files("surfmet").joinpath("data", name)))
    if not path.is_file():
        raise SurfmetInputError(f"the shipped data file {name} is missing from {path.parent}; "
                                "reinstall surfmet")
    return path


# ---------------------------------------------------------------------------------------
# the output folder


def _previous_summary(folder: Path) -> dict[str, Any] | None:
    try:
        data = json.loads((folder / SUMMARY).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    return data if isinstance(data, dict) and data.get("generator") == GENERATOR else None


def prepare_output(out_dir: str | os.PathLike) -> Path:
    """Create the output folder, or make a previous demo output ready to be overwritten.

    A folder that exists and is not empty is used only if its ``summary.json`` was written
    by the demo; then the files that summary lists are removed first (nothing else is
    touched). The folder is marked at once (a ``summary.json`` saying the run is under
    way), so that a run that fails half-way can be repeated into the same folder.

    Raises
    ------
    SurfmetInputError
        The path is a file, or a non-empty folder that is not a previous demo output.
    """
    folder = Path(out_dir)
    if folder.exists() and not folder.is_dir():
        raise SurfmetInputError(f"{folder} exists and is not a folder; give another --out")
    if folder.is_dir() and any(folder.iterdir()):
        prev = _previous_summary(folder)
        if prev is None:
            raise SurfmetInputError(
                f"{folder} is not empty and does not look like a previous 'surfmet demo' "
                f"output (no {SUMMARY} written by the demo): refusing to write into it. "
                "Give another --out, or empty the folder."
            )
        # remove what the previous run wrote, by the names it recorded (plain names only)
        for name in (prev.get("figures") or {}).values():
            if isinstance(name, str) and name == Path(name).name and name in FIGURES.values():
                (folder / name).unlink(missing_ok=True)
    folder.mkdir(parents=True, exist_ok=True)
    _write_json(folder / SUMMARY, {"generator": GENERATOR, "status": "running"})
    return folder


def _write_json(path: Path, obj: Any) -> None:
    from surfmet.units import jsonable

    tmp = path.with_name(path.name + ".part")
    tmp.write_text(json.dumps(jsonable(obj), indent=2, ensure_ascii=False, allow_nan=False)
                   + "\n", encoding="utf-8")
    tmp.replace(path)


# ---------------------------------------------------------------------------------------
# the steps


def load_scans() -> tuple[Any, Any, dict[str, Any]]:
    """The shipped plate and ball scans and their ``surfmet info`` records."""
    import surfmet
    from surfmet.records import scan_record

    plate = surfmet.read(data_file("paper_plate.x3p"))
    ball = surfmet.read(data_file("paper_ball.x3p"))
    rec = {}
    for name, scan in (("plate", plate), ("ball", ball)):
        d = scan_record(scan)
        d["file"] = Path(str(d["file"])).name if d["file"] else None
        d["nan_fraction"] = quantity(d["nan_fraction"], "")
        d.pop("metadata")
        rec[name] = d
    return plate, ball, rec


def row_statistics(scan: Any, level: str, lc: str = LC) -> tuple[dict[str, Any], Any]:
    """R-parameters of every row: median and quartiles, and the analysis of the row whose
    Ra is nearest the median (for the profile figure).

    The median over rows is the statistic the paper's Table 2 is compared with: a few rows
    of the plate carry spikes, which a mean would let through.
    """
    from surfmet.roughness import roughness

    values: dict[str, list[float]] = {k: [] for k in ROW_PARAMETERS}
    for k in range(scan.ny):
        res = roughness(scan, profile=f"row:{k}", level=level, lc=lc)
        for key in values:
            values[key].append(res.value(key))
    arr = {k: np.asarray(v) for k, v in values.items()}
    med = {k: float(np.median(v)) for k, v in arr.items()}
    row = int(np.argmin(np.abs(arr["Ra"] - med["Ra"])))
    typical = roughness(scan, profile=f"row:{row}", level=level, lc=lc)
    rec = {
        "rows": scan.ny,
        "settings": {"level": level, "lc": quantity(typical.settings.get("lc"), "m"),
                     "evaluation_length": quantity(typical.settings.get("evaluation_length"),
                                                   "m"),
                     "filter": typical.settings.get("filter")},
        "median": {k: quantity(v, "m") for k, v in med.items()},
        "quartiles": {k: quantity(np.percentile(v, [25, 75]), "m") for k, v in arr.items()},
        "typical_row": row,
    }
    return rec, typical


def plate_areal(plate: Any) -> tuple[dict[str, Any], Any]:
    """Areal parameters of the levelled plate as scanned and with its spikes removed."""
    from surfmet.roughness import roughness

    which = ("height", "functional")
    raw = roughness(plate, level=PLATE_LEVEL, which=("Sa", "Sq", "Sku"))
    clean = roughness(plate, level=PLATE_LEVEL, spikes=True, which=which)
    sp = clean.spike_report
    rec = {
        "as_scanned": {
            "parameters": raw.to_json()["parameters"],
            "sq_over_sa": quantity(raw.value("Sq") / raw.value("Sa"), ""),
            "spikes_suspected": bool(raw.spike_diagnosis.suspected),
            "diagnosis": raw.spike_diagnosis.message,
        },
        "spikes_removed": {"count": int(sp.count), "points": int(sp.n_points),
                           "threshold": quantity(sp.threshold, "m")},
        "cleaned": {
            "parameters": clean.to_json()["parameters"],
            "sq_over_sa": quantity(clean.value("Sq") / clean.value("Sa"), ""),
            "gaussian_sq_over_sa": quantity(math.sqrt(math.pi / 2), ""),
        },
    }
    return rec, clean


def ball_form(ball: Any) -> tuple[dict[str, Any], Any]:
    """Sphere fit of the ball scan, and circle fits of the row and column through its apex."""
    import profiles
    from surfmet.extract import extract_profile
    from surfmet.fitting import fit_sphere
    from surfmet.records import fit_record

    fit = fit_sphere(ball)
    rec: dict[str, Any] = {"nominal_radius": quantity(RADIUS, "m"),
                           "sphere": fit_record(ball, "sphere")}
    dev = fit.radius - RADIUS
    rec["radius_minus_nominal"] = quantity(dev, "m")
    rec["radius_minus_nominal_in_uncertainties"] = quantity(dev / fit.radius_uncertainty, "")
    iy = min(max(round(fit.center[1] / ball.dy), 0), ball.ny - 1)
    ix = min(max(round(fit.center[0] / ball.dx), 0), ball.nx - 1)
    for key, spec in (("row_circle", f"row:{iy}"), ("column_circle", f"col:{ix}")):
        prof = extract_profile(ball, spec)
        c = profiles.fit_circle(np.asarray(prof.positions), np.asarray(prof.z))
        rec[key] = {"profile": spec, "radius": quantity(c.radius, "m"),
                    "radius_uncertainty": quantity(c.radius_uncertainty, "m")}
    residual = ball.replace(heights=np.asarray(fit.residuals))
    # The sphere residual is roughness, outliers and the form error; a quadratic fitted to
    # it keeps the form (the astigmatism of a cap that is not a sphere) and its PV is the
    # form deviation that roughness and outliers do not inflate.
    from surfmet.form import remove_form

    rough, _ = remove_form(residual, "poly:2")
    form = np.asarray(residual.heights) - np.asarray(rough.heights)
    rec["quadratic_form_pv"] = quantity(float(np.nanmax(form) - np.nanmin(form)), "m")
    return rec, residual


def hertz_step(plate: Any, ball: Any, load: float = CHECK_LOAD) -> tuple[dict[str, Any], Any]:
    """The Hertz check of the ball on the plate at ``load`` (both scans, spikes removed)."""
    from surfmet.hertz_check import hertz_check

    check = hertz_check(plate, ball=ball, radius=RADIUS, load=load, materials=MATERIALS)
    rec = check.to_json()
    details = check.details()
    # each criterion's number as a dimensionless quantity (a ratio or a fraction)
    details["criteria"] = [
        {"name": c["name"], "measured": quantity(c["value"], ""),
         "limit": quantity(c["limit"], ""), "passed": c["passed"], "decisive": c["decisive"]}
        for c in details["criteria"]
    ]
    rec["details"] = details
    rec["paper"] = {"delta": quantity(PAPER_HERTZ["delta"], "m"),
                    "a": quantity(PAPER_HERTZ["a"], "m")}
    return rec, check


def rotor_loads() -> dict[str, float]:
    """Normal load per ball of the paper's rotor on a level plate (Eqs. 41-42, 50-51), N."""
    from contact.rotor.mechanics import mass_properties, normal_reactions, paper_rotor

    sym = normal_reactions(mass_properties(paper_rotor(), "symmetric"))
    asym = normal_reactions(mass_properties(paper_rotor(), "end"))
    return {"symmetric": sym[0], "asymmetric_ball1": asym[0], "asymmetric_ball2": asym[1]}


def contact_step(check: Any, load: float) -> tuple[dict[str, Any], Any]:
    """Elastic-perfectly-plastic contact at ``load`` on the Hertz check's paired roughness."""
    import warnings

    from contact.errors import EdgeContactWarning
    from contact.materials import contact_hardness
    from contact.sphere import solve_sphere
    from surfmet.records import contact_record

    pair = check.scans.pair
    hardness = contact_hardness(check.ball_material, check.plate_material)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", EdgeContactWarning)
        res = solve_sphere(RADIUS, load, check.e_star, roughness=pair.roughness,
                           roughness_dx=pair.dx, roughness_dy=pair.dy, hardness=hardness)
    rec = contact_record(res, check.ball_material, check.plate_material, pair, radius=RADIUS,
                         plate_file="paper_plate.x3p", ball_file="paper_ball.x3p")
    rec["notes"] = [*rec["notes"], *(str(w.message) for w in caught)]
    return rec, res


def rolling_step(plate: Any, ball: Any, loads: str) -> tuple[dict[str, Any], Any]:
    """The hysteresis rolling-resistance sweep over ``loads`` ("F1:F2:N")."""
    from surfmet.rolling import rolling_resistance

    rep = rolling_resistance(plate, ball, radius=RADIUS, materials=MATERIALS, loads=loads,
                             model="hysteresis")
    return rep.to_json(), rep


def _parabola(coef: Any) -> dict[str, Any]:
    c2, c1, c0 = (float(c) for c in coef)
    return {"c2": quantity(c2, "rad/s²"), "c1": quantity(c1, "rad/s"), "c0": quantity(c0, "rad")}


def rotor_step() -> tuple[dict[str, Any], Any]:
    """The law-of-motion analysis of the shipped Table 3, and the paper's parabolas."""
    from contact.rotor.groups import analyse_table
    from contact.rotor.frames import table3_tsv
    from surfmet.frames import read_frames_table

    path = data_file("table3_frames.tsv")
    ks, cols = read_frames_table(path)
    an = analyse_table(cols, ks, fps=120.0, step=math.pi / 2, cv="approx")
    fps = an.fps
    tests = []
    for t in an.tests:
        tests.append({
            "name": t.name, "group": t.group, "selected_model": t.selected,
            "effect": t.effect, "misread_rows": [int(k) for k in t.outliers],
            "eps0": quantity(t.eps0, "rad/s²"), "eps0_stderr": quantity(t.eps0_stderr, "rad/s²"),
            "rms_paper_model": quantity(t.fits["rest"].rms * fps, "frame"),
            "rms_selected": quantity(t.fit.rms * fps, "frame"),
        })
    groups = []
    for g in an.groups:
        groups.append({
            "name": g.name, "tests": list(g.tests),
            "paper_parabola": _parabola(g.paper_parabola),
            "paper_parabola_stderr": _parabola(g.paper_parabola_stderr),
            "paper_parabola_rms": quantity(g.paper_rms, "rad"),
            "eps0": {m: {"mean": quantity(v[0], "rad/s²"), "uncertainty": quantity(v[1], "rad/s²")}
                     for m, v in g.eps.items() if m in ("paper", "rest", "const", an.study_model)},
        })
    # which group's parabola is each of the paper's (to the three decimals it prints)?
    match = {}
    for label, ref in PAPER_PARABOLAS.items():
        for g in an.groups:
            if np.allclose(np.round(g.paper_parabola, 3), np.round(ref, 3), atol=1e-9):
                match[label] = g.name
    comps = [{"groups": [c.a, c.b], "model": c.model, "quantity": c.quantity,
              "difference": quantity(c.difference, "rad/s²"),
              "uncertainty": quantity(c.uncertainty, "rad/s²"),
              "z": quantity(c.z, ""), "p_value": quantity(c.p_value, "")}
             for c in an.comparisons if c.quantity == "eps0"]
    rec = {
        "file": path.name,
        "equals_the_split_of_the_printed_rows": path.read_text(encoding="utf-8") == table3_tsv(),
        "fps": quantity(fps, "1/s"), "step": quantity(an.step, "rad"),
        "quantisation_sigma": quantity(an.noise_floor, "s"),
        "study_model": an.study_model,
        "tests": tests,
        "groups": groups,
        "paper_reported": {k: _parabola(v) for k, v in PAPER_PARABOLAS.items()},
        "paper_label_match": match,
        "comparisons": comps,
    }
    return rec, an


# ---------------------------------------------------------------------------------------
# figures


def _figure(out: Path, key: str, draw: Callable[[Path], Any], written: dict[str, str]) -> None:
    from surfmet.plots._style import close

    path = out / FIGURES[key]
    close(draw(path))
    written[key] = FIGURES[key]


# ---------------------------------------------------------------------------------------
# the whole story


def run_demo(
    out_dir: str | os.PathLike = "surfmet_demo",
    *,
    quick: bool = False,
    progress: bool | Callable[[str], None] = True,
) -> dict[str, Any]:
    """Run the demo and write its figures and ``summary.json`` to ``out_dir``.

    Parameters
    ----------
    out_dir : path
        Output folder: created if absent; a non-empty folder must be a previous demo
        output (see :func:`prepare_output`).
    quick : bool
        A shorter rolling sweep (3 loads instead of 5) and no PSD or Abbott–Firestone
        figure; every number the story quotes is computed the same way.
    progress : bool or callable
        Report each step on stderr (True), not at all (False), or to ``progress(line)``.

    Returns
    -------
    dict
        The summary, as written to ``summary.json``.
    """
    import surfmet

    out = prepare_output(out_dir)
    if callable(progress):
        say = progress
    elif progress:
        def say(line: str) -> None:
            print(line, file=sys.stderr, flush=True)
    else:
        def say(line: str) -> None:
            return None

    steps = 7
    timings: dict[str, Any] = {}
    t_start = time.perf_counter()
    state = {"n": 0, "t": t_start}

    def step(name: str, text: str) -> None:
        state["n"] += 1
        state["t"] = time.perf_counter()
        state["name"] = name
        say(f"step {state['n']}/{steps}: {text} ...")

    def done() -> None:
        dt = time.perf_counter() - state["t"]
        timings[state["name"]] = quantity(dt, "s")
        say(f"  done in {dt:.1f} s")

    figures: dict[str, str] = {}
    summary: dict[str, Any] = {"generator": GENERATOR, "surfmet_version": surfmet.__version__,
                               "status": "running", "quick": bool(quick)}

    step("read", "reading the shipped plate and ball scans (x3p)")
    plate, ball, summary["scans"] = load_scans()
    done()

    step("roughness", "roughness of every row of both scans, and the plate's areal "
         "parameters")
    rough: dict[str, Any] = {}
    rough["plate_rows"], typical = row_statistics(plate, PLATE_LEVEL)
    rough["ball_rows"], _ = row_statistics(ball, BALL_LEVEL)
    rough["paper_table2_mean"] = {k: {p: quantity(v * 1e-6, "m") for p, v in d.items()}
                                  for k, d in PAPER_TABLE2_MEAN_UM.items()}
    rough["plate_areal"], clean = plate_areal(plate)
    summary["roughness"] = rough
    _figure(out, "plate_height_map", lambda p: _height_map(clean.surface, p,
            "aluminium plate (stand-in): levelled, spikes removed"), figures)
    row = rough["plate_rows"]["typical_row"]
    _figure(out, "plate_profile", lambda p: _profile_fig(typical.analysis, p,
            f"plate row {row} (Ra nearest the median of all rows)"), figures)
    if not quick:
        _figure(out, "plate_abbott_firestone",
                lambda p: _abbott(clean, p), figures)
    done()

    step("ball", "the ball's radius (sphere fit) and form deviation")
    summary["ball"], residual = ball_form(ball)
    _figure(out, "ball_form", lambda p: _height_map(
        residual, p, f"ball minus its best-fit sphere (R = "
        f"{summary['ball']['sphere']['radius']['value'] * 1e3:.3f} mm)"), figures)
    if not quick:
        _figure(out, "psd", lambda p: _psd_fig(clean.surface, residual, p), figures)
    done()

    step("hertz", f"Hertz check at {CHECK_LOAD:g} N (boundary elements on both scans)")
    summary["hertz_check"], check = hertz_step(plate, ball)
    _figure(out, "hertz_check", check.figure, figures)
    done()

    loads = rotor_loads()
    step("contact", f"contact at the rotor's load per ball, {loads['symmetric']:.2f} N "
         "(elastic-perfectly-plastic)")
    rec, res = contact_step(check, loads["symmetric"])
    rec["rotor_loads"] = {k: quantity(v, "N") for k, v in loads.items()}
    summary["contact"] = rec
    _figure(out, "contact_pressure", lambda p: _pressure(res, p), figures)
    done()

    n_loads = 3 if quick else 5
    step("rolling", f"rolling-resistance sweep, {n_loads} loads from 1 N to 100 N")
    summary["rolling"], rep = rolling_step(plate, ball, f"1N:100N:{n_loads}")
    _figure(out, "rolling", rep.figure, figures)
    done()

    step("rotor", "law of motion of the rotor (the paper's Table 3)")
    summary["rotor"], an = rotor_step()
    from surfmet.plots.rotor import law_of_motion_figure, residual_figure

    _figure(out, "rotor_law_of_motion", lambda p: law_of_motion_figure(an, p), figures)
    _figure(out, "rotor_residuals", lambda p: residual_figure(an, p), figures)
    done()

    summary["figures"] = figures
    summary["timings"] = timings
    summary["total_time"] = quantity(time.perf_counter() - t_start, "s")
    summary["out_dir"] = str(out)
    summary["status"] = "complete"
    _write_json(out / SUMMARY, summary)
    say(f"figures and {SUMMARY} written to {out} ({time.perf_counter() - t_start:.0f} s)")
    from surfmet.units import jsonable

    return jsonable(summary)


def _height_map(topo: Any, path: Path, title: str) -> Any:
    from surfmet.plots.areal import height_map

    return height_map(topo, path, title=title)


def _profile_fig(analysis: Any, path: Path, title: str) -> Any:
    from surfmet.plots.profile import profile_figure

    return profile_figure(analysis, path, title=title)


def _abbott(clean: Any, path: Path) -> Any:
    from surfmet.plots.areal import abbott_firestone

    return abbott_firestone(clean.surface, path, parameters=clean.parameters,
                            title="aluminium plate: material ratio curve (ISO 25178-2)")


def _psd_fig(plate_surface: Any, ball_residual: Any, path: Path) -> Any:
    from surfmet.plots.areal import psd_figure
    from surfmet.psd import psd

    return psd_figure([psd(plate_surface), psd(ball_residual)], path,
                      labels=["aluminium plate (5 µm pitch)",
                              "steel ball minus its sphere (50 µm pitch)"],
                      title="radially averaged PSD")


def _pressure(res: Any, path: Path) -> Any:
    from surfmet.plots.contact import pressure_map

    return pressure_map(res, path)


# ---------------------------------------------------------------------------------------
# the text


def _v(q: Any) -> float:
    v = q["value"] if isinstance(q, dict) else q
    return math.nan if v is None else float(v)


def _um(q: Any, digits: int = 3) -> str:
    return f"{_v(q) * 1e6:.{digits}f} µm"


def story(summary: dict[str, Any]) -> str:
    """The demo's findings as text for a terminal (from the summary alone)."""
    import textwrap

    lines: list[str] = []

    def head(text: str) -> None:
        lines.extend(["", text, "-" * len(text)])

    def para(text: str, indent: str = "") -> None:
        lines.extend(textwrap.wrap(text, 92, initial_indent=indent,
                                   subsequent_indent=indent + ("  " if indent else "")))

    lines.append("surfmet demo: rolling friction of a steel ball on an aluminium plate "
                 "(Alaci et al. 2022)")
    sc = summary["scans"]
    for name, what in (("plate", "aluminium plate"), ("ball", "steel ball")):
        s = sc[name]
        lines.append(f"  {what:16} {s['file']}: {s['nx']} x {s['ny']} points, pitch "
                     f"{format_length(_v(s['dx']))}, {format_length(_v(s['size_x']))} x "
                     f"{format_length(_v(s['size_y']))}")
    para("These are synthetic stand-ins with the statistics of the paper's scans, written "
         "as X3P by surfmet (the original NanoFocus files are not public).", "  ")

    r = summary["roughness"]
    head(f"1. Roughness (every row; λc = {_v(r['plate_rows']['settings']['lc']) * 1e3:g} mm, "
         "ISO 4288)")
    lines.append(f"  {'':16}{'median of rows':>16}{'paper (Table 2 mean)':>24}")
    for part, key in (("plate", "plate_rows"), ("ball", "ball_rows")):
        paper = r["paper_table2_mean"][part]
        label = part
        for sym, q in r[key]["median"].items():
            ref = f"{_v(paper[sym]) * 1e6:.3f} µm" if sym in paper else "-"
            lines.append(f"  {label:6}{sym:10}{_um(q):>16}{ref:>24}")
            label = ""
    a = r["plate_areal"]
    raw, cl = a["as_scanned"], a["cleaned"]
    lines.append(f"  plate areal, as scanned: Sa {_um(raw['parameters']['Sa'])}, Sq "
                 f"{_um(raw['parameters']['Sq'])}, Sq/Sa = {_v(raw['sq_over_sa']):.2f}")
    lines.append(f"  after removing {a['spikes_removed']['count']} spikes: Sa "
                 f"{_um(cl['parameters']['Sa'])}, Sq {_um(cl['parameters']['Sq'])}, Sq/Sa = "
                 f"{_v(cl['sq_over_sa']):.3f} (Gaussian {_v(cl['gaussian_sq_over_sa']):.3f})")
    para("Optical spikes, not roughness, are what pushed the paper's Table 1 Sq/Sa up to 4.3; "
         "surfmet flags them and takes them out before any contact analysis.", "  ")

    b = summary["ball"]
    sp = b["sphere"]
    head("2. The ball's radius")
    lines.append(f"  best-fit sphere  R = {_v(sp['radius']) * 1e3:.4f} mm ± "
                 f"{_v(sp['radius_uncertainty']) * 1e6:.2f} µm (k = 1), nominal "
                 f"{_v(b['nominal_radius']) * 1e3:g} mm")
    lines.append(f"  R - nominal = {_v(b['radius_minus_nominal']) * 1e6:+.1f} µm = "
                 f"{_v(b['radius_minus_nominal_in_uncertainties']):+.0f} uncertainties")
    lines.append(f"  sphere residual {_um(sp['rms_residual'], 2)} rms (roughness, outliers, form);"
                 f" form deviation {_um(b['quadratic_form_pv'], 2)} PV")
    lines.append(f"  circle fits: {b['row_circle']['profile']} R = "
                 f"{_v(b['row_circle']['radius']) * 1e3:.3f} mm, "
                 f"{b['column_circle']['profile']} R = "
                 f"{_v(b['column_circle']['radius']) * 1e3:.3f} mm (the cap is not a sphere)")

    h = summary["hertz_check"]
    d = h["details"]
    head(f"3. Does Hertz hold? ({_v(d['load']):g} N, R = {_v(d['radius']) * 1e3:g} mm, "
         f"{d['materials']['ball']} on {d['materials']['plate']})")
    lines.append(f"  Hertz: δ0 = {_um(h['hertz']['delta'])} (paper {_um(h['paper']['delta'])}), "
                 f"a0 = {_um(h['hertz']['a'], 1)} (paper {_um(h['paper']['a'], 1)}), p0 = "
                 f"{_v(h['hertz']['p0']) / 1e6:.0f} MPa")
    verdict = "Hertz holds" if h["hertz_holds"] else "Hertz does NOT hold"
    lines.append(f"  verdict: {verdict} (α = {_v(h['alpha']):.3g}, σ = {_um(h['sigma'])})")
    for reason in h["reasons"]:
        para(f"- {reason}", "    ")

    c = summary["contact"]
    rl = c["rotor_loads"]
    head(f"4. Contact at the rotor's load ({_v(c['load']):.2f} N per ball)")
    lines.append(f"  rotor loads per ball: symmetric {_v(rl['symmetric']):.2f} N; asymmetric "
                 f"{_v(rl['asymmetric_ball1']):.2f} N and {_v(rl['asymmetric_ball2']):.2f} N")
    lines.append(f"  grid {c['grid']['nx']} x {c['grid']['ny']}, pitch "
                 f"{format_length(_v(c['grid']['dx']))}; {c['iterations']} iterations, "
                 f"{'converged' if c['converged'] else 'NOT converged'}")
    lines.append(f"  95 % of the load within {_um(c['radius_95'], 0)} of the centre (Hertz a0 "
                 f"{_um(c['hertz']['a'], 0)})")
    lines.append(f"  approach {_um(c['approach'])} (Hertz {_um(c['hertz']['delta'])})")
    a_hz = math.pi * _v(c["hertz"]["a"]) ** 2
    lines.append(f"  {c['n_clusters']} contact spots, real area {_v(c['contact_area']) / a_hz:.3g}"
                 f" × π a0², of which {_v(c['plastic_area']) / a_hz:.3g} × π a0² at the "
                 f"hardness {_v(c['hardness']) / 1e6:.0f} MPa")
    lines.append(f"  regime: {c['regime']}")

    ro = summary["rolling"]
    lo, hi = ro["lambda_ci"]["value"]
    head("5. Rolling resistance M_r = s_r N^λ (hysteresis model, one track position)")
    lines.append(f"  λ_eff = {_v(ro['lambda_eff']):.3f}, "
                 f"{100 * _v(ro['settings']['confidence']):.0f} % CI [{lo:.3f}, {hi:.3f}]   "
                 "(smooth Hertz contact: 4/3)")
    lines.append(f"  {'load (N)':>10}{'M_r (N m)':>13}{'local λ':>10}")
    for w, m, lam in zip(ro["loads"]["value"], ro["moments"]["value"],
                         ro["local_lambda"]["value"]):
        lam_s = f"{lam:10.3f}" if lam is not None else f"{'-':>10}"
        lines.append(f"  {w:10.3g}{m:13.4g}{lam_s}")

    rt = summary["rotor"]
    head("6. The rotor's law of motion (Table 3, 120 frames/s, marks every 90°)")
    lines.append(f"  {rt['file']}: equals the split of the paper's printed rows: "
                 f"{rt['equals_the_split_of_the_printed_rows']}")
    for g in rt["groups"]:
        p = g["paper_parabola"]
        lines.append(f"  columns {g['name']:>2} ({', '.join(g['tests'])}): φ = "
                     f"{_v(p['c2']):.3f} t² {_v(p['c1']):+.3f} t {_v(p['c0']):+.3f} rad")
    inv = {v: k for k, v in rt["paper_label_match"].items()}
    for label, ref in rt["paper_reported"].items():
        grp = rt["paper_label_match"].get(label)
        where = f"reproduced by columns '{grp}'" if grp else "not reproduced by any group"
        lines.append(f"  paper's {label} = {_v(ref['c2']):g} t² {_v(ref['c1']):+g} t "
                     f"{_v(ref['c0']):+g}: {where}")
    if inv.get("as") == "phi_s" and inv.get("s") == "phi_a":
        para("The paper's labels are swapped: its 'symmetric' parabola fits Table 3's "
             "asymmetric columns and vice versa.", "  ")
    lines.append(f"  model chosen by the summed BIC: {rt['study_model']}")
    lines.append(f"  {'test':6}{'chosen model':24}{'misread k':>10}{'rms rest':>10}"
                 f"{'rms chosen':>12}  (frames)")
    for t in rt["tests"]:
        mis = ",".join(str(k) for k in t["misread_rows"]) or "-"
        lines.append(f"  {t['name']:6}{t['selected_model']:24}{mis:>10}"
                     f"{_v(t['rms_paper_model']):10.2f}{_v(t['rms_selected']):12.2f}")
    for cmp in rt["comparisons"]:
        if cmp["model"] in ("paper", rt["study_model"]):
            a_, b_ = cmp["groups"]
            lines.append(f"  eps0({b_}) - eps0({a_}) under {cmp['model']}: "
                         f"{_v(cmp['difference']):+.3f} ± {_v(cmp['uncertainty']):.3f} rad/s² "
                         f"(z {_v(cmp['z']):+.1f})")
    rest = [_v(t["rms_paper_model"]) for t in rt["tests"]]
    chosen = [_v(t["rms_selected"]) for t in rt["tests"]]
    q_frames = _v(rt["quantisation_sigma"]) * _v(rt["fps"])
    para(f"The paper's model (constant acceleration from rest at the first mark) misses the "
         f"frame indices by {min(rest):.1f}-{max(rest):.1f} frames rms, the chosen models by "
         f"{min(chosen):.2f}-{max(chosen):.2f}, against a reading quantisation of "
         f"{q_frames:.2f} frame. 'surfmet rotor paper2022' prints the full analysis.", "  ")

    head("Files")
    out = summary.get("out_dir", ".")
    for name in summary.get("figures", {}).values():
        lines.append(f"  {Path(out) / name}")
    lines.append(f"  {Path(out) / SUMMARY}")
    total = summary.get("total_time")
    if total:
        lines.append(f"  (total {_v(total):.0f} s)")
    return "\n".join(lines)
