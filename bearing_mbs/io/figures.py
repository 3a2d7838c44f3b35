"""Figure files: figures are built with matplotlib's object-oriented API (:class:`matplotlib.figure.Figure`), so
drawing needs no screen, never selects a backend and never touches pyplot's global state."""

from __future__ import annotations

from pathlib import Path

#: Resolution of saved figures [dots per inch].
DPI = 120
#: The colour of a status note: a figure of a run that is not ``success`` must not pass for a valid result.
STATUS_COLOUR = "#b00020"
#: The height of the status band [fraction of the figure's height].
STATUS_BAND = 0.06


def new_figure(rows: int = 1, columns: int = 1, *, figsize: tuple[float, float] | None = None, **options):
    """A new figure of ``figsize`` [inch] and its axes (``Figure.subplots(rows, columns, **options)``: one axes,
    or an array of them)."""
    from matplotlib.figure import Figure

    figure = Figure(figsize=figsize)
    return figure, figure.subplots(rows, columns, **options)


def save_figure(figure, path: str | Path, *, dpi: float = DPI, tight: bool = True,
                status_note: str | None = None) -> Path:
    """Save ``figure`` to ``path`` (format from the suffix, e.g. ``.png``), after ``tight_layout`` unless ``tight``
    is False. The parent directory is created; the file is written to ``path.part`` first and then replaces
    ``path``, so a crash never leaves a half-written figure. ``status_note``: the status of a result that is not
    ``success`` (e.g. :attr:`bearing_mbs.core.result.Result.status_note`), stamped on the figure
    (:func:`stamp_status`). Returns the path."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    if tight:
        figure.tight_layout()
    if status_note:
        stamp_status(figure, status_note)
    temporary = path.with_name(path.name + ".part")
    figure.savefig(temporary, format=path.suffix.lstrip(".") or "png", dpi=dpi)
    temporary.replace(path)
    return path


def stamp_status(figure, note: str) -> None:
    """Write ``note`` (the status of the result drawn, first word the status) in a band across the top of
    ``figure`` and the status as a large translucent word across it, so that a figure of a suspect, failed or
    interrupted run is never read as a valid result. The axes move down to make room for the band."""
    status = note.split(":")[0].split()[0].upper()
    if figure.axes:  # the axes (and their titles) move down by the band's height
        figure.subplots_adjust(top=figure.subplotpars.top - STATUS_BAND)
    figure.text(0.5, 0.995, note, ha="center", va="top", color="white", fontsize=9, wrap=True,
                bbox={"facecolor": STATUS_COLOUR, "edgecolor": "none", "boxstyle": "square,pad=0.4"})
    figure.text(0.5, 0.5, status, ha="center", va="center", rotation=25, fontsize=64, fontweight="bold",
                color=STATUS_COLOUR, alpha=0.18)
