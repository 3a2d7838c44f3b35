"""The reference engine: compiled (numba) explicit integrators, one step function per method.

Layout:

* :mod:`.engine` — the Python side: packs the scene, allocates the bundles, runs the driver in chunks and
  turns its status into a :class:`~bearing_mbs.core.failures.Failure` and a message;
* :mod:`.integrators` — the compiled driver :func:`~.integrators.integrate`: output instants, step choice,
  dispatch to the method's step function by method code, constraint projection, run guards, the pairs'
  state update once per accepted step, decimated output;
* one step function per method: :mod:`.central_difference`, :mod:`.velocity_verlet`, :mod:`.runge_kutta`
  (``rk4`` and ``dopri5``; ``dopri5`` adds the embedded error estimate and the step control);
* :mod:`.tableaus` — the Runge–Kutta methods as data (Butcher tableaus);
* :mod:`.bundles` — the state, controls, per-method carry, scratch and output as NamedTuples of arrays;
* :mod:`.codes` — method codes, status codes (equal to the ``Failure`` values) and counter slots;
* :mod:`.dynamics` — the accelerations a = M⁻¹f + g, the one place compiled code evaluates forces;
* :mod:`.constraints` — index-1 constraint accelerations and SHAKE/RATTLE projection.

Energy audit: the work supplied by loads and drives and the work dissipated by the contacts are integrated
with each method's own quadrature (the Runge–Kutta weights over the stages, the trapezoid rule for velocity
Verlet, the rectangle rule for the central difference), so the audit is as accurate as the motion.
"""
