"""Studies: many simulations of one scenario, each run from a ``bearing-mbs`` subcommand (convergence, numerics
report, stability, static check, skidding, cage models; sensitivity on Dask in :mod:`.sensitivity`), sharing the
plumbing of :mod:`.common`."""
