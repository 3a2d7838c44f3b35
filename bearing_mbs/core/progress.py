"""Injectable progress meters: silent in the library, a tqdm bar in the command line."""

from __future__ import annotations


class ProgressMeter:
    """Receives simulated time; the default does nothing."""

    def start(self, total: float, description: str = "") -> None:
        pass

    def update(self, value: float) -> None:
        pass

    def close(self) -> None:
        pass


class TqdmProgress(ProgressMeter):
    """A tqdm bar over simulated time, with an estimated time of arrival."""

    def start(self, total: float, description: str = "") -> None:
        from tqdm import tqdm

        self._bar = tqdm(total=total, desc=description, unit="s(sim)", unit_scale=True, leave=False)
        self._value = 0.0

    def update(self, value: float) -> None:
        self._bar.update(value - self._value)
        self._value = value

    def close(self) -> None:
        self._bar.close()
