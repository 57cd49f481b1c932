"""JSON records of results, in one place, shared by the CLI, the demo, the report and sweep.

This package is the only place that builds JSON quantities: engines (:mod:`contact`,
:mod:`profiles`) return dataclasses, facades (:mod:`surfmet.mechanics`, :mod:`surfmet.roughness`)
return results, and the commands print the records built here from them
(``tests/test_records_only.py`` counts every ``quantity(...)`` and ``{"value", "unit"}``
elsewhere: none, but a scan's metadata in :mod:`surfmet.io`).

One direction between the records and the facades: ``surfmet.records`` may import
``surfmet.mechanics`` (its results' constants, its text helpers) and reads its results by
their attributes; surfmet.mechanics never imports surfmet.records, not even inside a
function (the same test checks it).

Every dimensional value is ``{"value": v, "unit": "..."}`` (dimensionless ratios with
``"unit": ""``); counts and flags are plain JSON numbers and booleans. One module per kind
of result: :mod:`~surfmet.records._scans` (scans, their calibration and form fits),
:mod:`~surfmet.records._preparation` (what was done to the scans),
:mod:`~surfmet.records._roughness` and :mod:`~surfmet.records._form` (a roughness
evaluation and its form removal), :mod:`~surfmet.records._solve` (a solve's
:class:`contact._record.SolveRecord`), :mod:`~surfmet.records._contact` (a ball-on-plate
contact solve), :mod:`~surfmet.records._hertz` and :mod:`~surfmet.records._hertz_adhesion`
(the Hertz check), :mod:`~surfmet.records._rolling`,
:mod:`~surfmet.records._rolling_mechanisms`, :mod:`~surfmet.records._rolling_contact`,
:mod:`~surfmet.records._adhesion`, :mod:`~surfmet.records._flat` (flat rough contact),
:mod:`~surfmet.records._spectrum`, :mod:`~surfmet.records._scales` (scale-dependent
statistics of several measurements), :mod:`~surfmet.records._all_scales` (their averaged
PSD for Persson's theory), :mod:`~surfmet.records._resolution` (resolution studies),
:mod:`~surfmet.records._sweep` (a sweep's rows), :mod:`~surfmet.records._inputs` (a
command's inputs) and :mod:`~surfmet.records._demo`, :mod:`~surfmet.records._demo_rotor`
(the demo's steps).
"""

from surfmet.records._contact import (
    ball_contact_record,
    contact_record,
    grid_record,
    material_record,
)
from surfmet.records._flat import flat_contact_record
from surfmet.records._hertz import hertz_check_details, hertz_check_record
from surfmet.records._resolution import study_record
from surfmet.records._rolling import rolling_record, tracks_record
from surfmet.records._roughness import roughness_record
from surfmet.records._scans import fit_record, scan_record
from surfmet.records._spectrum import spectrum_record

__all__ = ["ball_contact_record", "contact_record", "fit_record", "flat_contact_record",
           "grid_record", "hertz_check_details", "hertz_check_record", "material_record",
           "rolling_record", "roughness_record", "scan_record", "spectrum_record",
           "study_record", "tracks_record"]
