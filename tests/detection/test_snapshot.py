"""Snapshot mode, the detect-images command and real images from the Colombia data set."""

import csv
import glob
from pathlib import Path

import cv2
import numpy as np
import pytest
import tifffile
from click.testing import CliRunner

from clearfast_gis.cli.detect_images import COLUMNS, command
from clearfast_gis.detection import detect_snapshot
from clearfast_gis.detection.imageio import read_image
from clearfast_gis.detection.multiscale import detect_snapshot_multiscale
from clearfast_gis.errors import InvalidInput

COLOMBIA = Path(__file__).resolve().parents[1] / "data" / "colombia"


def _scene(rng):
    img = rng.normal(20.0, 0.05, (120, 160)).astype(np.float32)
    yy, xx = np.mgrid[:120, :160]
    img += 1.0 * (np.hypot(yy - 40.0, xx - 50.0) <= 6)  # warm disc
    img += 0.6 * (np.hypot(yy - 80.0, xx - 120.0) <= 4)  # weaker, smaller
    return img


def test_snapshot_finds_discs_ranked():
    dets = detect_snapshot(_scene(np.random.default_rng(0)), d1_px=25, d2_px=3, epsilon=0.002)
    assert len(dets) >= 2
    assert (dets[0].x_px, dets[0].y_px) == pytest.approx((50.0, 40.0), abs=0.5)
    assert dets[0].diameter_px == pytest.approx(13.0, rel=0.1)
    assert dets[0].polarity == "warm" and dets[0].score > dets[1].score
    assert (dets[1].x_px, dets[1].y_px) == pytest.approx((120.0, 80.0), abs=0.5)
    scaled = detect_snapshot(_scene(np.random.default_rng(0)), 13, 2, 0.002, smooth_px=1.0, scale=2)
    assert (scaled[0].x_px, scaled[0].y_px) == pytest.approx((50.0, 40.0), abs=1.0)


def test_cli_writes_csv(tmp_path):
    img = _scene(np.random.default_rng(1))
    png = tmp_path / "a.png"
    cv2.imwrite(str(png), np.clip((img - 19.5) * 100, 0, 255).astype(np.uint8))
    tif = tmp_path / "b.tif"
    tifffile.imwrite(tif, img)
    out = tmp_path / "det.csv"
    res = CliRunner().invoke(command, [str(png), str(tif), "-o", str(out), "--mode", "single",
                                       "--d1-px", "25",
                                       "--d2-px", "3", "--epsilon", "0.002", "--scale", "1",
                                       "--smooth-px", "0", "--progress", "none"])
    assert res.exit_code == 0, res.output
    rows = list(csv.DictReader(out.open()))
    assert list(rows[0].keys()) == COLUMNS
    for name in (str(png), str(tif)):
        best = [r for r in rows if r["image"] == name][0]
        assert float(best["x_px"]) == pytest.approx(50.0, abs=0.5)
        assert float(best["y_px"]) == pytest.approx(40.0, abs=0.5)
    # multi-scale mode, altitude read from the name: same best blob
    named = tmp_path / "c__0-5m_x.png"
    named.write_bytes(png.read_bytes())
    res = CliRunner().invoke(command, [str(named), "-o", str(out), "--mode", "multiscale",
                                       "--altitude-from-name",
                                       "--px-at-1m", "6", "--progress", "none"])
    assert res.exit_code == 0, res.output
    rows = list(csv.DictReader(out.open()))
    assert (float(rows[0]["x_px"]), float(rows[0]["y_px"])) == pytest.approx((50, 40), abs=1.5)
    assert rows[0]["polarity"] == "warm" and 3.0 <= float(rows[0]["scale_px"]) <= 35.0
    res = CliRunner().invoke(command, [str(named), "-o", str(out), "--mode", "multiscale",
                                       "--min-diameter-px", "1"])
    assert getattr(res.exception, "exit_code", None) == 2  # usage error


def test_bad_image_is_one_line_error(tmp_path):
    bad = tmp_path / "broken.jpg"
    bad.write_bytes(b"not an image")
    with pytest.raises(InvalidInput, match="broken.jpg"):
        read_image(bad)
    from clearfast_gis.cli.main import cli

    with pytest.raises(SystemExit) as exc:
        cli(["detect-images", str(bad), "-o", str(tmp_path / "x.csv"), "--progress", "none"])
    assert exc.value.code == 1


def _real_images(n=4):
    """Four 1 cm-deep snapshots shipped in tests/data/colombia (see its README)."""
    files = sorted(glob.glob(str(COLOMBIA / "images" / "*Mine_1cm*.jpg")))
    assert len(files) == n
    return files


def test_real_snapshots_find_the_mine():
    found = 0
    files = _real_images()
    for f in files:
        boxes = []
        for line in Path(f.replace("/images/", "/labels/")).with_suffix(".txt").read_text(
        ).splitlines():
            if line.strip():
                _, cx, cy, w, h = map(float, line.split())
                boxes.append(((cx - w / 2) * 640, (cy - h / 2) * 640,
                              (cx + w / 2) * 640, (cy + h / 2) * 640))
        image = read_image(f)
        for dets in (detect_snapshot(image, 41, 5, 0.01, smooth_px=3.0, scale=2),
                     detect_snapshot_multiscale(image)):
            top = dets[:3]
            hit = [d for d in top for b in boxes
                   if b[0] <= d.x_px <= b[2] and b[1] <= d.y_px <= b[3]]
            if hit:
                found += 1
                assert hit[0].score > 1.0
    assert found >= 2 * len(files) - 2
