"""Power of the rotor adequacy check against short plate waves (0.3-0.6 revolutions) at
240 fps, 45 deg marks, 40 rows, at amplitudes above those of ``benchmarks/rotor_adequacy.py``
(issue 17): the 90 % threshold of that band was not established there.

Columns from :func:`rotor.simulate_random_run` (the generator the hidden-
effect test of ``tests/test_rotor_adequacy.py`` draws from), alternately without effect and
with a decay, no misread rows, the wave amplitude a fixed fraction of eps0 and its period
uniform in the band. Prints, per amplitude, the columns flagged inadequate or named a wave,
those named a wave, and those given the smooth term. Numbers in ``docs/rotor_adequacy.md``.

Run: ``PYTHONPATH=. python3 benchmarks/rotor_short_waves.py [columns] [first_seed] [sizes...]``
(default 20 columns from seed 60000 at 0.35 and 0.5 eps0).
"""

from __future__ import annotations

import math
import sys
import time

from rotor import analyse_test, simulate_random_run


def main(argv: list[str]) -> None:
    n = int(argv[0]) if argv else 20
    first = int(argv[1]) if len(argv) > 1 else 60000
    sizes = [float(a) for a in argv[2:]] or [0.35, 0.5]
    for size in sizes:
        flag = named = smooth = 0
        t0 = time.process_time()
        for i in range(n):
            run = simulate_random_run(first + i, "none" if i % 2 == 0 else "decaying",
                                      n_marks=40, fps=240.0, step=math.pi / 4, n_misread=0,
                                      wave_fraction=(size, size), wave_period_rev=(0.3, 0.6))
            rep = analyse_test("w", run.frames, run.k, fps=run.fps, step=run.step)
            wave = "wave" in rep.effect
            flag += wave or not rep.adequacy.adequate
            named += wave
            smooth += rep.smooth is not None
        print(f"B/eps0 {size:g}: {n} columns, flagged or named {flag}, named a wave {named}, "
              f"smooth term {smooth} ({time.process_time() - t0:.0f} s CPU)")


if __name__ == "__main__":
    main(sys.argv[1:])
