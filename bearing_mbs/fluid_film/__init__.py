"""Fluid-film journal bearings: a library any model can call (pure functions and small records, SI units).

* :mod:`.journal` — the bearing's geometry, its recesses and the (θ, z) finite-volume grid of the unwrapped film.
* :mod:`.restrictors` — capillary, orifice, constant-flow and direct (uncompensated) supply of a recess.
* :mod:`.reynolds` — the conservative finite-volume Reynolds solver: Couette and squeeze terms, lumped recesses,
  Gümbel or mass-conserving (JFO) cavitation; load, flow, friction and recess pressures.
* :mod:`.closed_forms` — the short (Ocvirk) and long (Sommerfeld, Gümbel condition) bearing.
* :mod:`.cylinder_plane` — the rigid, isoviscous film of a cylinder on a plane, wedge and squeeze together (a
  roller on a cage's pocket wall).
* :mod:`.coefficients` — static stiffness and the eight dynamic coefficients by perturbation.
* :mod:`.network` — document 001's pocket-pressure resistance network (eq. 11.2, errata corrected), a fast
  approximation of the recess pressures.

Nothing here imports an engine or a model.
"""
