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
3. the Hertz check at the paper's 10 N (:func:`surfmet.mechanics.hertz_check.hertz_check`): verdict
   and reasons;
4. a contact solve at the rotor's load per ball (elastic-perfectly-plastic, on the same
   paired roughness);
5. a short rolling-resistance sweep
   (:func:`surfmet.mechanics.rolling_resistance.rolling_resistance`);
6. the law-of-motion analysis of Table 3 (:func:`rotor.analyse_table`) on
   ``surfmet/data/table3_frames.tsv``, the paper's table re-typed and split
   (:mod:`rotor._frames`), with the paper's parabolas reproduced.

Figures and ``summary.json`` (every dimensional value ``{"value": v, "unit": "..."}``)
go to the output folder; :func:`story` turns the summary into the text ``surfmet demo``
prints.

Modules: :mod:`~surfmet.demo._outputs` (the output folder and ``summary.json``),
:mod:`~surfmet.demo._settings` (the settings and Table 2; the paper's rotor facts are
:mod:`rotor._paper`),
:mod:`~surfmet.demo._surfaces`, :mod:`~surfmet.demo._mechanics` and
:mod:`~surfmet.demo._lawofmotion` (the steps), :mod:`~surfmet.demo._figures`,
:mod:`~surfmet.demo._run` (the steps in order) and :mod:`~surfmet.demo._story` (the text).
"""

from surfmet.demo._outputs import FIGURES, GENERATOR, SUMMARY, data_file, prepare_output
from surfmet.demo._run import run_demo
from surfmet.demo._story import story

__all__ = ["FIGURES", "GENERATOR", "SUMMARY", "data_file", "prepare_output", "run_demo",
           "story"]
