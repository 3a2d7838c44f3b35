"""Invalidate numba's on-disk cache when any compiled source of the package changes.

numba keys a cached function on its own file only: after an edit to ``contact/normal.py`` a cached
``engines/reference/integrators.integrate`` would still hold the old law. :func:`invalidate_if_stale` hashes all
the sources that compiled code is made of (:data:`COMPILED_SOURCES`; keep numba code there); when the hash
differs from the one stored next to the cache, every ``*.nbi``/``*.nbc`` file of the package is removed and
numba recompiles.

It is called by the entry points, once per process and before any compiled code runs (the command line, the
test session, the benchmarks), never at import: a Dask worker or a library user's process does not delete
caches under another process's feet. A sweep's driver calls it before its workers start. It sits in ``core`` (it
imports nothing of the package), so every layer's entry point may call it; being in ``core/``, it is hashed with
the compiled sources, which costs one recompilation when it changes.
"""

from __future__ import annotations

import hashlib
from pathlib import Path

#: The package directory (this module is in ``core/``).
PACKAGE = Path(__file__).resolve().parents[1]
STAMP = PACKAGE / "__pycache__" / "numba_sources.sha256"
#: Globs (relative to the package) of every file whose code numba compiles or whose types it reads.
COMPILED_SOURCES = ("contact/*.py", "core/*.py", "elements/*.py", "engines/reference/*.py", "fluid_film/*.py")


def isolated_cache_dir(name: str) -> Path:
    """A numba cache directory of its own (for ``NUMBA_CACHE_DIR``), for code compiled on types from outside the
    package (a test's force element): the package's cache, which a process that cannot import those types reads
    (a Dask worker), stays free of them, and :func:`invalidate_if_stale` clears this one with it."""
    return PACKAGE / "__pycache__" / "isolated" / name


def sources_digest() -> str:
    digest = hashlib.sha256()
    for path in sorted(p for pattern in COMPILED_SOURCES for p in PACKAGE.glob(pattern)):
        digest.update(path.relative_to(PACKAGE).as_posix().encode())
        digest.update(path.read_bytes())
    return digest.hexdigest()


def invalidate_if_stale() -> None:
    try:
        current = sources_digest()
        if STAMP.exists() and STAMP.read_text() == current:
            return
        for cached in [*PACKAGE.rglob("*.nbi"), *PACKAGE.rglob("*.nbc")]:
            cached.unlink(missing_ok=True)
        STAMP.parent.mkdir(exist_ok=True)
        STAMP.write_text(current)
    except OSError:  # a read-only installation: numba falls back to its own behaviour
        pass
