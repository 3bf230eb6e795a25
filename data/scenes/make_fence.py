#!/usr/bin/env python3
"""Writes the alpha-tested fence scene of data/scenes (deterministic, no third-party modules):

    python3 data/scenes/make_fence.py    # rewrites fence.gltf, fence.bin and fence_holes.png here

A fence of one quad (4 x 2.5 units, standing on the ground at z = 0) whose base colour texture's alpha
cuts a grid of square holes under a solid top rail (glTF alphaMode MASK, alphaCutoff 0.5), a ground
quad, a low sun behind the fence throwing its shadow toward the camera, and the camera.

The texture is 64 x 40 texels: the top 8 rows the rail (alpha 1), then 4 rows of 8 cells of 8 x 8 texels,
each with a 5 x 5 hole (alpha 0) at texels 2..6 of the cell (bars 3 texels wide). glTF's texture
coordinates put (0, 0) at the image's top-left corner: the rail is along the fence's top edge.
"""
import json
import math
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))

TEXTURE_WIDTH, TEXTURE_HEIGHT = 64, 40
RAIL_ROWS, CELL, HOLE_FIRST, HOLE_LAST = 8, 8, 2, 6
FENCE_HALF_WIDTH, FENCE_BOTTOM, FENCE_TOP = 2.0, 0.0, 2.5
GROUND_HALF = 6.0
SUN_TRAVELS = (0.25, -0.8, 0.9)  # the way the light travels: down, toward +z (the camera's side)


def hole_alpha(x, y):
    """255 on the fence, 0 in a hole; y counts rows from the image's top."""
    if y < RAIL_ROWS:
        return 255
    cx, cy = x % CELL, (y - RAIL_ROWS) % CELL
    return 0 if HOLE_FIRST <= cx <= HOLE_LAST and HOLE_FIRST <= cy <= HOLE_LAST else 255


def png_rgba(width, height, alpha_of):
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    rows = b"".join(b"\x00" + b"".join(bytes((110, 84, 60, alpha_of(x, y))) for x in range(width))
                    for y in range(height))
    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)  # 8 bits, RGBA
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b"")


def normalized(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def node_matrix(position, forward, up_hint):
    """Column-major 4x4 whose -z is `forward` (glTF cameras and lights look down their -z)."""
    back = normalized([-c for c in forward])
    right = normalized(cross(up_hint, back))
    up = cross(back, right)
    return [round(c, 6) + 0.0 for c in right + [0] + up + [0] + back + [0] + list(position) + [1]]


def main():
    fence_positions = [(-FENCE_HALF_WIDTH, FENCE_BOTTOM, 0.0), (FENCE_HALF_WIDTH, FENCE_BOTTOM, 0.0),
                       (FENCE_HALF_WIDTH, FENCE_TOP, 0.0), (-FENCE_HALF_WIDTH, FENCE_TOP, 0.0)]
    fence_uvs = [(0.0, 1.0), (1.0, 1.0), (1.0, 0.0), (0.0, 0.0)]  # v down the image
    ground_positions = [(-GROUND_HALF, 0.0, -GROUND_HALF), (-GROUND_HALF, 0.0, GROUND_HALF),
                        (GROUND_HALF, 0.0, GROUND_HALF), (GROUND_HALF, 0.0, -GROUND_HALF)]
    quad = [0, 1, 2, 0, 2, 3]
    parts = [b"".join(struct.pack("<3f", *p) for p in fence_positions),
             b"".join(struct.pack("<2f", *t) for t in fence_uvs),
             struct.pack("<6H", *quad) + b"\x00\x00",
             b"".join(struct.pack("<3f", *p) for p in ground_positions),
             struct.pack("<6H", *quad) + b"\x00\x00"]
    views, offset = [], 0
    for part in parts:
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(part)})
        offset += len(part)
    binary = b"".join(parts)
    views[2]["byteLength"] = views[4]["byteLength"] = 12

    def bounds(points):
        return {"min": [min(p[i] for p in points) for i in range(3)],
                "max": [max(p[i] for p in points) for i in range(3)]}

    accessors = [
        {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", **bounds(fence_positions)},
        {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC2"},
        {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"},
        {"bufferView": 3, "componentType": 5126, "count": 4, "type": "VEC3", **bounds(ground_positions)},
        {"bufferView": 4, "componentType": 5123, "count": 6, "type": "SCALAR"},
    ]
    camera_position = (1.5, 3.2, 8.5)
    camera_target = (0.0, 0.4, 1.6)
    gltf = {
        "asset": {"version": "2.0", "generator": "ShadowLab data/scenes/make_fence.py: an alpha-tested fence"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [{"name": "sun", "type": "directional"}]}},
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2, 3]}],
        "nodes": [
            {"name": "fence", "mesh": 0},
            {"name": "ground", "mesh": 1},
            {"name": "sun", "matrix": node_matrix((0.0, 10.0, 0.0), normalized(SUN_TRAVELS), [0.0, 0.0, 1.0]),
             "extensions": {"KHR_lights_punctual": {"light": 0}}},
            {"name": "camera", "camera": 0,
             "matrix": node_matrix(camera_position,
                                   normalized([t - p for t, p in zip(camera_target, camera_position)]),
                                   [0.0, 1.0, 0.0])},
        ],
        "cameras": [{"type": "perspective",
                     "perspective": {"yfov": 0.75, "aspectRatio": 1.7778, "znear": 0.1, "zfar": 40.0}}],
        "meshes": [
            {"name": "fence", "primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2,
                                              "material": 0}]},
            {"name": "ground", "primitives": [{"attributes": {"POSITION": 3}, "indices": 4, "material": 1}]},
        ],
        "materials": [
            {"name": "fence", "alphaMode": "MASK", "alphaCutoff": 0.5, "doubleSided": True,
             "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}},
            {"name": "ground", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1.0]}},
        ],
        "samplers": [{"magFilter": 9728, "minFilter": 9728}],  # NEAREST: texels as ShadowLab tests them
        "textures": [{"sampler": 0, "source": 0}],
        "images": [{"uri": "fence_holes.png"}],
        "buffers": [{"uri": "fence.bin", "byteLength": len(binary)}],
        "bufferViews": views,
        "accessors": accessors,
    }
    with open(os.path.join(HERE, "fence.bin"), "wb") as out:
        out.write(binary)
    with open(os.path.join(HERE, "fence_holes.png"), "wb") as out:
        out.write(png_rgba(TEXTURE_WIDTH, TEXTURE_HEIGHT, hole_alpha))
    with open(os.path.join(HERE, "fence.gltf"), "w") as out:
        json.dump(gltf, out, indent=1)
        out.write("\n")


if __name__ == "__main__":
    main()
