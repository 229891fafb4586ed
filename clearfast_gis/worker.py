"""A worker process of :class:`clearfast_gis.parallel.ProcessChunks`.

``python -m clearfast_gis.worker`` reads a pickled ``(fn, items)`` from standard input and
writes the pickled ``fn(items)`` to standard output; an error exits non-zero (the parent then
computes the chunk itself).
"""

from __future__ import annotations

import pickle
import sys


def main() -> int:
    from clearfast_gis.allocator import keep_freed_memory

    keep_freed_memory()
    fn, items = pickle.load(sys.stdin.buffer)
    result = fn(items)
    sys.stdout.buffer.write(pickle.dumps(result, protocol=pickle.HIGHEST_PROTOCOL))
    sys.stdout.buffer.flush()
    return 0


if __name__ == "__main__":
    sys.exit(main())
