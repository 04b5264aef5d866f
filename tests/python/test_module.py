"""shadowgen's entry points in Python (python/module.cpp): lit areas equal to the report
CSV's numbers, by any method; threads honoured; the GIL released while a scene is
generated; every output byte for byte as the command writes it."""

import json
import os
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import shadowgen
from conftest import csv_tables, run_shadowgen


def test_version_is_the_commands():
    assert run_shadowgen("--version") == f"shadowgen {shadowgen.__version__}\n"
    assert shadowgen.version() == shadowgen.__version__


@pytest.mark.parametrize("scene", ["courtyard.json", "garden.json", "pergola.json"])
def test_lit_areas_are_the_report_csvs_numbers(scenes, scene):
    rows = shadowgen.lit_areas(scenes / scene)
    expected = csv_tables(run_shadowgen("report", scenes / scene))[0]
    assert len(rows) == len(expected) > 0
    for (face_id, light_id, area, lit_area), line in zip(rows, expected):
        # The CSV writes 17 significant digits: each number reads back as the same double.
        assert (face_id, light_id) == (line["face_id"], line["light_id"])
        assert area == float(line["area"])
        assert lit_area == float(line["lit_area"])
    assert list(rows.lit_fraction) == [float(line["lit_fraction"]) for line in expected]


@pytest.mark.parametrize("method,options", [
    ("rays", ["--samples", "16"]),
    ("shadow-map", ["--samples", "16", "--resolution", "256"]),
])
def test_a_sampled_methods_lit_areas_are_its_report_csvs(scenes, method, options):
    rows = shadowgen.lit_areas(scenes / "courtyard.json", method=method, samples=16, resolution=256)
    expected = csv_tables(run_shadowgen("report", scenes / "courtyard.json", "--method", method,
                                        *options))[0]
    assert list(rows.lit_area) == [float(line["lit_area"]) for line in expected]
    assert list(rows.area) == [float(line["area"]) for line in expected]


def test_columns_are_numpy_arrays_of_the_rows(scenes):
    rows = shadowgen.lit_areas(str(scenes / "courtyard.json"), "exact", 2)
    scene = shadowgen.read_scene(scenes / "courtyard.json")
    assert rows.area.dtype == np.float64 and rows.lit_area.dtype == np.float64
    assert rows.face.dtype == np.int64 and rows.light.dtype == np.int64
    assert list(rows.face_id) == [scene.face_ids[f] for f in rows.face]
    assert list(rows.light_id) == [scene.light_ids[l] for l in rows.light]
    assert rows[0] == ("ground", "sun", 400.0, rows.lit_area[0])
    assert rows[-1] == tuple(list(rows)[-1])
    assert np.array_equal(rows.lit_fraction, rows.lit_area / rows.area)


def test_the_lights_asked_for_alone(scenes):
    rows = shadowgen.lit_areas(scenes / "courtyard.json", lights=["lamp"])
    assert set(rows.light_id) == {"lamp"}
    assert list(rows.lit_area) == [float(line["lit_area"]) for line in csv_tables(
        run_shadowgen("report", scenes / "courtyard.json", "--lights", "lamp"))[0]]


def new_threads(scene, threads):
    """How many threads generating `scene` on `threads` threads starts, in a fresh process."""
    program = (
        "import os, shadowgen\n"
        "before = len(os.listdir('/proc/self/task'))\n"
        f"shadowgen.lit_areas({str(scene)!r}, threads={threads})\n"
        "print(len(os.listdir('/proc/self/task')) - before)\n")
    environment = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
    result = subprocess.run([sys.executable, "-c", program], capture_output=True, text=True,
                            env=environment, check=True)
    return int(result.stdout)


def test_threads_are_honoured(scenes):
    # The engine's pool is the caller's thread and threads - 1 workers of its own.
    scene = scenes / "pergola.json"
    assert new_threads(scene, 1) == 0
    assert 1 <= new_threads(scene, 4) <= 3
    assert list(shadowgen.lit_areas(scene, threads=1).lit_area) == \
        list(shadowgen.lit_areas(scene, threads=4).lit_area)


def test_other_python_threads_run_while_a_scene_is_generated(scenes):
    # The garden's faces under a sun every 10 minutes of 21 March: 72 instants, a few
    # tenths of a second of work.
    document = json.loads((scenes / "garden.json").read_text())
    faces = [(polygon["id"], polygon["outer"]) for polygon in document["polygons"]]
    day = {"id": "day", "type": "sun", "from": "2026-03-21T06:00", "to": "2026-03-21T18:00",
           "step_min": 10}
    scene = shadowgen.make_scene(faces, [day], site=document["site"])
    span = {}

    def generate():
        span["start"] = time.perf_counter()
        shadowgen.generate(scene, threads=1)
        span["end"] = time.perf_counter()

    worker = threading.Thread(target=generate)
    stamps = []
    worker.start()
    while worker.is_alive():
        stamps.append(time.perf_counter())
    worker.join()
    assert span["end"] - span["start"] > 0.05, "too little work to tell"
    # Holding the GIL, generate would let no stamp be taken until it returned: none in the
    # first half of its time (after it, the worker waits for the GIL to set "end").
    middle = (span["start"] + span["end"]) / 2
    assert any(span["start"] < t < middle for t in stamps)


def test_bad_settings_are_value_errors(scenes):
    with pytest.raises(ValueError, match=r"^method 'bogus' is none of exact, rays, shadow-map$"):
        shadowgen.lit_areas(scenes / "courtyard.json", method="bogus")
    with pytest.raises(ValueError, match=r"^threads must be 0 \(every hardware thread\) or more$"):
        shadowgen.lit_areas(scenes / "courtyard.json", threads=-1)
    with pytest.raises(ValueError, match=r"^samples must be from 1 to "):
        shadowgen.lit_areas(scenes / "courtyard.json", method="rays", samples=0)
    with pytest.raises(ValueError, match=r"^report format 'xml' is none of csv, energyplus, "):
        shadowgen.report(shadowgen.load(scenes / "courtyard.json"), "xml")


@pytest.mark.parametrize("format,options", [
    ("csv", []), ("json", []), ("table", []), ("sun-hours", ["--threshold", "2,4"]),
    ("sun-hours-table", ["--threshold", "2,4"])])
def test_reports_are_the_commands_byte_for_byte(scenes, format, options):
    shadows = shadowgen.load(scenes / "garden.json")
    thresholds = [2.0, 4.0] if options else [2.0]
    assert shadowgen.report(shadows, format, thresholds=thresholds) == \
        run_shadowgen("report", scenes / "garden.json", "--format", format, *options)


def test_groups_in_a_report_are_the_commands(scenes):
    shadows = shadowgen.load(scenes / "garden.json")
    assert shadowgen.report(shadows, group_by="house-*") == \
        run_shadowgen("report", scenes / "garden.json", "--group-by", "house-*")


def test_files_are_the_commands_byte_for_byte(scenes, tmp_path):
    # Each in a folder of its own under the same name: an OBJ names its MTL.
    scene = scenes / "courtyard.json"
    ours, theirs = tmp_path / "ours", tmp_path / "theirs"
    ours.mkdir()
    theirs.mkdir()
    shadows = shadowgen.load(scene)
    shadowgen.write_database(shadows, ours / "courtyard.json")
    shadowgen.write_obj(shadows, ours / "courtyard.obj")
    shadowgen.write_gltf(shadows, ours / "courtyard.glb")
    shadowgen.write_svg(shadows, ours / "courtyard.svg", "main", width=400, height=300)
    run_shadowgen("generate", scene, "-o", theirs / "courtyard.json")
    run_shadowgen("export", scene, "-o", theirs / "courtyard.obj", "-o", theirs / "courtyard.glb")
    run_shadowgen("render", theirs / "courtyard.json", "--view", "main", "--width", "400",
                  "--height", "300", "-o", theirs / "courtyard.svg")
    names = sorted(path.name for path in theirs.iterdir())
    assert names == ["courtyard.glb", "courtyard.json", "courtyard.mtl", "courtyard.obj",
                     "courtyard.svg"]
    assert sorted(path.name for path in ours.iterdir()) == names
    for name in names:
        assert (ours / name).read_bytes() == (theirs / name).read_bytes(), name


def test_a_database_written_reads_back_with_the_same_lit_areas(scenes, tmp_path):
    shadows = shadowgen.load(scenes / "courtyard.json")
    shadowgen.write_database(shadows, tmp_path / "courtyard.shadowed.json")
    again = shadowgen.load(tmp_path / "courtyard.shadowed.json")
    assert list(again.lit_areas()) == list(shadows.lit_areas())
    assert again.exact and again.method == "exact"


def test_the_radiation_report_is_the_commands_byte_for_byte(tmp_path):
    header = ["LOCATION,Test,,GBR,Test,000000,51.5,0.0,0.0,10.0", "DESIGN CONDITIONS,0",
              "TYPICAL/EXTREME PERIODS,0", "GROUND TEMPERATURES,0",
              "HOLIDAYS/DAYLIGHT SAVINGS,No,0,0,0", "COMMENTS 1,", "COMMENTS 2,",
              "DATA PERIODS,1,1,Data,Sunday, 1/ 1,12/31"]
    rows = ["2026,3,21,%d,0,?9,6,4,87,101800,0,0,316,500,400,150,0,0,0,0,240,4,8,8,11,77777,9,"
            "999999999,0,0.1,0,88,0.3,0,0" % h for h in range(1, 25)]
    (tmp_path / "march.epw").write_text("\n".join(header + rows) + "\n")
    scene = tmp_path / "yard.json"
    scene.write_text(json.dumps({
        "format": "shadowgen-scene/1", "weather": "march.epw",
        "polygons": [{"id": "yard", "outer": [[0, 0, 0], [10, 0, 0], [10, 10, 0], [0, 10, 0]]},
                     {"id": "wall", "outer": [[0, 0, 0], [10, 0, 0], [10, 0, 4], [0, 0, 4]]}],
        "lights": [{"id": "day", "type": "sun", "from": "2026-03-21T10:00",
                    "to": "2026-03-21T14:00", "step_min": 60}]}))
    assert shadowgen.radiation_report(scene, subdivisions=2, albedo=0.5) == \
        run_shadowgen("report", scene, "--format", "radiation", "--sky", "reinhart:2",
                      "--albedo", "0.5")


@pytest.mark.parametrize("subdivisions,sky", [(1, "tregenza"), (2, "reinhart:2")])
def test_the_sky_report_is_the_commands_byte_for_byte(scenes, subdivisions, sky):
    assert shadowgen.sky_report(scenes / "courtyard.json", subdivisions=subdivisions) == \
        run_shadowgen("report", scenes / "courtyard.json", "--format", "sky", "--sky", sky)


@pytest.mark.parametrize("fine,sky", [(False, []), (True, ["--sky", "tregenza"])])
def test_the_energyplus_sky_report_is_the_commands_byte_for_byte(scenes, fine, sky):
    text = shadowgen.sky_report(scenes / "courtyard.json", subdivisions=1, energyplus=True,
                                energyplus_fine=fine)
    assert text == run_shadowgen("report", scenes / "courtyard.json", "--format",
                                 "energyplus-sky", *sky)
    rows = csv_tables(text)[0]
    assert rows and all(0 <= float(row["dif_shdg_ratio_iso_sky"]) <= 1 for row in rows)
