"""The ROSS adapter (bearing_mbs/io/ross.py), run where ROSS installs (``pip install -e '.[ross]'``; skipped
elsewhere).

A rigid 100 kg rotor on two plain bearings of the rotor scenarios (50 mm × 25 mm, C = 50 µm, 0.01 Pa s), each
carrying half its weight: ``bearing-mbs journal`` gives the eight coefficients over speed at the equilibrium (Reynolds
solves), the adapter hands them to ROSS, and ROSS's rotor (a short, very stiff, nearly massless shaft with the mass
as a disk in the middle, a bearing at each end) must find the modes of our own linearised rotor, M ẍ + C ẋ + K x = 0
with K, C the two bearings' (models/rotor/linear.py's equation): damped natural frequencies within 0.5 % and
logarithmic decrements within 2 % (ROSS's log_dec = 2πζ/√(1 − ζ²) = −2π Re λ / Im λ): at 6000 rpm 428.5 rad/s and
1.863 against our 428.5 and 1.866. ROSS solves a 36-degree-of-freedom beam model, ours 2 degrees: the shaft's bending
(its stiffness 10³ times the films') separates them, and ROSS's rotor also tilts (its conical modes, which the planar
model leaves out, are not compared; our overdamped, real eigenvalues have no frequency to compare). Exchanging k_xy
and k_yx moves our mode to 405 rad/s: the test holds only if ROSS reads the coefficients as we mean them.
"""

from __future__ import annotations

import json
import math
import warnings

import numpy as np
import pytest

from bearing_mbs.cli import main

from no_traceback import toml_document

ross = pytest.importorskip("ross")

MASS, GRAVITY = 100.0, 9.81
SPEEDS_RPM = [3000.0, 6000.0, 9000.0]
ID = 1e-3


@pytest.fixture(scope="module")
def coefficients(tmp_path_factory):
    scenario = {"scenario": {"name": "rotor_bearing", "model": "journal_bearing", "end_time": 1.0},
                "journal": {"diameter": 0.05, "length": 0.025, "radial_clearance": 50e-6, "viscosity": 0.01,
                            "speed_rpm": 6000.0, "eccentricity_ratio": 0.4, "grid": [120, 30],
                            "coefficient_speeds_rpm": SPEEDS_RPM, "static_load": [0.0, -MASS * GRAVITY / 2]}}
    folder = tmp_path_factory.mktemp("ross")
    (folder / "bearing.toml").write_text(toml_document(scenario))
    main(["journal", str(folder / "bearing.toml"), "--out", str(folder / "out"), "--no-figures"])
    return folder / "out" / "summary.json"


def _ross_rotor(summary):
    from bearing_mbs.io.ross import bearing_element_from_summary

    steel = ross.Material(name="stiff_light", rho=1.0, E=2.1e11, Poisson=0.3)
    shaft = [ross.ShaftElement(L=0.25, idl=0.0, odl=0.3, material=steel, n=k) for k in range(2)]
    disk = ross.DiskElement(n=1, m=MASS, Id=ID, Ip=2 * ID)
    bearings = [bearing_element_from_summary(summary, node, tag=f"bearing {node}") for node in (0, 2)]
    return ross.Rotor(shaft, [disk], bearings)


@pytest.mark.parametrize("rpm", [3000.0, 6000.0])
def test_ross_finds_the_modes_of_our_linearised_rotor(coefficients, rpm):
    row = next(r for r in json.loads(coefficients.read_text())["coefficients_over_speed"] if r["speed_rpm"] == rpm)
    stiffness, damping = 2 * np.array(row["stiffness"]), 2 * np.array(row["damping"])
    system = np.block([[np.zeros((2, 2)), np.eye(2)], [-stiffness / MASS, -damping / MASS]])
    ours = [value for value in np.linalg.eigvals(system) if value.imag > 0]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        modal = _ross_rotor(coefficients).run_modal(speed=rpm * math.pi / 30, num_modes=12)
    for value in ours:
        frequency, decrement = value.imag, -2 * math.pi * value.real / value.imag
        k = int(np.argmin(np.abs(modal.wd - frequency)))
        assert modal.wd[k] == pytest.approx(frequency, rel=0.005)
        assert modal.log_dec[k] == pytest.approx(decrement, rel=0.02, abs=0.02)


def test_a_speed_without_coefficients_is_refused():
    from bearing_mbs.io.ross import bearing_element

    rows = [{"speed_rpm": 100.0, "eccentricity": None, "stiffness": None, "damping": None}]
    with pytest.raises(ValueError):
        bearing_element(rows, 0)
