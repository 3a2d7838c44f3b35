"""Studies any model may run: many simulations of one scenario, each run from a ``bearing-mbs`` subcommand
(convergence, numerics report, stability; sensitivity on Dask in :mod:`.sensitivity`), sharing the plumbing of
:mod:`.common`. What is particular to a model (its norms, stability cases, settling check, steady balance) they
ask its record; a model's own studies live in its package, run through the services of :mod:`.services`."""
