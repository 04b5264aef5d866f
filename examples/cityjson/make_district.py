#!/usr/bin/env python3
"""Writes a small made-up district as CityJSON 2.0 (district.city.json) and as CityJSONSeq
(district.city.jsonl), the same city objects in both.

Everything here is the project's own: the geometry is made up by this script, placed in
Amersfoort / RD New + NAP height (EPSG:7415) coordinates near Delft, the Netherlands, so
that shadowgen derives the site (latitude, longitude, grid convergence) from the file.

  python3 examples/cityjson/make_district.py [OUT_FOLDER]   # default: beside this script

What it holds (CityJSON 2.0 specification, https://www.cityjson.org/specs/2.0.1/):
  - ground:       a TINRelief, one square 160 m a side (CompositeSurface, LoD 1);
  - gabled-house: a Building with an LoD 1.2 block and an LoD 2.2 gabled Solid whose
                  surfaces carry semantics (GroundSurface, WallSurface, RoofSurface);
  - flats:        a Building of LoD 1.2 only, a flat-roofed block 15 m tall;
  - church:       a Building without geometry of its own and two BuildingParts, its
                  nave (LoD 2.2, gabled) and its tower (LoD 2.2, a box 24 m tall);
  - tree-1..4:    SolitaryVegetationObjects, each a GeometryInstance of one tree template
                  (a trunk and a crown, LoD 1) scaled and placed at its own point.
Vertices are integers of a 1 mm transform, as real CityJSON files store them.
"""

import json
import os
import sys

ORIGIN = (84500.0, 447200.0, -0.4)  # RD x, y and NAP height of the district's corner
SCALE = 0.001


class Model:
    def __init__(self):
        self.vertices = []
        self.index = {}

    def vertex(self, x, y, z):
        """The index of the local point (x, y, z) in metres, quantized to the transform."""
        key = tuple(round(c / SCALE) for c in (x, y, z))
        if key not in self.index:
            self.index[key] = len(self.vertices)
            self.vertices.append(list(key))
        return self.index[key]

    def ring(self, points):
        return [self.vertex(*p) for p in points]


def box_surfaces(x0, y0, z0, x1, y1, z1):
    """The six surfaces of a box, each counter-clockwise seen from outside: ground, roof,
    then the walls facing -y, +x, +y, -x."""
    p = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
         (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    order = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
    kinds = ["GroundSurface", "RoofSurface"] + ["WallSurface"] * 4
    return [[p[i] for i in face] for face in order], kinds


def gabled_surfaces(x0, y0, x1, y1, z0, eaves, ridge):
    """A house with its ridge along x at mid y: ground, four walls (two gables), two roof
    slopes, each counter-clockwise seen from outside."""
    ym = 0.5 * (y0 + y1)
    p0, p1, p2, p3 = (x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0)
    p4, p5, p6, p7 = (x0, y0, eaves), (x1, y0, eaves), (x1, y1, eaves), (x0, y1, eaves)
    r0, r1 = (x0, ym, ridge), (x1, ym, ridge)
    surfaces = [
        [p0, p3, p2, p1],          # ground
        [p0, p1, p5, p4],          # south wall
        [p1, p2, p6, r1, p5],      # east gable
        [p2, p3, p7, p6],          # north wall
        [p3, p0, p4, r0, p7],      # west gable
        [p4, p5, r1, r0],          # south roof
        [p6, p7, r0, r1],          # north roof
    ]
    kinds = ["GroundSurface"] + ["WallSurface"] * 4 + ["RoofSurface"] * 2
    return surfaces, kinds


def solid(model, lod, surfaces_and_kinds):
    surfaces, kinds = surfaces_and_kinds
    types = sorted(set(kinds))
    return {
        "type": "Solid",
        "lod": lod,
        "boundaries": [[[model.ring(s)] for s in surfaces]],
        "semantics": {
            "surfaces": [{"type": t} for t in types],
            "values": [[types.index(k) for k in kinds]],
        },
    }


def plain_solid(model, lod, surfaces_and_kinds):
    surfaces, _ = surfaces_and_kinds
    return {"type": "Solid", "lod": lod, "boundaries": [[[model.ring(s)] for s in surfaces]]}


def tree_template():
    """A tree 1 unit = 1 m: a trunk 0.3 m square, 2.5 m tall (its four sides), and a crown,
    an octahedron 4 m across from 2.5 m to 7.5 m up."""
    vertices = []

    def v(x, y, z):
        vertices.append([x, y, z])
        return len(vertices) - 1

    t = 0.15
    trunk = [v(-t, -t, 0), v(t, -t, 0), v(t, t, 0), v(-t, t, 0),
             v(-t, -t, 2.5), v(t, -t, 2.5), v(t, t, 2.5), v(-t, t, 2.5)]
    sides = [(0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
    e, n, w, s = v(2, 0, 5), v(0, 2, 5), v(-2, 0, 5), v(0, -2, 5)
    top, bottom = v(0, 0, 7.5), v(0, 0, 2.5)
    crown = [(e, n, top), (n, w, top), (w, s, top), (s, e, top),
             (n, e, bottom), (w, n, bottom), (s, w, bottom), (e, s, bottom)]
    boundaries = [[[trunk[i] for i in side]] for side in sides] + [[list(f)] for f in crown]
    geometry = {
        "type": "MultiSurface",
        "lod": "1",
        "boundaries": boundaries,
        "semantics": {"surfaces": [{"type": "+Trunk"}, {"type": "+Crown"}],
                      "values": [0] * 4 + [1] * 8},
    }
    return geometry, vertices


def district():
    model = Model()
    objects = {}
    objects["ground"] = {"type": "TINRelief", "geometry": [{
        "type": "CompositeSurface", "lod": "1",
        "boundaries": [[model.ring([(0, 0, 0), (160, 0, 0), (160, 160, 0), (0, 160, 0)])]]}]}
    objects["gabled-house"] = {
        "type": "Building",
        "attributes": {"function": "residential", "roofType": "gabled", "yearOfConstruction": 1931},
        "geometry": [
            plain_solid(model, "1.2", box_surfaces(30, 40, 0, 42, 50, 8.5)),
            solid(model, "2.2", gabled_surfaces(30, 40, 42, 50, 0, 6, 10.5)),
        ]}
    objects["flats"] = {
        "type": "Building",
        "attributes": {"function": "residential", "storeysAboveGround": 5},
        "geometry": [plain_solid(model, "1.2", box_surfaces(70, 30, 0, 110, 42, 15))]}
    objects["church"] = {"type": "Building", "attributes": {"function": "religious"},
                         "children": ["church-nave", "church-tower"]}
    objects["church-nave"] = {"type": "BuildingPart", "parents": ["church"], "geometry": [
        solid(model, "2.2", gabled_surfaces(60, 90, 90, 104, 0, 9, 16))]}
    objects["church-tower"] = {"type": "BuildingPart", "parents": ["church"], "geometry": [
        solid(model, "2.2", box_surfaces(90, 92, 0, 100, 102, 24))]}
    for i, (x, y, size) in enumerate([(20, 20, 1.0), (50, 20, 1.2), (120, 70, 1.5),
                                      (30, 110, 0.8)], start=1):
        objects[f"tree-{i}"] = {"type": "SolitaryVegetationObject", "geometry": [{
            "type": "GeometryInstance", "template": 0,
            "boundaries": [model.vertex(x, y, 0)],
            "transformationMatrix": [size, 0, 0, 0, 0, size, 0, 0, 0, 0, size, 0, 0, 0, 0, 1]}]}
    template, template_vertices = tree_template()
    return model, objects, template, template_vertices


def header():
    return {
        "type": "CityJSON",
        "version": "2.0",
        "transform": {"scale": [SCALE] * 3, "translate": list(ORIGIN)},
        "metadata": {
            "title": "A made-up district near Delft, written by shadowgen's make_district.py",
            "referenceSystem": "https://www.opengis.net/def/crs/EPSG/0/7415",
        },
    }


def write_city_json(path, model, objects, template, template_vertices):
    """One CityJSON object: one city object a line, one vertex a line."""
    top = header()
    lines = ["{"]
    for key, value in top.items():
        lines.append(f" {json.dumps(key)}: {json.dumps(value)},")
    lines.append(' "geometry-templates": {"templates": [' + json.dumps(template) + '],')
    lines.append('  "vertices-templates": ' + json.dumps(template_vertices) + "},")
    lines.append(' "CityObjects": {')
    items = [f"  {json.dumps(k)}: {json.dumps(v)}" for k, v in objects.items()]
    lines.append(",\n".join(items))
    lines.append(" },")
    lines.append(' "vertices": [')
    lines.append(",\n".join("  " + json.dumps(v) for v in model.vertices))
    lines.append(" ]")
    lines.append("}")
    with open(path, "w", encoding="utf-8") as out:
        out.write("\n".join(lines) + "\n")


def write_city_json_seq(path, model, objects, template, template_vertices):
    """CityJSONSeq: the header line (transform, metadata, templates), then one feature a
    line, each a first-level object with its children and its own vertices."""
    top = header()
    top["geometry-templates"] = {"templates": [template], "vertices-templates": template_vertices}
    top["CityObjects"] = {}
    top["vertices"] = []
    lines = [json.dumps(top)]
    for key, value in objects.items():
        if "parents" in value:
            continue
        members = [key] + value.get("children", [])
        local = {}
        vertices = []

        def renumber(node):
            if isinstance(node, list):
                return [renumber(n) for n in node]
            if node not in local:
                local[node] = len(vertices)
                vertices.append(model.vertices[node])
            return local[node]

        feature_objects = {}
        for member in members:
            o = json.loads(json.dumps(objects[member]))
            for g in o.get("geometry", []):
                g["boundaries"] = renumber(g["boundaries"])
            feature_objects[member] = o
        lines.append(json.dumps({"type": "CityJSONFeature", "id": key,
                                 "CityObjects": feature_objects, "vertices": vertices}))
    with open(path, "w", encoding="utf-8") as out:
        out.write("\n".join(lines) + "\n")


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    model, objects, template, template_vertices = district()
    write_city_json(os.path.join(folder, "district.city.json"), model, objects, template,
                    template_vertices)
    write_city_json_seq(os.path.join(folder, "district.city.jsonl"), model, objects, template,
                        template_vertices)


if __name__ == "__main__":
    main()
