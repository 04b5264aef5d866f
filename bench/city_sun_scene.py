#!/usr/bin/env python3
"""The procedural city's database (output_bench --write-database=city:...) as a scene at
Greenwich with one sun path, "path", from FROM to TO every STEP_MIN minutes: each part of
a face a polygon of its own. Prints the middle of the city's bounding box in x and y and
a height above its top by its width, where a camera looks straight down from.

    city_sun_scene.py CITY_DB SCENE FROM TO STEP_MIN
"""
import json
import sys

db = json.load(open(sys.argv[1]))
polygons = []
lo = [float("inf")] * 3
hi = [float("-inf")] * 3
for face in db["faces"]:
    for k, part in enumerate(face["parts"]):
        suffix = "" if len(face["parts"]) == 1 else "/%d" % k
        polygons.append({"id": (face["id"] + suffix).replace("/", "."), "outer": part["outer"], "holes": part["holes"]})
        for p in part["outer"]:
            lo = [min(a, b) for a, b in zip(lo, p)]
            hi = [max(a, b) for a, b in zip(hi, p)]
scene = {"format": "shadowgen-scene/1", "polygons": polygons,
         "site": {"latitude_deg": 51.4779, "longitude_deg": -0.0015, "utc_offset_h": 0},
         "lights": [{"id": "path", "type": "sun", "from": sys.argv[3], "to": sys.argv[4],
                     "step_min": int(sys.argv[5])}]}
json.dump(scene, open(sys.argv[2], "w"))
print("%r %r %r" % ((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, hi[2] + 1 + (hi[0] - lo[0])))
