#!/usr/bin/env python3
"""A copy of a scene with some keys set, written elsewhere: its volume and mesh
files by absolute path, so that the copy loads what the original loads.

  scene_variant.py SRC DST [KEY=JSON | KEY- ...]

KEY is a dotted path ("polygons", "polygon_engine.connection"), JSON its new
value ('[]', '"rle"'); missing objects on the way are made. KEY- removes the
key if it is there ("view.fov-").
"""
import json, os, sys


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    src, dst = sys.argv[1], sys.argv[2]
    scene = json.load(open(src))
    for item in sys.argv[3:]:
        key, eq, value = item.partition("=")
        remove = not eq and key.endswith("-")
        *path, last = (key[:-1] if remove else key).split(".")
        node = scene
        for k in path:
            node = node.setdefault(k, {})
        if remove:
            node.pop(last, None)
        else:
            node[last] = json.loads(value)
    base = os.path.dirname(os.path.abspath(src))
    for item in [scene.get("volume", {})] + scene.get("polygons", []):
        if "file" in item and not os.path.isabs(item["file"]):
            item["file"] = os.path.join(base, item["file"])
    json.dump(scene, open(dst, "w"))


main()
