"""The text of a ``surfmet rolling-contact`` record, elastic or viscoelastic: one printer,
one layout, one name per quantity (the record's keys)."""

from __future__ import annotations

from surfmet.cli._common import log, print_solve

#: The quantities of a rolling-contact record, in the order the text prints them (the
#: elastic and the viscoelastic records share the names; each prints those it has).
SUMMARY_KEYS = ("creepage", "fx", "fy", "pmax", "approach", "contact_area", "stick_area",
                "slip_area", "frictional_power", "frictional_power_at_speed",
                "rolling_resistance_coefficient", "pressure_moment_coefficient",
                "pressure_offset", "leading_edge", "trailing_edge")


def print_summary(rec: dict) -> None:
    """The text of a rolling-contact record, elastic
    (:func:`surfmet.records._rolling_contact.rolling_contact_record`) or viscoelastic
    (:func:`surfmet.records._rolling_contact.visco_rolling_contact_record`):
    one layout, one name per quantity."""
    from surfmet.units import format_quantity

    def fmt(key: str) -> str:
        return format_quantity(rec[key]["value"], rec[key]["unit"], digits=5)

    visco = str(rec.get("model", "")).startswith("viscoelastic")
    print(f"{'viscoelastic ' if visco else ''}rolling contact ({rec['geometry']}, "
          f"{'free rolling' if rec['free_rolling'] else 'prescribed creepage'}"
          + (f", {fmt('speed')})" if visco else ")"))
    tangential = rec.get("tangential")
    if tangential is not None and not tangential["solved"]:
        status = ("not solved (see the note)" if rec.get("mu") is not None
                  else tangential["status"])
        print(f"  {'creepage, fx, stick, slip':32s} {status}")
    for key in SUMMARY_KEYS:
        if key in rec:
            print(f"  {key:32s} {fmt(key)}")
    print_solve(rec["solve"], f"  {'solver':32s}")
    if "traction_solve" in rec:
        print_solve(rec["traction_solve"], f"  {'traction_solver':32s}")
    g = rec["grid"]
    shape = (f"{g['elements']} elements" if rec["geometry"].startswith("cylinder")
             else f"{g['elements']} x {g['elements']} elements")
    print(f"  {'grid':32s} {shape} of "
          f"{format_quantity(g['element_size']['value'], 'm', digits=3)} over "
          f"{format_quantity(g['domain_side']['value'], 'm', digits=4)}")
    for note in rec.get("notes", []):
        print(f"  note: {note}")
    log(f"sign convention: {rec['sign_convention']}")
    if "rolling_resistance_definition" in rec:
        log(f"definitions: {rec['rolling_resistance_definition']}")
