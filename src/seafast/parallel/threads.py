"""BLAS thread pinning: one thread for seafast's small dense solves, every core for the BEM.

seafast's dense solves are small (about 100 to 5000 unknowns): on few cores one BLAS thread is
fastest, and it leaves the cores to the worker processes of a study or a Monte Carlo run, which
parallelise across points instead. Three places set the thread count, each through this module:

* :func:`default_to_one_thread`, before numpy loads (the ``seafast`` command at import): the
  thread-count environment variables (:data:`THREAD_VARIABLES`) default to 1; a value the user
  set wins. OpenBLAS, MKL and OpenMP read them when they are loaded.
* :func:`one_blas_thread`, a context manager: the BLAS libraries loaded (numpy's and scipy's,
  loaded first so the limit reaches both) run one thread until it exits; the ``seafast`` command
  and the serial back-end of :mod:`seafast.parallel.executor` run inside it.
  :func:`blas_on_every_core` lifts the limit for a block that profits from every core (the
  BEM's dense complex solves).
* :func:`pin_worker_threads`, in each worker process (the executor's initialiser and every Dask
  task): the variables forced to 1 (libraries loaded later read them) and every thread pool
  already loaded, BLAS and OpenMP, limited to one thread for the rest of the process.

The thread count can change how BLAS splits a reduction, and so its round-off: one thread
everywhere keeps serial, worker-process and Dask results equal bit for bit. threadpoolctl is imported when
a limit is applied, never at import (the command line imports this module before numpy).
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from contextlib import contextmanager

__all__ = ["THREAD_VARIABLES", "default_to_one_thread", "one_blas_thread", "blas_on_every_core", "pin_worker_threads"]

THREAD_VARIABLES: tuple[str, ...] = ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS", "NUMEXPR_NUM_THREADS")
"""The environment variables that set the thread count of OpenBLAS, OpenMP, MKL and numexpr."""


def default_to_one_thread() -> None:
    """Default every variable of :data:`THREAD_VARIABLES` to ``1`` (a value already set wins).

    Call it before numpy and scipy load: the libraries read the variables when they are loaded.
    """
    for name in THREAD_VARIABLES:
        os.environ.setdefault(name, "1")


@contextmanager
def _blas_threads(count: int) -> Iterator[None]:
    import scipy.linalg  # noqa: F401 - load scipy's BLAS (and numpy's) now, so the limit reaches both
    from threadpoolctl import threadpool_limits

    with threadpool_limits(limits=count, user_api="blas"):
        yield


@contextmanager
def one_blas_thread() -> Iterator[None]:
    """Run the block with one BLAS thread (numpy's and scipy's BLAS); the previous counts return after it.

    OpenMP thread pools are left to ``OMP_NUM_THREADS`` (:func:`default_to_one_thread`); seafast's
    own kernels use none.
    """
    with _blas_threads(1):
        yield


@contextmanager
def blas_on_every_core() -> Iterator[None]:
    """Run the block with one BLAS thread per core (``os.cpu_count()``), whatever limit is in force around it."""
    with _blas_threads(os.cpu_count() or 1):
        yield


def pin_worker_threads() -> None:
    """Pin this worker process to one thread: the variables forced to ``1``, every loaded thread pool limited to one.

    For the rest of the process (not a context: a worker does nothing else). Libraries loaded
    later read the variables. Pinning is an optimisation: a library threadpoolctl cannot inspect
    does not stop the worker.
    """
    for name in THREAD_VARIABLES:
        os.environ[name] = "1"
    try:
        from threadpoolctl import threadpool_limits

        threadpool_limits(limits=1)
    except Exception:  # noqa: BLE001  # pragma: no cover - see the docstring
        pass
