"""Tamaas' Polonsky-Keer iteration counts on the periodic case of ``core_scaling.py``.

Run in a separate virtualenv that has Tamaas (never imported by surfmet or its tests)::

    python3 -c "import sys, numpy as np; sys.path.insert(0, 'benchmarks');
    from core_scaling import periodic_case; g = periodic_case(512)[0];
    np.save('z512.npy', g.max() - g)"
    /path/to/venv/bin/python benchmarks/peer_tamaas_iterations.py z512.npy

``HEIGHTS.npy`` holds the surface heights (m) of ``core_scaling.periodic_case(n)``
(``z = gap.max() - gap``), written by surfmet's environment; the pixel is 1 um, E* 1 Pa
(E 1 Pa, nu 0), the mean pressure 0.005 E*, Tamaas' own tolerance 1e-8 on its own error
(Polonsky & Keer 1999, Wear 231:206; no preconditioner, no coarse start). Tamaas logs the
final iteration at info level.
"""

import sys
import time

import numpy as np


def main(path: str) -> None:
    import tamaas as tm

    tm.set_log_level(tm.LogLevel.info)
    z = np.load(path)
    n = z.shape[0]
    pixel = 1e-6
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [n * pixel] * 2, [n, n])
    model.E, model.nu = 1.0, 0.0
    solver = tm.PolonskyKeerRey(model, z, 1e-8)
    solver.max_iter = 100000
    t0 = time.perf_counter()
    solver.solve(0.005)
    p = np.asarray(model.traction)
    print(f"N {n} seconds {time.perf_counter() - t0:.2f} area {np.mean(p > 0):.4f}")


if __name__ == "__main__":
    main(sys.argv[1])
