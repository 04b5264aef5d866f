"""examples/python/: each script runs on the example scenes and prints what the command
prints."""

import subprocess
import sys

import pytest

from conftest import SOURCE_DIR, run_shadowgen


@pytest.mark.parametrize("scene", ["courtyard.json", "garden.json", "chairs.json"])
def test_lit_areas_py_prints_the_report_csv_byte_for_byte(scenes, scene):
    result = subprocess.run([sys.executable, SOURCE_DIR / "examples" / "python" / "lit_areas.py",
                             scenes / scene], capture_output=True, text=True, check=True)
    assert result.stdout == run_shadowgen("report", scenes / scene)


def test_lit_areas_py_on_a_missing_scene(tmp_path):
    result = subprocess.run([sys.executable, SOURCE_DIR / "examples" / "python" / "lit_areas.py",
                             tmp_path / "missing.json"], capture_output=True, text=True)
    assert result.returncode == 1 and result.stdout == ""
    assert result.stderr.startswith(f"bad input: {tmp_path / 'missing.json'}: ")
