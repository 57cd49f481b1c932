"""Benchmark: the Greenwood-Tripp rough sphere (target: milliseconds to ~0.1 s each).

Run ``python benchmarks/greenwood_tripp.py``. Times the solve at the paper's summit
parameters (from the bundled scans' spectra) at 10 N and at the rotor's ball loads,
elastic and capped at the aluminium's hardness, and over α = 0.01..4 for a generic
population; each time is the minimum of 5 repeats (shared machine: read them as noisy).
Also times the summit parameters of the bundled pair (PSDs of both scans).
"""

from __future__ import annotations

from importlib import resources

from _timing import min_time_and_result

from contact import composite_modulus, hertz_sphere, material
from contact.roughcontact._greenwood_tripp import Asperities, greenwood_tripp
from rotor import BALL_RADIUS, HERTZ_CHECK_LOAD, paper_ball_loads


def main() -> None:
    import surfmet
    from surfmet.mechanics.hertz_check import scan_summits
    from surfmet.mechanics.scan_preparation import prepare_scans

    data = resources.files("surfmet").joinpath("data")
    plate = surfmet.read(str(data / "paper_plate.x3p"))
    ball = surfmet.read(str(data / "paper_ball.x3p"))
    prep = prepare_scans(plate, ball)
    t, sp = min_time_and_result(lambda: scan_summits(prep), 3)
    print(f"summit parameters of the paper's pair (two PSDs): {1e3 * t:.1f} ms")
    steel, alu = material("steel"), material("aluminium")
    e_star = composite_modulus(steel, alu)
    kw = dict(asperities=Asperities.of(sp))
    for load in (HERTZ_CHECK_LOAD, *paper_ball_loads().values()):
        for hardness in (None, alu.hardness):
            t, sol = min_time_and_result(lambda load=load, hardness=hardness: greenwood_tripp(
                load, BALL_RADIUS, e_star, hardness=hardness, **kw))
            print(f"paper pair, W = {load:6.3f} N, {'capped' if hardness else 'elastic'}: "
                  f"{1e3 * t:6.1f} ms  (a*/a0 = {sol.a_star / sol.a0:.3f}, "
                  f"{sol.iterations} Newton steps, {sol.r.size} rings)")
    radius, load, e = 0.01, 2.0, 70e9
    hz = hertz_sphere(radius, load, e)
    for alpha in (0.01, 0.1, 1.0, 4.0):
        sig = alpha * hz.a**2 / radius
        beta = sig / 1e-3
        t, sol = min_time_and_result(lambda sig=sig, beta=beta: greenwood_tripp(
            load, radius, e, asperities=Asperities(sig, 0.05 / (beta * sig), beta)))
        print(f"generic population, α = {alpha:5.2f}: {1e3 * t:6.1f} ms "
              f"(a*/a0 = {sol.a_star / hz.a:.3f})")


if __name__ == "__main__":
    main()
