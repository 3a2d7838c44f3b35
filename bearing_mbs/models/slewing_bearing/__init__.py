"""The ``slewing_bearing`` model (document 002): four-point-contact ball slewing bearings of wind turbines with
flexible rings. So far: the condensed ring-stiffness parametrisation (:mod:`.ring_stiffness`); the load
distribution, its command and scenarios are to come."""
