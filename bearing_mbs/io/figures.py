"""Figure files: figures are built with matplotlib's object-oriented API (:class:`matplotlib.figure.Figure`), so
drawing needs no screen, never selects a backend and never touches pyplot's global state."""

from __future__ import annotations

from pathlib import Path

#: Resolution of saved figures [dots per inch].
DPI = 120


def new_figure(rows: int = 1, columns: int = 1, *, figsize: tuple[float, float] | None = None, **options):
    """A new figure of ``figsize`` [inch] and its axes (``Figure.subplots(rows, columns, **options)``: one axes,
    or an array of them)."""
    from matplotlib.figure import Figure

    figure = Figure(figsize=figsize)
    return figure, figure.subplots(rows, columns, **options)


def save_figure(figure, path: str | Path, *, dpi: float = DPI, tight: bool = True) -> Path:
    """Save ``figure`` to ``path`` (format from the suffix, e.g. ``.png``), after ``tight_layout`` unless ``tight``
    is False. The parent directory is created; the file is written to ``path.part`` first and then replaces
    ``path``, so a crash never leaves a half-written figure. Returns the path."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    if tight:
        figure.tight_layout()
    temporary = path.with_name(path.name + ".part")
    figure.savefig(temporary, format=path.suffix.lstrip(".") or "png", dpi=dpi)
    temporary.replace(path)
    return path
