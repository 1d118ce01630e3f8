"""`OraclePool`: several oracle processes for surveys of many cases.

The oracle answers one request at a time, so a survey of millions of cases is spread over
processes: the pool keeps `size` of them, each `Oracle` used by one thread at a time (the
threads only move JSON; the work is in the processes).
"""

import os
import queue
from concurrent.futures import ThreadPoolExecutor

from .errors import OracleInputError
from .oracle import DEFAULT_TIMEOUT, Oracle


class OraclePool:
    """`size` running oracles (default: one per CPU).

        with OraclePool(4) as pool:
            answers = pool.requests(reqs)                       # in order, chunks in parallel
            verdicts = pool.map(lambda o, c: o.within_bound(*c), cases)

    Every `Oracle` keeps its own ids, timeout and restarts; an error in any task is raised
    (the first one, in order) after the tasks already running have finished.
    """

    def __init__(self, size=None, binary=None, args=(), timeout=DEFAULT_TIMEOUT, arrays=None):
        size = (os.cpu_count() or 1) if size is None else size
        if not isinstance(size, int) or isinstance(size, bool) or size < 1:
            raise OracleInputError(f"a pool has at least one oracle, not {size!r}")
        self.size = size
        self.oracles = []
        try:
            for _ in range(size):
                self.oracles.append(Oracle(binary, args, timeout=timeout, arrays=arrays))
        except BaseException:
            self.close()
            raise
        self._idle = queue.SimpleQueue()
        for o in self.oracles:
            self._idle.put(o)
        self._executor = ThreadPoolExecutor(max_workers=size, thread_name_prefix="casteljau-oracle")

    def _with_oracle(self, fn, item):
        o = self._idle.get()
        try:
            return fn(o, item)
        finally:
            self._idle.put(o)

    def map(self, fn, items):
        """[fn(oracle, item) for item in items], each call on one of the pool's oracles, in
        parallel; the results in the order of `items`."""
        futures = [self._executor.submit(self._with_oracle, fn, item) for item in items]
        try:
            return [f.result() for f in futures]
        except BaseException:
            for f in futures:
                f.cancel()
            raise

    def requests(self, reqs, check=True, chunk=512):
        """`Oracle.requests` over the pool: the requests in chunks of `chunk`, each chunk
        pipelined through one oracle; the answers in order."""
        if not isinstance(chunk, int) or chunk < 1:
            raise OracleInputError(f"chunk must be a positive int, not {chunk!r}")
        reqs = list(reqs)
        chunks = [reqs[i : i + chunk] for i in range(0, len(reqs), chunk)]
        return [a for part in self.map(lambda o, c: o.requests(c, check=check), chunks) for a in part]

    def close(self):
        """Ends every oracle of the pool."""
        executor = getattr(self, "_executor", None)
        if executor is not None:
            executor.shutdown(wait=True, cancel_futures=True)
        for o in self.oracles:
            o.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
