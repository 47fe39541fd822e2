#!/usr/bin/env python3
"""Imports a USD recording with Blender (its Python module, bpy) as File > Import > USD does, and prints as
JSON what a test needs: the frame range, the objects Blender made, and the cloth's vertices and each
object's world translation at the asked frames (in Blender's z-up frame: USD's (x, y, z) is (x, -z, y)).

Usage: blender_read.py FILE.usda [FRAME ...]
(optional: scripts/deps --blender makes .venv-blender with bpy 5.0.1, about 1 GB)
"""
import json
import sys

import bpy


def main(path, frames):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    result = bpy.ops.wm.usd_import(filepath=path)
    scene = bpy.context.scene
    out = {"result": sorted(result), "frameStart": scene.frame_start, "frameEnd": scene.frame_end, "objects": {}}
    for frame in frames:
        scene.frame_set(frame)
        depsgraph = bpy.context.evaluated_depsgraph_get()
        for o in bpy.data.objects:
            entry = out["objects"].setdefault(o.name, {"type": o.type, "modifiers": [m.type for m in o.modifiers], "at": {}})
            at = {"translation": list(o.matrix_world.translation)}
            if o.type == "MESH":
                mesh = o.evaluated_get(depsgraph).data
                at["vertices"] = [list(o.matrix_world @ v.co) for v in mesh.vertices]
            entry["at"][str(frame)] = at
    return out


if __name__ == "__main__":
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else sys.argv[1:]
    data = main(argv[0], [int(f) for f in argv[1:]])
    sys.stdout.write("BLENDER-JSON " + json.dumps(data) + "\n")
