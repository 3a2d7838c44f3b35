"""The bearing's measured work–precision tables (``work_precision.json`` next to this module), from which
``[solver] tolerance`` chooses a run's method and step (:mod:`bearing_mbs.numerics.work_precision`).

``benchmarks/bench_revolution.py`` measures one revolution of seed_hss_steady's variants with every engine's
settings and writes the file (never edited by hand). A scene takes the table of the variant whose physics sets its
numerics: the raceways' friction law (EHL traction, or a regularised Coulomb law), the cage model (the
constraint cage's projections, or the penalty cage's pocket contacts) and, lubricated, whether the bearing has a
diametral clearance (its rollers then rattle in it and the ring falls through it onto them: steps that are sound
at zero clearance are not there). Another bearing of the same physics takes
the seed bearing's table: its error is expected, not measured (``bearing-mbs convergence`` measures it).
"""

from __future__ import annotations

from pathlib import Path

from bearing_mbs.contact.friction import FRICTION_LAWS
from bearing_mbs.models.protocol import WorkPrecisionData

#: The tables' file.
TABLES = Path(__file__).with_name("work_precision.json")

LUBRICATED, DRY, LUBRICATED_CLEARANCE = "lubricated", "dry", "lubricated_operating_clearance"
#: The friction law of lubricated raceways; the dry ones' are the regularised Coulomb laws.
EHL = "ehl"
COULOMB_LAWS = tuple(law for law in FRICTION_LAWS if law not in (EHL, "none"))
#: A diametral clearance up to this [m] (or a preload) counts as none: well below the loaded rollers' contact
#: deflections (10-20 µm at the seed bearing's load).
NO_CLEARANCE = 1e-6
#: The cage model of each variant.
CAGES = {LUBRICATED: "constraint", DRY: "penalty"}
VARIANTS = {
    LUBRICATED: "EHL traction on both raceways, constraint cage, zero diametral clearance (seed_hss_steady's "
                "lubricated variant at the document's clearance)",
    LUBRICATED_CLEARANCE: "EHL traction on both raceways, constraint cage, a diametral clearance (seed_hss_steady's "
                          "lubricated variant at its operating clearance, 69.5 µm)",
    DRY: "a regularised Coulomb friction law on both raceways, penalty cage (seed_hss_steady's dry variant)",
}


def variant(spec) -> str | None:
    """The table that describes ``spec``'s scene (:data:`VARIANTS`), None where none does."""
    laws = {spec.contact.inner_race.friction_law, spec.contact.outer_race.friction_law}
    if laws == {EHL} and spec.cage.model == CAGES[LUBRICATED]:
        return LUBRICATED if spec.bearing.clearance <= NO_CLEARANCE else LUBRICATED_CLEARANCE
    if laws <= set(COULOMB_LAWS) and spec.cage.model == CAGES[DRY]:
        return DRY
    return None


WORK_PRECISION = WorkPrecisionData(path=TABLES, variant=variant, variants=VARIANTS)
