"""The fast calibration kernel over a block of frames: each frame's values do not depend on
the block it was computed in (the chain's blocks follow its chunking and threads)."""

from __future__ import annotations

import numpy as np

from clearfast_gis.radiometry._kernels import apparent_frames
from clearfast_gis.radiometry.calibration import GainOffset
from clearfast_gis.radiometry.table import BandTable


def _inputs(n: int = 7, shape=(24, 40)):
    rng = np.random.default_rng(11)
    table = BandTable(8.0, 9.2)

    def calibration(level):
        gain = 2.0e-4 * rng.uniform(0.95, 1.05, shape)
        offset = np.full(shape, level)
        return GainOffset(gain, offset, np.ones(shape, dtype=bool))

    cals = [calibration(1.2), calibration(1.25), calibration(1.3)]
    raw = rng.integers(9000, 12000, size=(n, *shape)).astype(np.uint16)
    parts = [[(cals[k % 3], 1.0)] if k % 2 else
             [(cals[k % 3], 1 - k / n), (cals[(k + 1) % 3], k / n)] for k in range(n)]
    taus = [rng.uniform(0.9, 0.99, shape) if k % 3 else 0.95 for k in range(n)]
    t_air = rng.uniform(285.0, 300.0, n)
    return raw, parts, taus, t_air, table.radiance(t_air), table


def test_a_block_gives_each_frame_the_bits_it_gets_alone():
    raw, parts, taus, t_air, b_air, table = _inputs()
    block = np.empty(raw.shape, np.float32)
    apparent_frames(raw, parts, taus, t_air, b_air, table, block)
    for k in range(raw.shape[0]):
        alone = np.empty((1, *raw.shape[1:]), np.float32)
        apparent_frames(raw[k:k + 1], parts[k:k + 1], taus[k:k + 1], t_air[k:k + 1],
                        b_air[k:k + 1], table, alone)
        assert np.array_equal(alone[0], block[k], equal_nan=True)
    assert np.all(np.isfinite(block)) and 200.0 < np.median(block) < 350.0  # K


def test_a_zero_transmittance_gives_no_data_not_an_error():
    raw, parts, taus, t_air, b_air, table = _inputs(n=1)
    out = np.empty(raw.shape, np.float32)
    apparent_frames(raw, parts, [0.0], t_air, b_air, table, out)
    assert np.all(np.isnan(out))
