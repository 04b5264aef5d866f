"""The library's errors as Python exceptions (python/errors.cpp): classes under
shadowgen.Error, the fields naming the input at fault, str() the command's own line."""

import subprocess
import os

import pytest

import shadowgen


def test_the_classes():
    assert issubclass(shadowgen.Error, Exception)
    assert issubclass(shadowgen.InputError, shadowgen.Error)
    assert issubclass(shadowgen.GenerationError, shadowgen.Error)
    assert not issubclass(shadowgen.InputError, shadowgen.GenerationError)
    error = shadowgen.GenerationError("made in Python")
    assert (error.file, error.problem, error.face_id, error.light_id) == ("", "", "", "")


def test_a_missing_scene_names_its_file_as_the_command_does(tmp_path):
    missing = tmp_path / "missing.json"
    with pytest.raises(shadowgen.InputError) as raised:
        shadowgen.read_scene(missing)
    error = raised.value
    assert error.file == str(missing) and error.face_id == ""
    command = subprocess.run([os.environ["SHADOWGEN_EXECUTABLE"], "report", str(missing)],
                             capture_output=True, text=True, check=False)
    assert command.returncode != 0
    assert str(error) in command.stderr


def test_a_light_the_scene_lacks(scenes):
    with pytest.raises(shadowgen.InputError, match="moon") as raised:
        shadowgen.load(scenes / "courtyard.json", lights=["moon"])
    assert raised.value.file == str(scenes / "courtyard.json")
    with pytest.raises(shadowgen.Error):
        shadowgen.lit_areas(scenes / "courtyard.json", lights="moon")


def test_a_face_pattern_that_matches_nothing(scenes):
    with pytest.raises(shadowgen.InputError, match="nothing-here"):
        shadowgen.groups(shadowgen.read_scene(scenes / "garden.json"), ["nothing-here*"])


def test_an_output_that_cannot_be_written_leaves_nothing(scenes, tmp_path):
    shadows = shadowgen.load(scenes / "courtyard.json")
    with pytest.raises(RuntimeError, match="no-such-folder"):
        shadowgen.write_database(shadows, tmp_path / "no-such-folder" / "db.json")
    with pytest.raises(ValueError):
        shadowgen.write_gltf(shadows, tmp_path / "model.png")
    assert list(tmp_path.iterdir()) == []


def test_reading_warnings_are_python_warnings(tmp_path):
    scene = tmp_path / "extra.json"
    scene.write_text('{"format": "shadowgen-scene/1", "colour": "red", "polygons": '
                     '[{"id": "ground", "outer": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]]}], '
                     '"lights": [{"id": "noon", "type": "directional", "direction": [0,0,-1]}]}')
    with pytest.warns(UserWarning, match="colour"):
        shadowgen.read_scene(scene)
    with pytest.raises(shadowgen.InputError, match="colour"):
        shadowgen.read_scene(scene, strict=True)
