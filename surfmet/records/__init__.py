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
of result: :mod:`~surfmet.records.scans` (scans, their calibration and form fits),
:mod:`~surfmet.records.preparation` (what was done to the scans),
:mod:`~surfmet.records.roughness` and :mod:`~surfmet.records.form` (a roughness
evaluation and its form removal), :mod:`~surfmet.records.solve` (a solve's
:class:`contact.record.SolveRecord`), :mod:`~surfmet.records.contact` (a ball-on-plate
contact solve), :mod:`~surfmet.records.hertz` and :mod:`~surfmet.records.hertz_adhesion`
(the Hertz check), :mod:`~surfmet.records.rolling`,
:mod:`~surfmet.records.rolling_mechanisms`, :mod:`~surfmet.records.rolling_contact`,
:mod:`~surfmet.records.adhesion`, :mod:`~surfmet.records.flat` (flat rough contact),
:mod:`~surfmet.records.spectrum`, :mod:`~surfmet.records.scales` (scale-dependent
statistics of several measurements), :mod:`~surfmet.records.all_scales` (their averaged
PSD for Persson's theory), :mod:`~surfmet.records.resolution` (resolution studies),
:mod:`~surfmet.records.sweep` (a sweep's rows), :mod:`~surfmet.records.inputs` (a
command's inputs) and :mod:`~surfmet.records.demo`, :mod:`~surfmet.records.demo_rotor`
(the demo's steps).
"""

from surfmet.records.contact import contact_record, grid_record, material_record
from surfmet.records.flat import flat_contact_record
from surfmet.records.hertz import hertz_check_details, hertz_check_record
from surfmet.records.resolution import study_record
from surfmet.records.rolling import rolling_record, tracks_record
from surfmet.records.scans import fit_record, scan_record
from surfmet.records.spectrum import spectrum_record

__all__ = ["contact_record", "fit_record", "flat_contact_record", "grid_record",
           "hertz_check_details", "hertz_check_record", "material_record", "rolling_record",
           "scan_record", "spectrum_record", "study_record", "tracks_record"]
