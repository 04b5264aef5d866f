"""Results as numpy arrays (python/result_arrays.cpp): lit polygons with their vertices,
sun hours per face and path against the sun-hours CSV."""

import numpy as np
import pytest

import shadowgen
from conftest import csv_tables, run_shadowgen

GROUND = np.array([[0, 0, 0], [10, 0, 0], [10, 10, 0], [0, 10, 0]], dtype=float)
ROOF = np.array([[2, 2, 3], [6, 2, 3], [6, 6, 3], [2, 6, 3]], dtype=float)
NOON = {"id": "noon", "type": "directional", "direction": (0, 0, -1)}


def loop_points(loop):
    return sorted(map(tuple, loop.tolist()))


def test_the_grounds_lit_polygon_is_the_ground_less_the_roofs_shadow():
    shadows = shadowgen.generate(shadowgen.make_scene([("ground", GROUND), ("roof", ROOF)], [NOON]))
    [(outer, holes)] = shadows.lit_polygons("ground", "noon")
    assert outer.shape == (4, 3) and outer.dtype == np.float64
    assert loop_points(outer) == loop_points(GROUND)
    assert [loop_points(hole) for hole in holes] == [[(2, 2, 0), (2, 6, 0), (6, 2, 0), (6, 6, 0)]]
    [(roof, roof_holes)] = shadows.lit_polygons(1, 0)
    assert loop_points(roof) == loop_points(ROOF) and roof_holes == []


def test_lit_polygons_by_an_id_or_index_the_scene_lacks():
    shadows = shadowgen.generate(shadowgen.make_scene([("ground", GROUND)], [NOON]))
    with pytest.raises(KeyError, match="no face 'lawn'"):
        shadows.lit_polygons("lawn", 0)
    with pytest.raises(IndexError, match="^light index 1 out of range$"):
        shadows.lit_polygons(0, 1)


def test_a_sampled_methods_shadows_hold_no_lit_polygons(scenes):
    shadows = shadowgen.load(scenes / "courtyard.json", method="rays", samples=16)
    assert not shadows.exact and shadows.method == "rays 16"
    with pytest.raises(shadowgen.InputError, match="no lit polygons kept") as raised:
        shadows.lit_polygons("ground", "sun")
    assert raised.value.file == str(scenes / "courtyard.json")


def test_sun_hours_are_the_sun_hours_csvs(scenes):
    table = shadowgen.load(scenes / "garden.json").sun_hours([2, 4])
    expected = csv_tables(run_shadowgen("report", scenes / "garden.json", "--format", "sun-hours",
                                        "--threshold", "2,4"))[0]
    assert len(table) == len(expected) == 12
    assert list(table.thresholds) == [2.0, 4.0]
    assert table.area_at_least.shape == (12, 2)
    # face_id, sun_path, area, mean, min and max sun hours, area at least 2 h and 4 h
    for row, line in zip(table, map(list, map(dict.values, expected))):
        assert row[:2] == tuple(line[:2])
        assert list(row[2:]) == [float(value) for value in line[2:6]]
    assert [list(r) for r in table.area_at_least] == \
        [[float(value) for value in list(line.values())[6:8]] for line in expected]
    assert list(table.face) == list(range(12))
    assert set(table.path_id) == {"march21"}


def test_sun_hours_need_the_paths_regions(scenes):
    shadows = shadowgen.load(scenes / "garden.json", sun_hours_regions=False)
    with pytest.raises(shadowgen.InputError):
        shadows.sun_hours()
