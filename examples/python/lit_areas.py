#!/usr/bin/env python3
"""Prints the report CSV of the scene (or shadowed database) named on the command line, as
`shadowgen report SCENE` does, from the Python module: the shadows generated with the
exact method, then area, lit area and lit fraction per face and light.

    PYTHONPATH=PREFIX/lib/python3/dist-packages python3 lit_areas.py courtyard.json
"""

import csv
import sys

import shadowgen


def main():
    if len(sys.argv) != 2:
        sys.exit(f"usage: lit_areas.py SCENE.json (shadowgen {shadowgen.__version__})")
    try:
        rows = shadowgen.lit_areas(sys.argv[1], method="exact", threads=0)
    except shadowgen.InputError as error:
        sys.exit(f"bad input: {error}")
    out = csv.writer(sys.stdout, lineterminator="\n")
    out.writerow(["face_id", "light_id", "area", "lit_area", "lit_fraction"])
    for (face_id, light_id, area, lit_area), fraction in zip(rows, rows.lit_fraction):
        # 17 significant digits, as the command writes them: each reads back as the same double.
        out.writerow([face_id, light_id, f"{area:.17g}", f"{lit_area:.17g}", f"{fraction:.17g}"])


if __name__ == "__main__":
    main()
