"""Input and output: JSON and figure files (written atomically; no other ``bearing_mbs`` layer is imported)."""
