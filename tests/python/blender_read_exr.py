"""Run inside Blender (blender -b --factory-startup --python tests/python/blender_read_exr.py --
EXR OUTDIR [MATTE_LAYER:NAME ...]): reads a lensrt EXR as Blender's compositor does and
writes what it finds, for tests/python/test_blender_exr.py to compare with the file:
  OUTDIR/passes.json       the Image node's passes (its enabled outputs, in order)
  OUTDIR/<pass>.exr        each pass through a Composite node (float RGBA)
  OUTDIR/matte_<i>.exr     the Cryptomatte node's matte of each LAYER:NAME asked for
Blender 3.4's EXR reader takes a file whose channels have layer names as a multilayer
image: RGBA is its Combined pass, each `<pass>.<channel>` another pass."""

import json
import os
import sys

import bpy

args = sys.argv[sys.argv.index("--") + 1:]
path, out, mattes = args[0], args[1], args[2:]
image = bpy.data.images.load(os.path.abspath(path))
scene = bpy.context.scene
scene.render.engine = "CYCLES"  # renders nothing but the compositor (no objects)
scene.cycles.samples = 1
scene.cycles.use_denoising = False
scene.render.resolution_percentage = 100
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_depth = "32"
scene.render.image_settings.color_mode = "RGBA"
scene.use_nodes = True
tree = scene.node_tree
for node in list(tree.nodes):
    tree.nodes.remove(node)
source = tree.nodes.new("CompositorNodeImage")
source.image = image
composite = tree.nodes.new("CompositorNodeComposite")
composite.use_alpha = True
passes = [o.name for o in source.outputs if o.enabled]
with open(os.path.join(out, "passes.json"), "w") as f:
    json.dump({"passes": passes, "type": image.type}, f)


def write(socket, name):
    tree.links.new(socket, composite.inputs[0])
    scene.render.filepath = os.path.join(out, name + ".exr")
    bpy.ops.render.render(write_still=True)


# The frame's size, from the file (a multilayer image reports 0 x 0 before it is shown).
width, height = (int(v) for v in os.environ["LENSRT_EXR_SIZE"].split("x"))
scene.render.resolution_x, scene.render.resolution_y = width, height
for name in passes:
    write(source.outputs[name], name)
crypto = tree.nodes.new("CompositorNodeCryptomatteV2")
crypto.source = "IMAGE"
crypto.image = image
for i, spec in enumerate(mattes):
    layer, name = spec.split(":", 1)
    crypto.layer_name = layer
    crypto.matte_id = name
    write(crypto.outputs["Matte"], f"matte_{i}")
