"""A registry of named plug-ins (models, force-element kinds): a read-only mapping from name to plug-in, in
registration order, that :meth:`Registry.register` extends from outside the package."""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping
from typing import Generic, TypeVar

Plugin = TypeVar("Plugin")


class Registry(Mapping, Generic[Plugin]):
    """Plug-ins by their ``name``. :meth:`clashes` says what else a subclass refuses to register twice."""

    def __init__(self, plugins: Iterable[Plugin] = ()):
        self._plugins: dict[str, Plugin] = {}
        for plugin in plugins:
            self.register(plugin)

    def clashes(self, plugin: Plugin, other: Plugin) -> bool:
        return other.name == plugin.name

    def register(self, plugin: Plugin) -> Plugin:
        for other in self._plugins.values():
            if other is not plugin and self.clashes(plugin, other):
                raise ValueError(f"{plugin.name!r} clashes with the registered {other.name!r}")
        self._plugins[plugin.name] = plugin
        return plugin

    def unregister(self, name: str) -> None:
        self._plugins.pop(name, None)

    def __getitem__(self, name: str) -> Plugin:
        return self._plugins[name]

    def __iter__(self) -> Iterator[str]:
        return iter(self._plugins)

    def __len__(self) -> int:
        return len(self._plugins)
