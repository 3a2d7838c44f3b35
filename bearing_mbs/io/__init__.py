"""Input and output: JSON and figure files."""
