"""The model's ``[scenario] model`` name: the name of its package. Its studies check a scenario against it."""

#: ``[scenario] model = "cylindrical_roller"`` selects this model.
MODEL_NAME = "cylindrical_roller"
