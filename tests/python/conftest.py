"""What the Python module's tests share: the example scenes, the `shadowgen` command
built beside the module, and its output parsed.

ctest runs them (tests/python/CMakeLists.txt) with PYTHONPATH at the built module and
SHADOWGEN_EXECUTABLE, SHADOWGEN_SOURCE_DIR set."""

import csv
import io
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("SHADOWGEN_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
SCENES = SOURCE_DIR / "examples" / "scenes"


@pytest.fixture(scope="session")
def scenes():
    return SCENES


def run_shadowgen(*args):
    """`shadowgen ARGS... --quiet`'s standard output; fails the test on a non-zero exit."""
    executable = os.environ.get("SHADOWGEN_EXECUTABLE")
    if not executable:
        pytest.fail("SHADOWGEN_EXECUTABLE is not set: run the tests through ctest")
    result = subprocess.run([executable, *map(str, args), "--quiet"], capture_output=True,
                            text=True, check=False)
    assert result.returncode == 0, result.stderr
    return result.stdout


def csv_tables(text):
    """The tables of a report CSV (an empty line between tables), each a list of dicts."""
    return [list(csv.DictReader(io.StringIO(block + "\n"))) for block in text.rstrip("\n").split("\n\n")]
