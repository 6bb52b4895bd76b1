#!/usr/bin/env python3
"""Writes the glTF files of the bad-input corpus (run from anywhere; the files
are committed, this records how each was made). Lens files are hand-written."""
import base64
import copy
import json
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
TRI = [0, 0, 0, 1, 0, 0, 0, 1, 0]
PNG_2x1 = ("iVBORw0KGgoAAAANSUhEUgAAAAIAAAABCAYAAAD0In+KAAAAEUlEQVR4nGNoaGj4z8DAwMAAAA4AAv9j"
           "8TQAAAAASUVORK5CYII=")


def scene(positions=TRI, indices=(0, 1, 2), extra_bytes=b""):
    data = struct.pack("<%df" % len(positions), *positions)
    pos_len = len(data)
    idx = struct.pack("<%dH" % len(indices), *indices)
    data += idx + b"\0" * (-len(idx) % 4) + extra_bytes
    doc = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": len(positions) // 3, "type": "VEC3",
             "min": [min(positions[i::3]) for i in range(3)], "max": [max(positions[i::3]) for i in range(3)]},
            {"bufferView": 1, "componentType": 5123, "count": len(indices), "type": "SCALAR"},
        ],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": pos_len},
            {"buffer": 0, "byteOffset": pos_len, "byteLength": len(idx)},
        ],
        "buffers": [{"byteLength": len(data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
    }
    return doc


def write(name, doc):
    text = doc if isinstance(doc, str) else json.dumps(doc, indent=1)
    with open(os.path.join(HERE, name), "w", encoding="utf-8") as f:
        f.write(text)


def glb(doc):
    body = json.dumps(doc).encode()
    body += b" " * (-len(body) % 4)
    return struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(body)) + struct.pack("<I4s", len(body), b"JSON") + body


good = scene()
write("good-triangle.gltf", good)
write("truncated.gltf", json.dumps(good, indent=1)[:200])

d = copy.deepcopy(good)
d["buffers"][0]["uri"] = "missing-geometry.bin"
write("missing-bin.gltf", d)

d = copy.deepcopy(good)
d["bufferViews"][0]["byteLength"] = 4000
write("buffer-shorter-than-view.gltf", d)

d = copy.deepcopy(good)
d["accessors"][0]["count"] = 5
write("accessor-beyond-view.gltf", d)

d = copy.deepcopy(good)
d["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 9
write("accessor-does-not-exist.gltf", d)

write("index-beyond-vertex-count.gltf", scene(indices=(0, 1, 7)))

nan = struct.unpack("<f", struct.pack("<I", 0x7FC00000))[0]
d = scene(positions=[0, 0, 0, 1, 0, 0, 0, 1, 0])
raw = base64.b64decode(d["buffers"][0]["uri"].split(",")[1])
raw = raw[:12] + struct.pack("<I", 0x7FC00000) + raw[16:]  # x of vertex 1 = NaN
d["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(raw).decode()
write("nan-vertex.gltf", d)

write("huge-coordinates.gltf", scene(positions=[0, 0, 0, 1e20, 0, 0, 0, 1, 0]))

d = copy.deepcopy(good)
d["nodes"][0]["scale"] = [1e16, 1, 1]
write("huge-node-scale.gltf", d)

write("degenerate-only.gltf", scene(positions=[0, 0, 0, 1, 1, 1, 2, 2, 2]))

write("no-meshes.gltf", {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
                         "nodes": [{"name": "empty"}]})

d = copy.deepcopy(good)
d["extensionsUsed"] = d["extensionsRequired"] = ["KHR_draco_mesh_compression"]
write("required-extension.gltf", d)


def textured(image):
    d = scene()
    raw = base64.b64decode(d["buffers"][0]["uri"].split(",")[1])
    raw += struct.pack("<6f", 0, 0, 1, 0, 0, 1)
    d["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(raw).decode()
    d["buffers"][0]["byteLength"] = len(raw)
    d["bufferViews"].append({"buffer": 0, "byteOffset": len(raw) - 24, "byteLength": 24})
    d["accessors"].append({"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"})
    d["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 2
    d["meshes"][0]["primitives"][0]["material"] = 0
    d["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]
    d["textures"] = [{"source": 0}]
    d["images"] = [image]
    return d


write("missing-texture.gltf", textured({"uri": "no-such-texture.png"}))
write("corrupt-texture.gltf", textured({"uri": "data:image/png;base64," +
                                        base64.b64encode(base64.b64decode(PNG_2x1)[:30]).decode()}))

d = copy.deepcopy(good)
d["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0, "znear": 0.1}}]
d["nodes"].append({"camera": 0, "translation": [0, 0, 5]})
d["scenes"][0]["nodes"].append(1)
write("camera-yfov-zero.gltf", d)

d = copy.deepcopy(good)
d["nodes"][0]["children"] = [0]
write("node-cycle.gltf", d)

d = copy.deepcopy(good)
d["asset"]["version"] = "1.0"
write("gltf-version-1.gltf", d)

d = copy.deepcopy(good)
d["accessors"][0]["count"] = 2 ** 31
write("huge-accessor-count.gltf", d)

d = copy.deepcopy(good)
d["nodes"][0]["matrix"] = [1, 0, 0]
write("short-matrix.gltf", d)

d = copy.deepcopy(good)
d["meshes"][0]["primitives"][0]["mode"] = 1  # LINES: nothing to render
write("lines-only.gltf", d)

with open(os.path.join(HERE, "wrong-header.glb"), "wb") as f:
    f.write(b"gLtF" + glb(good)[4:])
with open(os.path.join(HERE, "truncated.glb"), "wb") as f:
    f.write(glb(good)[:-40])
with open(os.path.join(HERE, "glb-version-1.glb"), "wb") as f:
    g = glb(good)
    f.write(g[:4] + struct.pack("<I", 1) + g[8:])
with open(os.path.join(HERE, "empty.gltf"), "w") as f:
    pass


def glb_with_bin(doc, payload, declared_bin_length):
    """A .glb whose BIN chunk header declares `declared_bin_length` bytes."""
    body = json.dumps(doc).encode()
    body += b" " * (-len(body) % 4)
    payload += b"\0" * (-len(payload) % 4)
    total = 12 + 8 + len(body) + 8 + len(payload)
    return (struct.pack("<4sII", b"glTF", 2, total) + struct.pack("<I4s", len(body), b"JSON") + body +
            struct.pack("<I4s", declared_bin_length, b"BIN\0") + payload)


d = copy.deepcopy(good)
payload = base64.b64decode(d["buffers"][0]["uri"].split(",")[1])
d["buffers"][0] = {"byteLength": len(payload) + 8}
with open(os.path.join(HERE, "glb-bin-chunk-overrun.glb"), "wb") as f:
    # The BIN chunk claims 8 bytes more than the file holds (tinygltf 2.7 accepts this).
    f.write(glb_with_bin(d, payload, len(payload) + (-len(payload) % 4) + 8))

d = copy.deepcopy(good)
d["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.1}}]
d["nodes"].append({"name": "far", "camera": 0, "translation": [0, 0, 1e20]})
d["scenes"][0]["nodes"].append(1)
write("camera-far-away.gltf", d)

d = copy.deepcopy(good)
d["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.001}}]
d["nodes"].append({"name": "close", "camera": 0, "translation": [0.2, 0.2, 0.01]})
d["scenes"][0]["nodes"].append(1)
write("camera-touching-surface.gltf", d)

with open(os.path.join(HERE, "png-named-gltf.gltf"), "wb") as f:
    f.write(base64.b64decode(PNG_2x1))  # an image renamed: not a glTF at all

d = copy.deepcopy(good)
d["buffers"][0]["uri"] = "."  # this directory: used to read as an absurd size ("out of memory")
write("buffer-uri-directory.gltf", d)

d = copy.deepcopy(good)  # found by the sanitizer run of the glTF fuzz test (UB: converted to int)
d["extensionsUsed"] = ["EXT_mesh_gpu_instancing"]
d["nodes"][0]["extensions"] = {"EXT_mesh_gpu_instancing": {"attributes": {"TRANSLATION": 1e10}}}
write("instancing-accessor-not-an-index.gltf", d)

d = copy.deepcopy(good)  # found by fuzz_gltf: no inverse, an uncaught exception
d["nodes"][0]["matrix"] = [1, 0, 0, 1, 0, 0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 0]
write("projective-matrix.gltf", d)

d = copy.deepcopy(good)
d["asset"] = {"version": "3.0", "minVersion": "3.0"}
write("gltf-min-version-3.gltf", d)

write("camera-no-meshes.gltf", {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
                                "cameras": [{"type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.1}}],
                                "nodes": [{"name": "flat field", "camera": 0}]})

d = textured({"uri": "data:image/png;base64," + PNG_2x1})
d["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["texCoord"] = 1
write("texcoord-1-missing.gltf", d)

d = textured({"uri": "data:image/png;base64," + PNG_2x1})
d["extensionsUsed"] = ["KHR_texture_transform"]
d["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"] = {
    "KHR_texture_transform": {"offset": [0.5], "rotation": "quarter", "scale": [2, 2]}}
write("texture-transform-malformed.gltf", d)

d = textured({"uri": "data:image/png;base64," + PNG_2x1})
d["samplers"] = [{"wrapS": 12345, "magFilter": 1}]
d["textures"][0]["sampler"] = 0
write("sampler-invalid-modes.gltf", d)

d = textured({"uri": "data:image/png;base64," + PNG_2x1})
d["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = 1  # the SCALAR index accessor
write("color-wrong-type.gltf", d)

# Untrusted scenes (issue 27): a scene reads only files in its own folder;
# each of these URIs is refused before anything is opened.
for name, uri in [("untrusted-absolute-buffer.gltf", "/etc/passwd"),
                  ("untrusted-dotdot-buffer.gltf", "../../../../../../../../etc/passwd"),
                  ("untrusted-percent-dotdot-buffer.gltf", "%2E%2E/%2e%2e/%2E%2E/etc/passwd"),
                  ("untrusted-file-uri-buffer.gltf", "file:///etc/passwd"),
                  ("untrusted-dev-zero-buffer.gltf", "/dev/zero")]:
    d = copy.deepcopy(good)
    d["buffers"][0]["uri"] = uri
    write(name, d)
write("untrusted-absolute-image.gltf", textured({"uri": "/etc/hostname"}))


def png_header(width, height):
    """A PNG signature and IHDR chunk declaring width x height RGBA, then IEND: no pixels."""
    ihdr = b"IHDR" + struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    chunk = struct.pack(">I", 13) + ihdr + struct.pack(">I", zlib.crc32(ihdr))
    return b"\x89PNG\r\n\x1a\n" + chunk + struct.pack(">I", 0) + b"IEND" + struct.pack(">I", zlib.crc32(b"IEND"))


for w, h in [(60000, 60000), (512, 512)]:
    with open(os.path.join(HERE, "header-only-%dx%d.png" % (w, h)), "wb") as f:
        f.write(png_header(w, h))
write("texture-60000x60000.gltf", textured({"uri": "header-only-60000x60000.png"}))
write("texture-512x512.gltf", textured({"uri": "header-only-512x512.png"}))


# EXT_texture_webp: a file that starts as WebP (RIFF, WEBP, a VP8 chunk) and
# holds noise, so it is sent to the OpenImageIO plugin and never decodes.
with open(os.path.join(HERE, "corrupt.webp"), "wb") as f:
    f.write(b"RIFF" + struct.pack("<I", 24) + b"WEBPVP8 " + struct.pack("<I", 12) + bytes(range(1, 10)) +
            b"\x9d\x01\x2a")
d = textured({"uri": "corrupt.webp"})
d["extensionsUsed"] = ["EXT_texture_webp"]
d["textures"] = [{"extensions": {"EXT_texture_webp": {"source": 0}}}]
write("texture-webp-corrupt.gltf", d)
d = textured({"uri": "data:image/png;base64," + PNG_2x1})
d["extensionsUsed"] = ["EXT_texture_webp"]
d["images"].append({"uri": "corrupt.webp"})
d["textures"] = [{"source": 0, "extensions": {"EXT_texture_webp": {"source": 1}}}]
write("texture-webp-with-png-fallback.gltf", d)


# Animation (issue 23): the good triangle with a camera, and one animation (or
# skin) whose data is broken in one way each. Channels that cannot be used are
# skipped with a warning naming them; a skin that cannot be used is an error.
def animated(channels, extra_floats=()):
    """The good triangle seen by a camera, with `channels`: (node, path, times,
    values, components, interpolation) each; extra_floats: more float arrays
    appended as accessors after them (returned indices are in the doc's order)."""
    d = copy.deepcopy(good)
    d["scenes"][0]["nodes"] = [0, 1]
    d["nodes"].append({"camera": 0, "translation": [0.3, 0.3, 3]})
    d["cameras"] = [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}]
    raw = bytearray(base64.b64decode(d["buffers"][0]["uri"].split(",")[1]))

    def accessor(values, components):
        offset = len(raw)
        raw.extend(struct.pack("<%df" % len(values), *values))
        d["bufferViews"].append({"buffer": 0, "byteOffset": offset, "byteLength": 4 * len(values)})
        kind = {1: "SCALAR", 3: "VEC3", 4: "VEC4", 16: "MAT4"}[components]
        d["accessors"].append({"bufferView": len(d["bufferViews"]) - 1, "componentType": 5126,
                               "count": len(values) // components, "type": kind})
        return len(d["accessors"]) - 1

    samplers, targets = [], []
    for node, path, times, values, components, interpolation in channels:
        samplers.append({"input": accessor(times, 1), "output": accessor(values, components),
                         "interpolation": interpolation})
        targets.append({"sampler": len(samplers) - 1, "target": {"node": node, "path": path}})
    extra = [accessor(values, components) for values, components in extra_floats]
    if samplers:
        d["animations"] = [{"name": "move", "samplers": samplers, "channels": targets}]
    d["buffers"][0] = {"byteLength": len(raw),
                       "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(raw)).decode()}
    return d, extra


inf = float("inf")
slide = (0, "translation", [0, 1], [0, 0, 0, 0.5, 0, 0], 3, "LINEAR")
write("animation-time-not-finite.gltf", animated([(0, "translation", [0, inf], [0, 0, 0, 0.5, 0, 0], 3,
                                                   "LINEAR")])[0])
write("animation-output-count-wrong.gltf", animated([(0, "translation", [0, 1, 2], [0, 0, 0, 0.5, 0, 0], 3,
                                                      "LINEAR")])[0])
write("animation-unknown-path.gltf", animated([(0, "colour", [0, 1], [0, 0, 0, 0.5, 0, 0], 3, "LINEAR")])[0])
write("animation-missing-node.gltf", animated([(7, "translation", [0, 1], [0, 0, 0, 0.5, 0, 0], 3,
                                                "LINEAR")])[0])
# A skin over one joint (node 2) whose inverse bind matrices number two.
identity = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]
d, (joints, weights, binds) = animated([slide], [([0, 0, 0, 0] * 3, 4), ([0.5, 0, 0, 0] * 3, 4),
                                                 (identity * 2, 16)])
# JOINTS_0 as unsigned bytes: the float zeros' bytes read as joint 0 for every vertex.
d["accessors"][joints]["componentType"] = 5121
d["nodes"][0]["skin"] = 0
d["nodes"].append({"name": "bone"})
d["scenes"][0]["nodes"].append(2)
d["meshes"][0]["primitives"][0]["attributes"].update({"JOINTS_0": joints, "WEIGHTS_0": weights})
d["skins"] = [{"joints": [2], "inverseBindMatrices": binds}]
write("skin-inverse-bind-count-wrong.gltf", d)
# The same skin with one bind matrix, and weights that sum to 0.5: normalised with a warning.
d["accessors"][binds]["count"] = 1
write("skin-weights-not-normalised.gltf", d)
