"""Runs inside Blender (tests/python/test_flow.py starts it): renders with Cycles the
plane of test_flow.plane_scene, moving at (vx, vy) m/s 2 m ahead of a camera at the
origin looking down -z, and writes the frame's Vector pass to an uncompressed
multilayer EXR.

    blender -b --factory-startup -P blender_vector_pass.py -- OUT.exr W H YFOV VX VY FRAME
"""

import sys

import bpy

out, width, height, yfov, vx, vy, frame = sys.argv[sys.argv.index("--") + 1:]
Z, FPS = 2.0, 24
bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.engine = "CYCLES"
scene.cycles.samples = 1
scene.cycles.use_denoising = False
scene.render.resolution_x, scene.render.resolution_y = int(width), int(height)
scene.render.resolution_percentage = 100
scene.render.fps = FPS
scene.render.use_motion_blur = False
camera = bpy.data.cameras.new("camera")
camera.sensor_fit = "VERTICAL"
camera.angle_y = float(yfov)
node = bpy.data.objects.new("camera", camera)  # at the origin, looking down -z, +y up
scene.collection.objects.link(node)
scene.camera = node
bpy.ops.mesh.primitive_plane_add(size=6, location=(0, 0, -Z))
plane = bpy.context.active_object
for f in (0, 240):
    plane.location = (float(vx) * f / FPS, float(vy) * f / FPS, -Z)
    plane.keyframe_insert("location", frame=f)
for curve in plane.animation_data.action.fcurves:
    for key in curve.keyframe_points:
        key.interpolation = "LINEAR"
scene.view_layers[0].use_pass_vector = True
settings = scene.render.image_settings
settings.file_format, settings.color_depth, settings.exr_codec = "OPEN_EXR_MULTILAYER", "32", "NONE"
scene.frame_set(int(frame))
scene.render.filepath = out
bpy.ops.render.render(write_still=True)
