"""Shared machinery of long runs of independent tasks: the resumable store, the executor, thread pinning, progress.

Generic: it knows tasks, records and fingerprints, not studies or sea states, and imports nothing
else of seafast (it sits beside :mod:`seafast.fourier` at the bottom of the layers). The parametric
studies (:mod:`seafast.studies`) and the Monte Carlo reference
(:mod:`seafast.analyses.seastate.monte_carlo`) both run on it.

* :mod:`seafast.parallel.store` - :class:`~seafast.parallel.store.RecordStore`, the resumable,
  kill-safe, append-only JSON-lines store of a run's finished tasks (a manifest with the run's
  fingerprint, one line per record), and :class:`~seafast.parallel.store.StoreLayout`, how a kind
  of record is laid out in it.
* :mod:`seafast.parallel.executor` - :func:`~seafast.parallel.executor.map_batches` over the
  serial, local-process and Dask back-ends (:class:`~seafast.parallel.executor.ExecutionOptions`),
  and the batch plan.
* :mod:`seafast.parallel.threads` - BLAS thread pinning: one thread for the small dense solves
  and in every worker, every core for the BEM.
* :mod:`seafast.parallel.progress` - the progress of a run on stderr (a bar on a terminal, else
  plain lines).
* :mod:`seafast.parallel.sharing` - :class:`~seafast.parallel.sharing.HelperPool`: one piece of
  a command's output work (``seafast run``'s figures) shared with forked helper processes.
* :mod:`seafast.parallel.errors` - :class:`~seafast.parallel.errors.ParallelError` and
  :class:`~seafast.parallel.errors.ForeignStoreError`.

The package exports nothing itself: import from the modules (the command line imports
:mod:`seafast.parallel.threads` before numpy loads, and must not pay for the executor's imports).
"""
