"""Scenes made from numbers (python/scene_arrays.cpp): faces as numpy arrays, lights,
site and groups as the scene file's dicts, meaning what the same scene written as a file
means."""

import json

import numpy as np
import pytest

import shadowgen
from conftest import csv_tables, run_shadowgen

GROUND = np.array([[0, 0, 0], [10, 0, 0], [10, 10, 0], [0, 10, 0]], dtype=float)
ROOF = np.array([[2, 2, 3], [6, 2, 3], [6, 6, 3], [2, 6, 3]], dtype=float)
NOON = {"id": "noon", "type": "directional", "direction": (0, 0, -1)}


def test_a_roof_over_the_ground_under_the_sun_straight_above():
    scene = shadowgen.make_scene([("ground", GROUND), ("roof", ROOF)], [NOON])
    rows = shadowgen.generate(scene).lit_areas()
    # The roof's 4 × 4 shadow falls on the 10 × 10 ground.
    assert list(rows) == [("ground", "noon", 100.0, 84.0), ("roof", "noon", 16.0, 16.0)]


def test_a_hole_in_the_shadow_is_neither_area_nor_lit_area():
    hole = np.array([[4, 4, 0], [4, 5, 0], [5, 5, 0], [5, 4, 0]])
    scene = shadowgen.make_scene([("ground", GROUND, [hole]), ("roof", ROOF.tolist())], [NOON],
                                 name="holed")
    assert scene.file == "holed"
    assert list(shadowgen.generate(scene).lit_areas())[0] == ("ground", "noon", 99.0, 84.0)


def test_the_garden_from_numbers_is_the_garden_from_its_file(scenes):
    # The example scene read as plain JSON, its faces as arrays: the same report numbers.
    document = json.loads((scenes / "garden.json").read_text())
    faces = [(p["id"], np.array(p["outer"], dtype=float)) for p in document["polygons"]]
    lights = [{k: v for k, v in light.items()} for light in document["lights"]]
    groups = {g["id"]: g["faces"] for g in document["groups"]}
    scene = shadowgen.make_scene(faces, lights, site=document["site"], groups=groups)
    assert scene.light_ids == shadowgen.read_scene(scenes / "garden.json").light_ids
    assert scene.sun_path_ids == ["march21"]
    rows = shadowgen.generate(scene).lit_areas()
    expected = csv_tables(run_shadowgen("report", scenes / "garden.json"))[0]
    assert [(r[0], r[1]) for r in rows] == [(e["face_id"], e["light_id"]) for e in expected]
    assert list(rows.lit_area) == [float(e["lit_area"]) for e in expected]
    assert {k: list(v) for k, v in shadowgen.groups(scene).items()} == {
        "garden": [0], "house": [1, 2, 3, 4, 5], "shed": [6, 7, 8, 9, 10]}


def test_a_point_light_with_a_range():
    lamp = {"id": "lamp", "type": "point", "position": [5, 5, 10], "intensity": [1, 1, 1],
            "range": {"falloff_start": 1.0, "end": 5.0, "exponent": 2}}
    scene = shadowgen.make_scene([("ground", GROUND)], [lamp])
    # The ground is 10 from the lamp, beyond its range's end: it is not lit.
    assert list(shadowgen.generate(scene).lit_areas()) == [("ground", "lamp", 100.0, 0.0)]


@pytest.mark.parametrize("faces,lights,message", [
    ([("ground", GROUND[:, :2])], [NOON],
     r"^face 'ground': outer: an \(n, 3\) array of points expected, not shape \(4, 2\)$"),
    ([("ground", GROUND, [np.zeros(3)])], [NOON],
     r"^face 'ground': hole 0: an \(n, 3\) array of points expected, not shape \(3,\)$"),
    ([("ground", [["a", "b", "c"]])], [NOON], r"^face 'ground': outer: not an array of numbers$"),
    ([("ground",)], [NOON], r"^face 0: \(id, outer\) or \(id, outer, holes\) expected, not 1 items$"),
    ([(7, GROUND)], [NOON], r"^face 0: its id is not a str$"),
    ([("ground", GROUND)], [{"id": "sun", "type": "spot"}],
     r"^light 'sun': type 'spot' is none of directional, point, sun$"),
    ([("ground", GROUND)], [{"id": "sun", "dir": (0, 0, -1)}], r"^light 'sun': unknown key 'dir'$"),
    ([("ground", GROUND)], [{"id": "sun", "direction": (0, -1)}],
     r"^light 'sun': direction: 3 numbers expected$"),
    ([("ground", GROUND)], [{"type": "sun"}], r"^light 0: no str 'id'$"),
])
def test_what_is_not_of_the_shape_is_a_value_error_naming_it(faces, lights, message):
    with pytest.raises(ValueError, match=message):
        shadowgen.make_scene(faces, lights)


def test_a_site_key_no_site_has():
    with pytest.raises(ValueError, match=r"^site: unknown key 'lat'$"):
        shadowgen.make_scene([("ground", GROUND)], [NOON], site={"lat": 51.5})


def test_what_the_scene_reader_refuses_is_an_input_error_naming_the_face(tmp_path):
    # The same face written as a scene file: the same problem; the scene's name as file.
    two = [[0, 0, 0], [1, 0, 0]]
    with pytest.raises(shadowgen.InputError) as raised:
        shadowgen.make_scene([("line", np.array(two))], [NOON], name="my scene")
    error = raised.value
    assert (error.file, error.face_id) == ("my scene", "line")
    assert error.problem == "the outer loop has 2 vertices; at least 3 are needed"
    assert str(error) == f"my scene: face 'line': {error.problem}"
    (tmp_path / "my scene").write_text(json.dumps({
        "format": "shadowgen-scene/1", "polygons": [{"id": "line", "outer": two}],
        "lights": [{"id": "noon", "type": "directional", "direction": [0, 0, -1]}]}))
    with pytest.raises(shadowgen.InputError) as from_file:
        shadowgen.read_scene(tmp_path / "my scene")
    assert (from_file.value.face_id, from_file.value.problem) == ("line", error.problem)


def test_a_face_id_twice():
    with pytest.raises(shadowgen.InputError, match=r"^s: polygons\[1\]\.id: duplicate id 'a' ") as raised:
        shadowgen.make_scene([("a", GROUND), ("a", ROOF)], [NOON], name="s")
    assert raised.value.file == "s"
