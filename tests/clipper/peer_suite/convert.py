#!/usr/bin/env python3
"""Converts JTS overlay test XML files into the peer suite's compact case files.

Usage: python3 convert.py XML_DIR OUT_DIR

XML_DIR holds JTS test XML files named after their path below JTS's
modules/tests/src/test/resources/testxml/ with "/" replaced by "__"
(general/TestOverlayAA.xml -> general__TestOverlayAA.xml). For each file that has at
least one case whose operands <a> and <b> are both areal (POLYGON or MULTIPOLYGON,
EMPTY included, as WKT or hex WKB), OUT_DIR/<name>.txt is written:

    case <n>
    a <operand A, on one line>
    b <operand B, on one line>

n is the case's 1-based position among the file's <case> elements (all of them, so
that a case keeps its number, and its test name "<name>#<n>", whatever is filtered
out). Geometry text is kept as written; only runs of white space are folded into one
space, which changes no WKT token and so no coordinate. JTS's expected results are
not kept: the test recomputes the truth with CGAL. Lines starting with "#" are
comments. Standard library only.
"""

import argparse
import pathlib
import re
import string
import struct
import sys
import xml.etree.ElementTree as ET

JTS_COMMIT = "07833d3c2f90"
JTS_TESTXML = "modules/tests/src/test/resources/testxml"
AREAL_WKT = {"POLYGON", "MULTIPOLYGON"}
AREAL_WKB = {3, 6}  # WKB type codes of Polygon and MultiPolygon
HEX_DIGITS = set(string.hexdigits)


def folded(text):
    return " ".join(text.split())


def is_wkb_hex(text):
    return bool(text) and all(c in HEX_DIGITS for c in text)


def is_areal(text):
    """Whether tests/support/wkt.h or wkb.h would read the geometry as areal."""
    if is_wkb_hex(text):
        data = bytes.fromhex(text)
        if len(data) < 5 or data[0] > 1:
            raise ValueError("malformed WKB header: " + text[:40])
        (kind,) = struct.unpack("<I" if data[0] == 1 else ">I", data[1:5])
        return (kind & 0xFFFF) in AREAL_WKB
    match = re.match(r"[A-Za-z]*", text)
    return match.group(0).upper() in AREAL_WKT


def operand(case, tag, where):
    element = case.find(tag)
    if element is None:
        return None
    text = folded("".join(element.itertext()))
    if not text:
        raise ValueError(f"{where}: <{tag}> is empty")
    if " " in text and is_wkb_hex(text.replace(" ", "")):
        raise ValueError(f"{where}: <{tag}> is hex WKB with white space inside")
    return text


def convert(path):
    """The file's areal cases as (number, a, b), in file order."""
    cases = []
    for number, case in enumerate(ET.parse(path).getroot().iter("case"), start=1):
        where = f"{path.name} case {number}"
        a = operand(case, "a", where)
        b = operand(case, "b", where)
        if a is not None and b is not None and is_areal(a) and is_areal(b):
            cases.append((number, a, b))
    return cases


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("xml_dir", type=pathlib.Path)
    parser.add_argument("out_dir", type=pathlib.Path)
    args = parser.parse_args()
    sources = sorted(args.xml_dir.glob("*.xml"))
    if not sources:
        sys.exit(f"no .xml files in {args.xml_dir}")
    args.out_dir.mkdir(parents=True, exist_ok=True)
    total = 0
    for path in sources:
        cases = convert(path)
        if not cases:
            print(f"{path.name}: no case with two areal operands, not written")
            continue
        origin = path.stem.replace("__", "/") + ".xml"
        lines = [
            f"# JTS Topology Suite (locationtech/jts, commit {JTS_COMMIT}),",
            f"# {JTS_TESTXML}/{origin}",
            "# EDL 1.0 (or EPL 2.0): see ../LICENSE_EDLv1.txt, ../LICENSES.md and ../README.md.",
            "# Made by convert.py: the cases whose operands are both areal, JTS's results dropped.",
        ]
        for number, a, b in cases:
            lines += ["", f"case {number}", f"a {a}", f"b {b}"]
        (args.out_dir / (path.stem + ".txt")).write_text("\n".join(lines) + "\n", encoding="ascii")
        total += len(cases)
        print(f"{path.name}: {len(cases)} case{'' if len(cases) == 1 else 's'}")
    print(f"{total} cases in all")


if __name__ == "__main__":
    main()
