"""Studies: many simulations of one scenario (sensitivity runs in :mod:`.sensitivity`)."""
