#!/usr/bin/env python3
"""Writes the clip fuzzer's seed corpus, tests/fuzz/corpus/clip/.

Each seed is one degenerate configuration clip() must get right, encoded in the byte
format that fuzz_input.h documents (keep the two in step). Every seed is within clip()'s
contract; the CTest test clip_fuzz_corpus_well_formed checks that.

    make_corpus.py            write the seeds, and the open findings to tests/fuzz/findings/
                              (other files in either folder are left alone)
    make_corpus.py --check    exit 1 if a file it writes is missing or differs
"""

import argparse
import pathlib
import struct
import sys

GRID, SCALED, PERTURBED, RAW = 0, 1, 2, 3

# Indices into fuzz_input.h's kSteps and kOffsets.
STEP = {1.0: 0, 0.5: 1, 0.1: 2, 1e-3: 3, "1/3": 4, 1e-7: 5, 1e5: 6, 3.0: 7}
OFFSET = {0.0: 0, 1.0: 1, -0.3: 2, 1e3: 3, 1e6: 4, -7.25e5: 5, 1e8: 6, 0.1: 7}


def coordinate(mode, c):
    if mode in (GRID, SCALED):
        assert isinstance(c, int) and -8 <= c <= 8, c
        return bytes([c + 8])
    if mode == PERTURBED:
        g, nudge = c if isinstance(c, tuple) else (c, 0)
        assert -8 <= g <= 8 and -128 <= nudge <= 127, c
        return bytes([g + 8, nudge & 0xFF])
    assert 1e-9 <= abs(c) <= 1e9 or c == 0.0, c
    return struct.pack("<d", c)


def loop(mode, points, fan=False):
    assert 3 <= len(points) <= 24, points
    out = bytes([(len(points) - 3) | (0x80 if fan else 0)])
    for x, y in points:
        out += coordinate(mode, x) + coordinate(mode, y)
    return out


def polygon_set(mode, polygons):
    """polygons: list of (outer, [holes]); a loop is a list of points or (points, fan)."""
    assert len(polygons) <= 3
    out = bytes([len(polygons)])
    for outer, holes in polygons:
        assert len(holes) <= 2
        out += bytes([len(holes)])
        for ring in [outer, *holes]:
            points, fan = ring if isinstance(ring, tuple) else (ring, False)
            out += loop(mode, points, fan)
    return out


def encode(subject, clip, mode=GRID, parameter=0):
    assert 0 <= parameter < 64
    return bytes([mode | parameter << 2]) + polygon_set(mode, subject) + polygon_set(mode, clip)


def rect(x0, y0, x1, y1):
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def reversed_loop(points):
    return list(reversed(points))


SQUARE = rect(0, 0, 4, 4)
BIG = rect(-6, -6, 6, 6)
U_SHAPE = [(-6, -6), (6, -6), (6, 6), (2, 6), (2, -2), (-2, -2), (-2, 6), (-6, 6)]
COMB = [(-7, -6), (7, -6), (7, 6), (5, 6), (5, -2), (3, -2), (3, 6), (1, 6), (1, -2),
        (-1, -2), (-1, 6), (-3, 6), (-3, -2), (-5, -2), (-5, 6), (-7, 6)]
STAR = [(0, 8), (2, 2), (8, 0), (2, -2), (0, -8), (-2, -2), (-8, 0), (-2, 2)]

SEEDS = {
    "identical-squares": encode([(SQUARE, [])], [(SQUARE, [])]),
    "identical-reversed-and-rotated": encode(
        [(SQUARE, [])], [([(4, 4), (4, 0), (0, 0), (0, 4)], [])]),
    "identical-with-holes": encode(
        [(BIG, [rect(-2, -2, 2, 2)])], [(BIG, [rect(-2, -2, 2, 2)])]),
    "shared-edge": encode([(SQUARE, [])], [(rect(4, 0, 8, 4), [])]),
    "shared-edge-partial": encode([(SQUARE, [])], [(rect(4, 2, 8, 6), [])]),
    "touching-vertex": encode([(SQUARE, [])], [(rect(4, 4, 8, 8), [])]),
    "vertex-on-edge-outside": encode([(SQUARE, [])], [([(4, 2), (8, 0), (8, 4)], [])]),
    "vertex-on-edge-inside": encode([(SQUARE, [])], [([(4, 2), (1, 1), (1, 3)], [])]),
    "crossing-at-shared-vertex": encode([(SQUARE, [])], [([(4, 4), (2, 1), (6, 1)], [])]),
    "nested-clip-inside": encode([(SQUARE, [])], [(rect(1, 1, 3, 3), [])]),
    "nested-subject-inside": encode([(rect(1, 1, 3, 3), [])], [(SQUARE, [])]),
    "nested-touching-inside": encode([(SQUARE, [])], [([(0, 0), (3, 1), (1, 3)], [])]),
    "clip-covers-subject": encode([(SQUARE, [])], [(BIG, [])]),
    "disjoint": encode([(rect(-8, -8, -4, -4), [])], [(rect(4, 4, 8, 8), [])]),
    "empty-clip": encode([(SQUARE, [])], []),
    "empty-subject": encode([], [(SQUARE, [])]),
    "hole-touches-outer-corner": encode(
        [(BIG, [[(-6, -6), (-2, -4), (-4, -2)]])], [(rect(-8, -8, -3, -3), [])]),
    "hole-touches-outer-clip-apart": encode(
        [(BIG, [[(0, -6), (3, 0), (-3, 0)]])], [(rect(-8, 2, 8, 4), [])]),
    "holes-touch-each-other": encode(
        [(BIG, [rect(-4, -4, 0, 0), rect(0, 0, 4, 4)])], [(rect(-2, -8, 2, 8), [])]),
    "hole-filled-exactly": encode([(BIG, [rect(-2, -2, 2, 2)])], [(rect(-2, -2, 2, 2), [])]),
    "clip-covers-hole": encode([(BIG, [rect(-2, -2, 2, 2)])], [(rect(-3, -3, 3, 3), [])]),
    "clip-hole-around-subject": encode(
        [(rect(-2, -2, 2, 2), [])], [(BIG, [rect(-3, -3, 3, 3)])]),
    "island-in-hole": encode(
        [(BIG, [rect(-4, -4, 4, 4)]), (rect(-2, -2, 2, 2), [])],
        [([(-8, -1), (8, -1), (8, 1), (-8, 1)], [])]),
    "island-touches-hole": encode(
        [(BIG, [rect(-4, -4, 4, 4)]), ([(-4, 0), (0, -2), (2, 0), (0, 2)], [])],
        [(rect(-1, -8, 1, 8), [])]),
    "collinear-overlap": encode([(rect(0, 0, 6, 2), [])], [(rect(3, 0, 8, 2), [])]),
    "collinear-vertices": encode(
        [([(0, 0), (2, 0), (4, 0), (4, 2), (4, 4), (2, 4), (0, 4), (0, 2)], [])],
        [([(2, 0), (6, 2), (2, 4), (-2, 2)], [])]),
    "repeated-vertices": encode(
        [([(0, 0), (0, 0), (4, 0), (4, 4), (4, 4), (0, 4), (0, 0)], [])],
        [(rect(2, 2, 6, 6), [])]),
    "clockwise-inputs": encode(
        [(reversed_loop(BIG), [reversed_loop(rect(-2, -2, 2, 2))])],
        [(reversed_loop(rect(0, -8, 8, 8)), [])]),
    "sliver": encode([(rect(-4, -4, 4, 4), [])], [([(-8, 0), (8, 0), (8, 1)], [])]),
    "sliver-along-edge": encode([(rect(-4, -4, 4, 4), [])], [([(-8, 4), (8, 4), (8, 3)], [])]),
    "concave-u-vs-bar": encode([(U_SHAPE, [])], [(rect(-8, 2, 8, 4), [])]),
    "comb-vs-bar-on-tips": encode([(COMB, [])], [(rect(-8, -2, 8, 6), [])]),
    "star-vs-square-with-hole": encode(
        [(STAR, [[(0, 1), (-1, 0), (0, -1), (1, 0)]])], [(rect(-4, -4, 4, 4), [rect(-1, -1, 1, 1)])]),
    "two-subjects-one-clip": encode(
        [(rect(-6, -2, -2, 2), []), (rect(2, -2, 6, 2), [])], [(rect(-4, -1, 4, 1), [])]),
    "three-clips": encode(
        [(BIG, [])],
        [(rect(-8, -8, -4, -4), []), (rect(-2, -2, 2, 2), []), (rect(4, 4, 8, 8), [])]),
    "fan-ordered-loops": encode(
        [(([(3, 5), (-5, -4), (6, -3), (-2, 6), (0, -7)], True), [])],
        [(([(1, 1), (-2, 2), (0, -3), (-1, 3)], True), [])]),
    "scaled-near-collinear-1e6": encode(
        [(rect(-4, -4, 4, 4), [])], [([(-8, -4), (8, 4), (-8, 5)], [])],
        mode=SCALED, parameter=STEP[0.1] | OFFSET[1e6] << 3),
    "scaled-thirds": encode(
        [(U_SHAPE, [])], [(rect(-8, -2, 8, 6), [rect(-1, 0, 1, 2)])],
        mode=SCALED, parameter=STEP["1/3"] | OFFSET[-0.3] << 3),
    "perturbed-near-touch": encode(
        [(rect(0, 0, 4, 4), [])], [([((4, 1), (2, 3)), (8, 0), (8, 4)], [])],
        mode=PERTURBED, parameter=40),
    "perturbed-sliver": encode(
        [(rect(-4, -4, 4, 4), [])], [([(-8, 0), (8, 0), (0, (0, 1))], [])],
        mode=PERTURBED, parameter=40),
    "raw-doubles": encode(
        [([(0.1, 0.2), (10.5, -3.25), (7.0, 9.125)], [])],
        [([(3.3, -1.0), (12.0, 4.0), (1.0 / 3.0, 8.0)], [])],
        mode=RAW),
    # Regressions: each broke the clipper once (named after what it broke).
    # A hole touching its outer loop at a point inside an outer edge: the output loop
    # passes through that point twice (as a vertex and inside an edge), so it is not simple.
    "hole-touches-outer-inside-not-simple": encode(
        [(BIG, [[(0, -6), (3, 0), (-3, 0)]])], [(rect(-2, -8, 2, 2), [])]),
    "hole-touches-outer-at-outer-vertex-inside-not-simple": encode(
        [([(-6, -6), (0, -6), (6, -6), (6, 6), (-6, 6)], [[(0, -6), (3, 0), (-3, 0)]])],
        [(rect(-2, -8, 2, 2), [])]),
    "hole-touches-outer-twice-outside-not-simple": encode(
        [(rect(-6, -4, 6, 4), [[(-6, 0), (0, -2), (6, 0), (0, 2)]])],
        [(rect(-2, -6, 2, 6), [])]),
    # clip(P, list of clips) clips the rounded outside pieces of one clip by the next; with
    # a clip listed twice the second pass meets edges that graze the first one's.
    "multi-clip-repeated-clip-whole-clip-inside": encode(
        [(BIG, [rect(-2, -2, 2, 2)])], [([(2, 0), (7, -3), (7, 3)], [])]),
    "multi-clip-repeated-clip-sliver-overlaps": encode(
        [(([(3, 5), (-5, -4), (6, -3), (-2, 6), (0, -7)], True), [])],
        [(([(7, 1), (-6, 2), (1, -5), (-1, 7)], True), [])]),
    # The first step of the one above as a plain clip: an edge leaving the point where the
    # hole touches the outer loop grazes a clip edge from that point (they differ by one
    # rounding); the whole clip triangle comes back as inside (area 15 instead of ~0).
    "pinch-point-grazing-edge-whole-clip-inside": encode(
        [([(6.0, 2.4), (6.0, 6.0), (-6.0, 6.0), (-6.0, -6.0), (6.0, -6.0),
           (6.0, -2.4000000000000004), (2.0, 0.0)],
          [[(-2.0, -2.0), (2.0, -2.0), (2.0, 2.0), (-2.0, 2.0)]])],
        [([(2.0, 0.0), (7.0, -3.0), (7.0, 3.0)], [])],
        mode=RAW),
    # The clip's hole touches the clip's outer loop at a corner it shares with the subject
    # (both sets exact on the grid): inside comes back as the whole subject square minus
    # that hole, 18 too much (the triangle (-6,-6) (6,-6) (6,-3) lies outside the clip),
    # and the outside piece is wrong too: inside + outside exceeds the subject by 17.
    "clip-hole-at-shared-corner-wrong-pieces": encode(
        [(rect(-6, -6, 6, 6), [])],
        [([(-6, -6), (6, -3), (6, 6), (-6, 6)], [[(-4, -4), (-4, -2), (-6, -6)]])]),
    # A clip edge through the corner where a hole touches its outer loop: the outside piece
    # runs through that corner twice without a vertex on its second pass.
    "hole-corner-pinch-clip-edge-through-outside-not-simple": encode(
        [(BIG, [[(-6, -6), (-2, -4), (-4, -2)]])], [([(-8, -8), (-3, -3), (-8, -3)], [])]),
    # Thin triangles, a few ulps off degenerate: whole regions land on the wrong side.
    # Here clip(S, C) returns C both as inside and as outside (area 32 each), while S
    # itself has area ~1e-11.
    "thin-subject-whole-clip-inside": encode(
        [([(0.0, -8.0), (-8.0, -7.9999999999990905), (-7.0, -8.0000000000019895)], [])],
        [([(-7.9999999999990905, 8.0000000000004547), (-8.0000000000002842, -7.9999999999998863),
           (-4.0, -4.0)], [])],
        mode=RAW),
    # clip(C, S) with a sliver C: its inside holds S's far vertices (x = 4), outside the
    # sliver; inside + outside exceeds area(C) by 64.
    "sliver-clip-inside-holds-subject": encode(
        [([(-4.0, -4.0), (4.0, -4.0000000000000568), (-8.0000000000000568, -8.0),
           (-3.9999999999990905, 4.0)], [])],
        [([(-7.9999999999995453, 8.0), (-8.0, 0.0), (-7.9999999999995453, -7.9999999999999432)],
          [])],
        mode=RAW),
    # area(S & C) and area(C & S) differ by 1.7.
    "thin-triangles-intersection-not-symmetric": encode(
        [([(-2.0, -8.0), (-3.9999999999999574, -4.0000000000000036), (-8.0000000000000036, -8.0),
           (-4.0, -2.0000000000000036)], [])],
        [([(-8.0, -4.9999999999999716), (-7.9999999999999432, -7.9999999999999964), (1.0, -8.0)],
          [])],
        mode=RAW),
    # Rounded crossings around a near-spike make an outside loop cross itself.
    "near-spike-outside-not-simple": encode(
        [([(-4.0, -4.0), (4.0, -4.0), (-8.0000000000000568, -4.0000000000000568), (-7.0, 4.0)],
          [])],
        [([(-8.0, 0.0), (8.0, 0.0), (0.0, -7.9999999999999432)], [])],
        mode=RAW),
}

# Inputs within the contract that break an invariant of today's clipper, named after what
# they break. They are written to tests/fuzz/findings/, which nothing builds or replays;
# once the clipper handles one, move it to SEEDS.
FINDINGS = {

}


def write_or_check(folder, files, check):
    stale = []
    if not check:
        folder.mkdir(parents=True, exist_ok=True)
    for name, data in sorted(files.items()):
        path = folder / name
        if check:
            if not path.is_file() or path.read_bytes() != data:
                stale.append(name)
        else:
            path.write_bytes(data)
    return stale


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="verify, write nothing")
    here = pathlib.Path(__file__).resolve().parent
    parser.add_argument("--out", type=pathlib.Path, default=here / "corpus" / "clip")
    parser.add_argument("--findings", type=pathlib.Path, default=here / "findings")
    args = parser.parse_args()

    stale = write_or_check(args.out, SEEDS, args.check)
    stale += write_or_check(args.findings, FINDINGS, args.check)
    if stale:
        print("stale files (run make_corpus.py): " + ", ".join(stale), file=sys.stderr)
        return 1
    print(f"{len(SEEDS)} seeds in {args.out}, {len(FINDINGS)} findings in {args.findings}: "
          + ("up to date" if args.check else "written"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
