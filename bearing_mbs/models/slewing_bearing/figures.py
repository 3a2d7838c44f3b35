"""The slewing command's figures: ball loads and contact angles around the ring, and the axial load–deflection
curve beside the rigid rings, the ADM group's engineering formula and, for the document's bearing, its
finite-element curve. Every legend says what its curve is."""

from __future__ import annotations

import math

import numpy as np

from bearing_mbs.io.figures import new_figure, save_figure
from bearing_mbs.models.slewing_bearing.spec import SlewingSpec

#: The balls' diagonals d = +1, −1, for legends.
DIAGONALS = ("inner ring's upper centre to outer ring's lower", "inner ring's lower centre to outer ring's upper")


def engineering_deflection(axial_load: float, pitch_diameter: float) -> float:
    """Document 002's engineering formula (3), δ = [F_a/(3300 D_pw^0.35)]^1.6 with F_a in kN, D_pw in mm and δ in
    mm (the units are the digest's inference from magnitudes); here in N, m → m."""
    return (axial_load / 1e3 / (3300.0 * (pitch_diameter * 1e3) ** 0.35)) ** 1.6 * 1e-3


def rings_label(spec: SlewingSpec) -> str:
    """What the scenario's rings are, for a legend."""
    s = spec.slewing
    if s.rings == "rigid":
        return "rigid rings"
    mount = "bolted faces clamped" if s.mount == "fixed" else "free rings, nothing clamped"
    coupling = "shared ring deformation" if s.coupling == "structural" else "whole sector matrices in series"
    return f"flexible rings ({mount}; {coupling})"


def plot_ball_loads(spec, summary, path, note=None):
    figure, (loads, angles) = new_figure(2, 1, figsize=(8, 7.5), sharex=True)
    azimuth = np.array(summary["azimuths"])
    shown = [(summary["ball_loads"], summary["contact_angles"], rings_label(spec), "-")]
    if "rigid_ball_loads" in summary:
        shown.append((summary["rigid_ball_loads"], summary["rigid_contact_angles"], "rigid rings", ":"))
    for ball_loads, contact_angles, label, style in shown:
        ball_loads, contact_angles = np.array(ball_loads), np.array(contact_angles)
        for d, diagonal in enumerate(DIAGONALS):
            line, = loads.plot(azimuth, ball_loads[:, d] / 1e3, "." + style, label=f"{label}: {diagonal}")
            loaded = ball_loads[:, d] > 0
            angles.plot(azimuth[loaded], contact_angles[loaded, d], ".", color=line.get_color())
    loads.set_ylabel("ball load [kN]")
    angles.set_ylabel("contact angle [deg]")
    angles.set_xlabel("azimuth ψ [deg] (0 along +x)")
    figure.legend(*loads.get_legend_handles_labels(), loc="lower center", ncol=1, fontsize=7)
    radial, axial, tilt = summary["state_displacement"]
    load = spec.load
    where = f"δ_r = {radial * 1e3:.4g} mm, δ_a = {axial * 1e3:.4g} mm, θ = {tilt * 1e3:.4g} mrad"
    if "axial_curve" not in summary:
        where = (f"F_r = {load.radial / 1e3:.4g} kN, F_a = {load.axial / 1e3:.4g} kN, M = {load.moment / 1e3:.4g} kN m"
                 f"\n({spec.slewing.rings} rings at {where})")
    loads.set_title(f"{spec.scenario.name}: {azimuth.size} balls at {where}", fontsize=9)
    figure.tight_layout(rect=(0, 0.14, 1, 1))
    return save_figure(figure, path, status_note=note, tight=False)


def plot_axial_curve(spec, summary, path, note=None):
    displacement, force = np.array(summary["axial_curve"]).T
    figure, axis = new_figure(figsize=(8, 5.5))
    axis.plot(displacement * 1e3, force / 1e3, "o-", label=f"this model, {rings_label(spec)}")
    rigid_curve = summary.get("rigid_axial_curve")
    if rigid_curve is not None:
        axis.plot(*(np.array(rigid_curve).T * [[1e3], [1e-3]]), "s--", label="this model, rigid rings")
    base_displacement, base_force = (displacement, force) if rigid_curve is None else np.array(rigid_curve).T
    engineering = [engineering_deflection(f, spec.slewing.pitch_diameter) + d
                   for d, f in zip(base_displacement, base_force)]
    axis.plot(np.array(engineering) * 1e3, base_force / 1e3, "--",
              label="rigid rings + the ADM group's engineering formula for the rings' deflection "
                    "(with bolted joints)")
    if "finite_element_axial_curve" in summary:
        fe_displacement, fe_force = np.array(summary["finite_element_axial_curve"]).T
        axis.plot(fe_displacement * 1e3, fe_force / 1e3, "k^", label="finite-element model of a ball's sector, "
                                                                     "both rings clamped (Fernández Apezteguia 2019)")
    axis.set_xlabel("axial displacement of the inner ring against the outer ring [mm]")
    axis.set_ylabel("axial force [kN]")
    axis.grid(True, alpha=0.3)
    axis.legend(fontsize=7)
    axis.set_title(f"{spec.scenario.name}: D_pw = {spec.slewing.pitch_diameter:g} m, α₀ = "
                   f"{math.degrees(spec.contact_angle_rad):g}°")
    return save_figure(figure, path, status_note=note)
