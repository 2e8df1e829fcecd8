"""The stored unit table, exgen/data/unit_table.tsv, rewritten from pint and the bank:
`python -m exgen.check.unit_table`.

Reading a printed or typed quantity looks its unit up in that table instead of building pint's registry
(~0.3 s); the table holds pint's own answer for every unit the bank's templates write, and for those
students commonly type. tests/test_units.py fails, naming this command, when a template writes one it lacks.
"""
from __future__ import annotations

from pathlib import Path

from .. import units
from ..answertypes.quantity import unit_families
from ..solve.variant import make_variant

#: Units stored beside those the bank's templates use: what students commonly type.
COMMON_UNITS = ("N", "kN", "MN", "N*m", "kN*m", "Nm", "W", "kW", "MW", "J", "kJ", "m", "mm", "cm", "km", "s",
                "min", "h", "kg", "g", "t", "rpm", "rev/min", "rad/s", "rad/s^2", "Hz", "deg", "rad", "m/s",
                "m/s^2", "km/h", "Pa", "kPa", "MPa", "GPa", "N/m", "kN/m", "N/mm", "kg*m^2", "kg*m", "%")


def bank_units(bank) -> set[str]:
    """Every unit a bank's templates write: parameters, parts, reported quantities, and the steps and
    table columns of a variant of each (the units their worked solutions are in)."""
    found = set(COMMON_UNITS) | set(units.SI_UNITS.values())
    found |= {unit for family in unit_families() for unit in family}  # a value is read in any of its kind
    for template in bank:
        found |= {p.unit for p in template.params} | {p.unit for p in template.parts}
        found |= {r.unit for r in template.report}
        variant = make_variant(template, 1)
        found |= {u for s in variant.steps for u in (s.unit, s.shown) if isinstance(u, str)}  # worked in, shown in
        found |= {c.unit for table in variant.inserts for c in getattr(table, "columns", ())}
    return found


if __name__ == "__main__":
    from ..load.bank import load_bank

    units._unit_table_rows = dict  # ask pint for everything, the stored table unread
    Path(units.__file__).parent.joinpath(units.UNIT_TABLE).write_text(units.unit_table(bank_units(load_bank())),
                                                                       encoding="utf-8")
