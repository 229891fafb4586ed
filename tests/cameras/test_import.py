"""``clearfast import``: a valid survey folder from camera files, a pose table and the logs;
every mismatch between frames and poses is one line naming the file, and nothing is written."""

from __future__ import annotations

import csv
import json
import shutil
import subprocess
import sys

import numpy as np
import pytest

from clearfast_gis.cameras.survey_import import ImportSpec, import_survey, read_pose_table
from clearfast_gis.cameras.tiff import write_tiff
from clearfast_gis.errors import InvalidInput
from clearfast_gis.survey import read_survey, validate_survey

pytestmark = pytest.mark.filterwarnings("ignore::rasterio.errors.NotGeoreferencedWarning")

N_FRAMES = 8


@pytest.fixture(scope="module")
def camera_dir(demo_survey, tmp_path_factory):
    """Scan 0 of the demo survey as 8 temperature TIFFs (degrees C) with a pose table and
    the survey's logs; the pose table leaves pan/tilt of the files' rows filled, time too."""
    d = tmp_path_factory.mktemp("cam")
    (d / "camera").mkdir()
    with open(demo_survey / "frames.csv", newline="") as fh:
        rows = [r for r in csv.DictReader(fh) if r["scan"] == "0" and r["band"] == "0"]
    rows = rows[:N_FRAMES]
    rng = np.random.default_rng(0)
    with open(d / "poses.csv", "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["file", "frame", "scan", "position", "time_utc", "pan_deg", "tilt_deg"])
        for r in rows:
            name = f"f{int(r['position']):03d}.tif"
            t_c = (15.0 + rng.normal(0.0, 0.5, (128, 160))).astype(np.float32)
            write_tiff(d / "camera" / name, t_c, "degC")
            w.writerow([name, 0, 0, r["position"], r["time_utc"], r["pan_deg"], r["tilt_deg"]])
    for name in ("gnss.nmea", "weather.dat", "soil.csv", "mission.json", "markers.csv"):
        shutil.copy(demo_survey / name, d / name)
    return d


def spec(d, **kw) -> ImportSpec:
    base = dict(frames=[d / "camera"], poses=d / "poses.csv", gnss=d / "gnss.nmea",
                weather=d / "weather.dat", soil=d / "soil.csv", mission=d / "mission.json",
                markers=d / "markers.csv", antenna_to_camera_m=(0.0, 0.0, -0.4),
                lens="equiangular", fov_deg=24.0, ground_altitude_m=160.0)
    base.update(kw)
    return ImportSpec(**base)


def test_import_builds_a_valid_survey(camera_dir, tmp_path):
    res = import_survey(spec(camera_dir), tmp_path / "survey")
    assert res.n_frames == N_FRAMES and res.n_scans == 1
    report = validate_survey(tmp_path / "survey")
    assert report.valid, [p.line() for p in report.problems]
    srv = read_survey(tmp_path / "survey")
    assert srv.radiometry.kind == "linear" and srv.radiometry.scale_k == 0.01
    assert "blackbody_frames" not in srv.manifest["files"]
    counts = srv.read_scan(0, 0)
    assert counts.shape == (N_FRAMES, 128, 160) and counts.dtype == np.uint16
    # 0.01 K counts reproduce the camera's temperatures within half a count
    t_in = read_frames_c(camera_dir / "camera" / "f000.tif")
    t_back = srv.radiometry.sensor_temperature_k(counts[0]) - 273.15
    assert np.max(np.abs(t_back - t_in)) <= 0.005 + 1e-6
    assert srv.frames.time_s.min() >= srv.start_s
    assert (tmp_path / "survey" / "gnss.nmea").read_bytes() == \
        (camera_dir / "gnss.nmea").read_bytes()


def read_frames_c(path):
    from clearfast_gis.cameras import read_frames

    return read_frames(path)[0].object_temperature_c().astype(np.float64)


def _edited(camera_dir, tmp_path, edit):
    d = tmp_path / "cam"
    shutil.copytree(camera_dir, d)
    edit(d)
    return d


def _drop_last_pose(d):
    lines = (d / "poses.csv").read_text().splitlines()
    (d / "poses.csv").write_text("\n".join(lines[:-1]) + "\n")


def _extra_pose(d):
    with open(d / "poses.csv", "a") as fh:
        fh.write("ghost.tif,0,0,99,2026-11-15T01:00:30Z,0,-45\n")


def _duplicate_position(d):
    lines = (d / "poses.csv").read_text().splitlines()
    parts = lines[2].split(",")
    parts[3] = lines[1].split(",")[3]
    lines[2] = ",".join(parts)
    (d / "poses.csv").write_text("\n".join(lines) + "\n")


def _no_unit(d):
    import tifffile

    tifffile.imwrite(d / "camera" / "f000.tif", np.full((128, 160), 15.0, np.float32))


def _no_time(d):
    lines = (d / "poses.csv").read_text().splitlines()
    parts = lines[1].split(",")
    parts[4] = ""
    lines[1] = ",".join(parts)
    (d / "poses.csv").write_text("\n".join(lines) + "\n")


@pytest.mark.parametrize("edit,message", [
    (_drop_last_pose, r"f\d{3}\.tif: frame 0 has no row in the pose table"),
    (_extra_pose, r"poses\.csv: line 10: file ghost\.tif frame 0 is not among the camera"),
    (_duplicate_position, r"poses\.csv: line 3: scan 0 position \d+ already on line 2"),
    (_no_unit, r"f000\.tif: float TIFF without a stated unit"),
    (_no_time, r"poses\.csv: line 2: time_utc: no time_utc for f000\.tif frame 0"),
])
def test_bad_input_is_one_error_and_nothing_written(camera_dir, tmp_path, edit, message):
    d = _edited(camera_dir, tmp_path, edit)
    out = tmp_path / "out"
    with pytest.raises(InvalidInput, match=message):
        import_survey(spec(d), out)
    assert not out.exists()
    assert [p.name for p in tmp_path.iterdir()] == ["cam"]  # no temporary folder left


def test_pose_table_errors_name_line_and_column(tmp_path):
    p = tmp_path / "poses.csv"
    p.write_text("file,scan,position,pan_deg\na.jpg,0,x,1\n")
    with pytest.raises(InvalidInput, match=r"poses\.csv: line 2: position: not an integer"):
        read_pose_table(p)
    p.write_text("file,scan\na.jpg,0\n")
    with pytest.raises(InvalidInput, match=r"line 1: missing column\(s\) position"):
        read_pose_table(p)


def test_cli_folder_layout_and_refusal_of_existing_output(camera_dir, tmp_path):
    d = _edited(camera_dir, tmp_path, lambda d: None)
    layout = {"frames": "camera", "poses": "poses.csv", "gnss": "gnss.nmea",
              "weather": "weather.dat", "soil": "soil.csv", "mission": "mission.json",
              "antenna_to_camera_m": [0, 0, -0.4], "lens": "equiangular", "fov_deg": 24.0}
    (d / "import.json").write_text(json.dumps(layout))
    cmd = [sys.executable, "-m", "clearfast_gis.cli.main", "import", str(d), "-o",
           str(tmp_path / "s"), "--progress", "none"]
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    assert "ground altitude" in r.stderr  # derived, and said so
    assert validate_survey(tmp_path / "s").valid
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    assert r.returncode == 1 and "already exists" in r.stderr and "Traceback" not in r.stderr


def test_calibrate_uses_the_camera_radiometry(camera_dir, tmp_path):
    import_survey(spec(camera_dir), tmp_path / "survey")
    r = subprocess.run([sys.executable, "-m", "clearfast_gis.cli.main", "calibrate",
                        str(tmp_path / "survey"), "-o", str(tmp_path / "cal"), "--progress",
                        "none"], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    doc = json.loads(next((tmp_path / "cal").rglob("calibration.json")).read_text())
    assert doc["bands"][0]["calibration"] == "camera radiometry (linear)"
    assert doc["bands"][0]["n_events"] == 0
    # at-sensor 15 +- 0.5 degC frames; the atmosphere over the ~10 m path moves them by
    # well under a kelvin
    assert doc["scans"][0]["mean_c"] == pytest.approx(15.0, abs=1.0)
    assert doc["scans"][0]["invalid_pixels"] == 0


# -- blackbody frames -----------------------------------------------------------------------

N_BB = 3  # frames per blackbody and event


def _write_blackbody_frames(d, demo_survey, offset_k: float) -> None:
    """Blackbody frames of events 0 and 1 as degrees C TIFFs in the camera folder: the log's
    temperature at each frame's time (the demo survey's blackbody times) + ``offset_k`` and
    0.02 K noise; ``blackbody.csv`` names them (rows shuffled: matched by name, not order)."""
    from clearfast_gis.radiometry.calibration import blackbody_temperature_at
    from clearfast_gis.survey import read_blackbody_log
    from clearfast_gis.timeutil import parse_utc

    log = read_blackbody_log(demo_survey / "blackbody" / "temperatures.csv")
    shutil.copy(demo_survey / "blackbody" / "temperatures.csv", d / "bb_log.csv")
    with open(demo_survey / "blackbody" / "frames.csv", newline="") as fh:
        src = [r for r in csv.DictReader(fh) if r["band"] == "0" and r["event"] in "01"]
    rng = np.random.default_rng(1)
    rows = []
    for ev in ("0", "1"):
        for bb in ("1", "2"):
            for k, r in enumerate([r for r in src if (r["event"], r["blackbody"]) == (ev, bb)]
                                  [:N_BB]):
                temps = log.bb1_c if bb == "1" else log.bb2_c
                t_k = float(blackbody_temperature_at(log.time_s, temps + 273.15,
                                                     parse_utc(r["time_utc"])))
                img = t_k - 273.15 + offset_k + rng.normal(0.0, 0.02, (128, 160))
                name = f"bb_e{ev}_b{bb}_{k}.tif"
                write_tiff(d / "camera" / name, img.astype(np.float32), "degC")
                rows.append([f"camera/{name}", 0, ev, bb, r["time_utc"]])
    rng.shuffle(rows)
    with open(d / "blackbody.csv", "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["file", "frame", "event", "blackbody", "time_utc"])
        w.writerows(rows)


def _bb_spec(d):
    return spec(d, blackbody=d / "blackbody.csv", blackbody_log=d / "bb_log.csv")


@pytest.mark.parametrize("offset_k", [0.0, 0.5])
def test_blackbody_frames_check_the_camera(camera_dir, demo_survey, tmp_path, offset_k):
    from clearfast_gis.radiometry.camera_check import camera_blackbody_check

    d = _edited(camera_dir, tmp_path, lambda d: _write_blackbody_frames(d, demo_survey,
                                                                        offset_k))
    res = import_survey(_bb_spec(d), tmp_path / "survey")
    assert res.n_frames == N_FRAMES  # the blackbody files in the camera folder are not poses
    report = validate_survey(tmp_path / "survey")
    assert report.valid, [p.line() for p in report.problems]
    check = camera_blackbody_check(read_survey(tmp_path / "survey"))
    assert [c["event"] for c in check] == [0, 1]
    for c in check:
        assert c["bb1_log_c"] - c["bb2_log_c"] > 5.0  # a real pair, heated vs ambient
        assert c["gain"] == pytest.approx(1.0, abs=0.005)
        # offset = log - camera at blackbody 2: a camera reading 0.5 K high gives -0.5 K
        assert c["offset_k"] == pytest.approx(-offset_k, abs=0.01)
        assert c["bb1_camera_c"] - c["bb1_log_c"] == pytest.approx(offset_k, abs=0.01)


def _bb_lines(d, change):
    lines = (d / "blackbody.csv").read_text().splitlines()
    (d / "blackbody.csv").write_text("\n".join(change(lines)) + "\n")


@pytest.mark.parametrize("change,message", [
    (lambda ls: ls[:1] + [ls[1].replace("camera/", "camera/ghost_")] + ls[2:],
     r"blackbody\.csv: line 2: file: no camera file camera/ghost_bb"),
    (lambda ls: ls + [ls[3]], r"blackbody\.csv: line 14: file camera/bb_\S+ frame 0 already "
     r"on line 4"),
    (lambda ls: [ls[0]] + [x for x in ls[1:] if ",1,2," not in x],
     r"blackbody\.csv: line \d+: event 1 has no frame of blackbody 2"),
    (lambda ls: ls[:1] + [ls[1].rsplit(",", 2)[0] + ",3," + ls[1].rsplit(",", 1)[1]] + ls[2:],
     r"blackbody\.csv: line 2: blackbody: not 1 \(heated\) or 2"),
])
def test_bad_blackbody_table_is_one_error_and_nothing_written(camera_dir, demo_survey,
                                                              tmp_path, change, message):
    def edit(d):
        _write_blackbody_frames(d, demo_survey, 0.0)
        _bb_lines(d, change)

    d = _edited(camera_dir, tmp_path, edit)
    with pytest.raises(InvalidInput, match=message):
        import_survey(_bb_spec(d), tmp_path / "out")
    assert [p.name for p in tmp_path.iterdir()] == ["cam"]


def test_blackbody_table_needs_its_log(camera_dir, demo_survey, tmp_path):
    d = _edited(camera_dir, tmp_path, lambda d: _write_blackbody_frames(d, demo_survey, 0.0))
    with pytest.raises(InvalidInput, match=r"blackbody\.csv: .*--blackbody-log"):
        import_survey(spec(d, blackbody=d / "blackbody.csv"), tmp_path / "out")


@pytest.mark.slow
def test_cli_import_with_blackbodies_then_process_records_camera_check(camera_dir, demo_survey,
                                                                       tmp_path):
    d = _edited(camera_dir, tmp_path, lambda d: _write_blackbody_frames(d, demo_survey, 0.5))
    cli = [sys.executable, "-m", "clearfast_gis.cli.main"]
    r = subprocess.run([*cli, "import", str(d / "camera"), "--poses", str(d / "poses.csv"),
                        "--gnss", str(d / "gnss.nmea"), "--weather", str(d / "weather.dat"),
                        "--soil", str(d / "soil.csv"), "--mission", str(d / "mission.json"),
                        "--antenna-to-camera", "0,0,-0.4", "--lens", "equiangular",
                        "--fov-deg", "24", "--ground-altitude-m", "160",
                        "--blackbody", str(d / "blackbody.csv"),
                        "--blackbody-log", str(d / "bb_log.csv"),
                        "-o", str(tmp_path / "s"), "--progress", "none"],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    r = subprocess.run([*cli, "process", str(tmp_path / "s"), "-o", str(tmp_path / "p"),
                        "--progress", "none"], capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    check = json.loads((tmp_path / "p" / "products.json").read_text())["camera_check"]
    assert [c["event"] for c in check] == [0, 1]
    for c in check:  # the blackbody frames were written 0.5 K warm
        assert c["gain"] == pytest.approx(1.0, abs=0.005)
        assert c["offset_k"] == pytest.approx(-0.5, abs=0.01)
