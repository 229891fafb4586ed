"""The calibrated frames' reused memory (mosaic.buffers)."""

import threading

import numpy as np

from clearfast_gis.mosaic.buffers import BufferPool


def test_a_released_block_is_given_again_by_shape_and_dtype():
    pool = BufferPool()
    first = pool.lease()
    a = first.empty((4, 3, 5, 6), np.float32)
    b = first.empty((2, 3, 5, 6), np.float32)
    second = pool.lease()
    assert second.empty((4, 3, 5, 6), np.float32) is not a  # not released yet
    first.release()
    third = pool.lease()
    assert third.empty((2, 3, 5, 6), np.float32) is b
    assert third.empty((4, 3, 5, 6), np.float32) is a
    assert third.empty((4, 3, 5, 6), np.float64).dtype == np.float64  # other dtype: new
    assert third.empty((4, 3, 5, 6), np.float32) is not a  # each block once


def test_leases_on_threads_take_distinct_blocks():
    pool = BufferPool()
    warm = pool.lease()
    blocks = [warm.empty((8, 8)) for _ in range(16)]
    warm.release()
    lease = pool.lease()
    got: list = []

    def take() -> None:
        for _ in range(4):
            got.append(lease.empty((8, 8)))

    threads = [threading.Thread(target=take) for _ in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert len({id(a) for a in got}) == 16
    assert {id(a) for a in got} == {id(a) for a in blocks}
    pool.clear()
    assert pool.lease().empty((8, 8)) is not got[0]
