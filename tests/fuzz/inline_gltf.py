#!/usr/bin/env python3
"""Seeds for fuzz_gltf: every .gltf/.glb under SRC no larger than MAX bytes
(after inlining), written to DST as one self-contained file each: external
buffers of a .gltf become base64 data URIs; images stay as they are."""
import base64
import json
import os
import sys

src, dst, limit = sys.argv[1], sys.argv[2], int(sys.argv[3])
for root, _, files in os.walk(src):
    for name in sorted(files):
        path = os.path.join(root, name)
        out = os.path.join(dst, "shared_" + os.path.relpath(path, src).replace(os.sep, "_"))
        if name.endswith(".glb"):
            if os.path.getsize(path) <= limit:
                with open(path, "rb") as f, open(out, "wb") as g:
                    g.write(f.read())
            continue
        if not name.endswith(".gltf"):
            continue
        try:
            with open(path, encoding="utf-8") as f:
                doc = json.load(f)
            for buf in doc.get("buffers", []):
                uri = buf.get("uri", "")
                if uri and not uri.startswith("data:"):
                    with open(os.path.join(root, uri), "rb") as b:
                        buf["uri"] = "data:application/octet-stream;base64," + base64.b64encode(b.read()).decode()
            text = json.dumps(doc, separators=(",", ":"))
        except (OSError, ValueError):
            continue
        if len(text) <= limit:
            with open(out, "w", encoding="utf-8") as g:
                g.write(text)
