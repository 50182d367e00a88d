"""What a sequence of structural models can share: the meshed cargo beams and the Rayleigh fits.

A study rebuilds the model at every point; along a stiffness axis the mesh and the beam matrices
do not change, and along a pretension axis not even the natural frequencies the damping is fitted
on. A :class:`ModelCache`, owned by whoever builds the models (a study's worker process keeps one
for its points), keeps both, keyed on everything they depend on: what it returns is what a fresh
build gives, to the bit. Pass it to :func:`~seafast.model.structure.build_structural_model`, or
share it with the code a block calls (``with cache.shared(): ...``). Without one, every build is
fresh.
"""

from __future__ import annotations

import threading
from collections import OrderedDict
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from typing import Any, Protocol, TypeVar

__all__ = ["ModelCache", "shared_model_cache"]

_Value = TypeVar("_Value")


class _Assembled(Protocol):
    """A cargo beam as the cache sees it: its dense matrices (their size bounds what is kept)."""

    @property
    def stiffness(self) -> Any: ...

    @property
    def mass(self) -> Any: ...


_Beam = TypeVar("_Beam", bound=_Assembled)


class ModelCache:
    """Cargo beams and Rayleigh fits of a sequence of models, each kept up to ``max_entries`` (the oldest goes first).

    Beams are also kept only while their dense matrices total at most ``max_beam_bytes`` (a
    2000-element beam holds 64 MB); the last one always stays.

    Parameters
    ----------
    max_entries
        Beams (and fits) kept [-], >= 1.
    max_beam_bytes
        Largest total size of the beams' dense stiffness and mass matrices [B], > 0.
    """

    def __init__(self, max_entries: int = 4, max_beam_bytes: int = 128 * 2**20) -> None:
        if max_entries < 1 or max_beam_bytes <= 0:
            raise ValueError(f"ModelCache: max_entries = {max_entries!r} (>= 1), max_beam_bytes = {max_beam_bytes!r} (> 0)")
        self.max_entries = int(max_entries)
        self.max_beam_bytes = int(max_beam_bytes)
        self._beams: OrderedDict[tuple, Any] = OrderedDict()
        self._fits: OrderedDict[tuple, Any] = OrderedDict()
        self._lock = threading.Lock()  # Dask runs batches on threads: the bookkeeping, not the computing, is serialised

    def beam(self, key: tuple, build: Callable[[], _Beam]) -> _Beam:
        """The beam kept for ``key``, or ``build()`` kept under it."""
        beam = self._get(self._beams, key, build)
        with self._lock:
            while len(self._beams) > 1 and sum(b.stiffness.nbytes + b.mass.nbytes for b in self._beams.values()) > self.max_beam_bytes:
                self._beams.popitem(last=False)
        return beam

    def rayleigh_fit(self, key: tuple, fit: Callable[[], _Value]) -> _Value:
        """The fit kept for ``key``, or ``fit()`` kept under it."""
        return self._get(self._fits, key, fit)

    def _get(self, store: OrderedDict[tuple, Any], key: tuple, make: Callable[[], _Value]) -> _Value:
        with self._lock:
            held: _Value | None = store.get(key)
            if held is not None:
                store.move_to_end(key)
                return held
        value = make()
        with self._lock:
            store[key] = value
            while len(store) > self.max_entries:
                store.popitem(last=False)
        return value

    def __len__(self) -> int:
        """Number of beams kept."""
        return len(self._beams)

    @contextmanager
    def shared(self) -> Iterator[ModelCache]:
        """Within the block (this thread or task), a model built without a cache uses this one."""
        token = _SHARED.set(self)
        try:
            yield self
        finally:
            _SHARED.reset(token)


_SHARED: ContextVar[ModelCache | None] = ContextVar("seafast_shared_model_cache", default=None)
"""The cache the innermost ``with cache.shared()`` block shares; None outside every such block."""


def shared_model_cache() -> ModelCache | None:
    """The :class:`ModelCache` the innermost ``with cache.shared()`` block around this call shares, or None."""
    return _SHARED.get()
