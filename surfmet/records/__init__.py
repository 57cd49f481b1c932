"""JSON records of results, in one place, shared by the CLI, the demo, the report and sweep.

Every dimensional value is ``{"value": v, "unit": "..."}`` (dimensionless ratios with
``"unit": ""``); counts and flags are plain JSON numbers and booleans. One module per kind
of result: :mod:`~surfmet.records.scans` (scans and form fits),
:mod:`~surfmet.records.contact` (a ball-on-plate contact solve),
:mod:`~surfmet.records.hertz` (the Hertz check), :mod:`~surfmet.records.rolling`,
:mod:`~surfmet.records.flat` (flat rough contact), :mod:`~surfmet.records.spectrum`,
:mod:`~surfmet.records.scales` (scale-dependent statistics of several measurements),
:mod:`~surfmet.records.all_scales` (their averaged PSD for Persson's theory) and
:mod:`~surfmet.records.resolution` (resolution studies).
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
