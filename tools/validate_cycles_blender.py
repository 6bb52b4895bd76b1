"""Runs inside Blender (tools/validate-cycles starts it): renders one glTF scene with
Cycles the way lensrt's pinhole sees it, then compares the two images.

    blender -b --factory-startup -P tools/validate_cycles_blender.py -- JOB.json

JOB.json names the scene, lensrt's EXR (whose metadata gave the camera), the settings
and the output paths. Every material is rebuilt as a node graph that follows the glTF
2.0 appendix's BRDF instead of the importer's Principled BSDF, whose diffuse and
specular layers are not glTF's (on rough dielectrics it renders about 18% brighter than
Lambert). What Cycles' nodes cannot say exactly is listed in DEPARTURES and printed.
"""

import json
import math
import sys

import bpy
import numpy as np

DEPARTURES = [
    "dielectric Fresnel: Cycles' Fresnel node (exact, at n.v) instead of Schlick at v.h",
    "metal: GGX tinted by the base colour (no Schlick rise toward grazing angles)",
    "diffuse under the specular layer: 1 - F(n.v) instead of lensrt's 1 - albedo",
    "transmission: a Glass BSDF mixed in by the transmission factor",
    "KHR_materials_specular: its specularFactor scales the Fresnel weight; textures and "
    "specularColorFactor are left out",
    "clearcoat: a white GGX mixed in by clearcoat * Fresnel(n.v) (lensrt: by its albedo)",
    "sheen: the importer's Velvet BSDF added on top (lensrt: Charlie sheen, the layer under "
    "it scaled down by the sheen's albedo)",
]


def job():
    argv = sys.argv[sys.argv.index("--") + 1:]
    with open(argv[0]) as f:
        return json.load(f)


def import_scene(path):
    # Blender 3.4's importer still says dtype=np.bool, which numpy 1.24 removed.
    if "bool" not in np.__dict__:
        np.bool = bool
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=path)


def specular_factors(path):
    """{material name: KHR_materials_specular specularFactor} from the glTF's JSON
    (Blender 3.4's importer does not carry the factor into its graph)."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:4] == b"glTF":  # GLB: the JSON chunk follows the 12-byte header
        length = int.from_bytes(data[12:16], "little")
        data = data[20:20 + length]
    doc = json.loads(data)
    factors = {}
    for i, m in enumerate(doc.get("materials", [])):
        ext = m.get("extensions", {}).get("KHR_materials_specular")
        if ext is not None:
            factors[m.get("name", f"material_{i}")] = float(ext.get("specularFactor", 1.0))
    return factors


def linked_or_value(tree, socket, target):
    """Feeds `target` from what fed the Principled socket: its link, else its value."""
    if socket.is_linked:
        tree.links.new(socket.links[0].from_socket, target)
    elif hasattr(target, "default_value"):
        target.default_value = socket.default_value


def rebuild_material(mat, specular_factor=1.0):
    """Replaces the importer's Principled BSDF by the glTF appendix B graph:
    mix(metallic, fresnel_mix(1.5, diffuse, ggx), ggx tinted by base colour),
    plus emission, alpha and transmission, reusing the importer's texture nodes."""
    tree = mat.node_tree
    principled = next((n for n in tree.nodes if n.type == "BSDF_PRINCIPLED"), None)
    output = next((n for n in tree.nodes if n.type == "OUTPUT_MATERIAL"), None)
    if principled is None or output is None:
        return False
    nodes, links, inp = tree.nodes, tree.links, principled.inputs

    def node(kind, **values):
        n = nodes.new(kind)
        for k, v in values.items():
            setattr(n, k, v)
        return n

    diffuse = node("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Roughness"].default_value = 0.0
    linked_or_value(tree, inp["Base Color"], diffuse.inputs["Color"])
    specular = node("ShaderNodeBsdfGlossy", distribution="GGX")
    specular.inputs["Color"].default_value = (1, 1, 1, 1)
    linked_or_value(tree, inp["Roughness"], specular.inputs["Roughness"])
    metal = node("ShaderNodeBsdfGlossy", distribution="GGX")
    linked_or_value(tree, inp["Base Color"], metal.inputs["Color"])
    linked_or_value(tree, inp["Roughness"], metal.inputs["Roughness"])
    fresnel = node("ShaderNodeFresnel")
    linked_or_value(tree, inp["IOR"], fresnel.inputs["IOR"])
    for shader in (diffuse, specular, metal, fresnel):
        if inp["Normal"].is_linked:
            links.new(inp["Normal"].links[0].from_socket, shader.inputs["Normal"])

    base = diffuse.outputs["BSDF"]
    transmission = inp["Transmission"]
    if transmission.is_linked or transmission.default_value > 0:
        glass = node("ShaderNodeBsdfGlass", distribution="GGX")
        linked_or_value(tree, inp["Roughness"], glass.inputs["Roughness"])
        linked_or_value(tree, inp["IOR"], glass.inputs["IOR"])
        linked_or_value(tree, inp["Base Color"], glass.inputs["Color"])
        mix = node("ShaderNodeMixShader")
        linked_or_value(tree, transmission, mix.inputs["Fac"])
        links.new(base, mix.inputs[1])
        links.new(glass.outputs["BSDF"], mix.inputs[2])
        base = mix.outputs["Shader"]

    dielectric = node("ShaderNodeMixShader")
    if specular_factor != 1.0:
        weight = node("ShaderNodeMath", operation="MULTIPLY")
        links.new(fresnel.outputs["Fac"], weight.inputs[0])
        weight.inputs[1].default_value = specular_factor
        links.new(weight.outputs["Value"], dielectric.inputs["Fac"])
    else:
        links.new(fresnel.outputs["Fac"], dielectric.inputs["Fac"])
    links.new(base, dielectric.inputs[1])
    links.new(specular.outputs["BSDF"], dielectric.inputs[2])
    surface = node("ShaderNodeMixShader")
    linked_or_value(tree, inp["Metallic"], surface.inputs["Fac"])
    links.new(dielectric.outputs["Shader"], surface.inputs[1])
    links.new(metal.outputs["BSDF"], surface.inputs[2])
    result = surface.outputs["Shader"]

    # KHR_materials_clearcoat (the importer fills the Principled clearcoat inputs):
    # a white GGX of ior 1.5 over the rest, mixed in by clearcoat * Fresnel(n.v),
    # glTF's own layering formula.
    coat_weight = inp["Clearcoat"]
    if coat_weight.is_linked or coat_weight.default_value > 0:
        coat = node("ShaderNodeBsdfGlossy", distribution="GGX")
        coat.inputs["Color"].default_value = (1, 1, 1, 1)
        linked_or_value(tree, inp["Clearcoat Roughness"], coat.inputs["Roughness"])
        coat_fresnel = node("ShaderNodeFresnel")
        coat_fresnel.inputs["IOR"].default_value = 1.5
        if inp["Clearcoat Normal"].is_linked:
            for shader in (coat, coat_fresnel):
                links.new(inp["Clearcoat Normal"].links[0].from_socket, shader.inputs["Normal"])
        fac = node("ShaderNodeMath", operation="MULTIPLY")
        linked_or_value(tree, coat_weight, fac.inputs[0])
        links.new(coat_fresnel.outputs["Fac"], fac.inputs[1])
        coated = node("ShaderNodeMixShader")
        links.new(fac.outputs["Value"], coated.inputs["Fac"])
        links.new(result, coated.inputs[1])
        links.new(coat.outputs["BSDF"], coated.inputs[2])
        result = coated.outputs["Shader"]
    # KHR_materials_sheen: the importer adds a Velvet BSDF (Cycles has no Charlie
    # sheen) to the Principled's output; keep it, added on top.
    velvet = next((n for n in tree.nodes if n.type == "BSDF_VELVET"), None)
    if velvet is not None:
        with_sheen = node("ShaderNodeAddShader")
        links.new(result, with_sheen.inputs[0])
        links.new(velvet.outputs["BSDF"], with_sheen.inputs[1])
        result = with_sheen.outputs["Shader"]

    emission = node("ShaderNodeEmission")
    linked_or_value(tree, inp["Emission"], emission.inputs["Color"])
    linked_or_value(tree, inp["Emission Strength"], emission.inputs["Strength"])
    add = node("ShaderNodeAddShader")
    links.new(result, add.inputs[0])
    links.new(emission.outputs["Emission"], add.inputs[1])
    result = add.outputs["Shader"]

    alpha = inp["Alpha"]
    if alpha.is_linked or alpha.default_value < 1:
        transparent = node("ShaderNodeBsdfTransparent")
        cut = node("ShaderNodeMixShader")
        linked_or_value(tree, alpha, cut.inputs["Fac"])
        links.new(transparent.outputs["BSDF"], cut.inputs[1])
        links.new(result, cut.inputs[2])
        result = cut.outputs["Shader"]
    links.new(result, output.inputs["Surface"])
    nodes.remove(principled)
    return True


def place_camera(j):
    """lensrt's camera, from its EXR metadata: glTF world (+Y up) to Blender's (+Z up)."""
    m = j["world_from_camera"]
    gltf = np.array(m, dtype=float).reshape(4, 4)
    to_blender = np.array([[1, 0, 0, 0], [0, 0, -1, 0], [0, 1, 0, 0], [0, 0, 0, 1]], dtype=float)
    world = to_blender @ gltf
    data = bpy.data.cameras.new("lensrt")
    data.sensor_fit = "VERTICAL"
    data.sensor_width, data.sensor_height = j["sensor_mm"]
    data.lens = j["focal_length_mm"]
    data.clip_start = 1e-3
    data.clip_end = 1e6
    cam = bpy.data.objects.new("lensrt", data)
    bpy.context.scene.collection.objects.link(cam)
    import mathutils

    cam.matrix_world = mathutils.Matrix(world.tolist())
    bpy.context.scene.camera = cam


def configure(j):
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    c = scene.cycles
    c.device = "CPU"
    c.samples = j["spp"]
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.seed = 0
    # lensrt's --max-depth counts scattering events (1 = direct light); Cycles'
    # bounces count what comes after the first hit (0 = direct light).
    bounces = max(j["max_depth"] - 1, 0)
    c.max_bounces = bounces
    c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = c.volume_bounces = bounces
    c.transparent_max_bounces = 64
    c.sample_clamp_direct = c.sample_clamp_indirect = 0.0
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    c.caustics_reflective = c.caustics_refractive = True
    c.blur_glossy = 0.0
    scene.render.threads_mode = "FIXED"
    scene.render.threads = j["threads"]
    scene.render.resolution_x, scene.render.resolution_y = j["width"], j["height"]
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = False
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0
    scene.view_settings.gamma = 1
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    scene.render.image_settings.color_mode = "RGBA"
    world = bpy.data.worlds.new("constant")
    world.use_nodes = True
    background = world.node_tree.nodes["Background"]
    background.inputs["Color"].default_value = (*j["env"], 1)
    background.inputs["Strength"].default_value = 1.0
    scene.world = world


def load_rgb(path):
    img = bpy.data.images.load(path)
    w, h = img.size
    px = np.array(img.pixels[:], dtype=np.float64).reshape(h, w, 4)[::-1, :, :3]
    bpy.data.images.remove(img)
    return px


def save_png(path, rgb):
    h, w, _ = rgb.shape
    v = np.clip(rgb, 0, 1)
    srgb = np.where(v <= 0.0031308, 12.92 * v, 1.055 * np.power(v, 1 / 2.4) - 0.055)
    img = bpy.data.images.new("side", w, h, alpha=False)
    img.colorspace_settings.name = "Non-Color"
    rgba = np.concatenate([srgb, np.ones((h, w, 1))], axis=2)[::-1].ravel()
    img.pixels[:] = rgba.tolist()
    img.filepath_raw = path
    img.file_format = "PNG"
    img.save()


def compare(j):
    a, b = load_rgb(j["lensrt_exr"]), load_rgb(j["cycles_exr"])
    if a.shape != b.shape:
        raise SystemExit(f"validate-cycles: sizes differ: lensrt {a.shape} vs Cycles {b.shape}")
    h, w = (a.shape[0] // 4) * 4, (a.shape[1] // 4) * 4

    def blocks(x):  # 4x4 block means: most of the Monte Carlo noise averages out
        return x[:h, :w].reshape(h // 4, 4, w // 4, 4, 3).mean(axis=(1, 3))

    mean_a, mean_b = a.mean(axis=(0, 1)), b.mean(axis=(0, 1))
    rel = [(ma - mb) / mb if mb > 0 else float("nan") for ma, mb in zip(mean_a, mean_b)]
    mad = float(np.abs(blocks(a) - blocks(b)).mean())
    side = np.concatenate([a, b, np.abs(a - b) * 4], axis=1)
    save_png(j["side_png"], side)
    return {
        "scene": j["name"],
        "lensrt_mean": mean_a.tolist(),
        "cycles_mean": mean_b.tolist(),
        "relative_mean_difference": rel,
        "block_mad": mad,
        "block_mad_relative": mad / float(mean_b.mean()) if mean_b.mean() > 0 else float("nan"),
        "cycles_seconds": j.get("cycles_seconds"),
    }


def main():
    j = job()
    if j["mode"] == "render":
        import_scene(j["scene"])
        factors = specular_factors(j["scene"])
        rebuilt = sum(rebuild_material(m, factors.get(m.name, 1.0)) for m in bpy.data.materials if m.use_nodes)
        place_camera(j)
        configure(j)
        bpy.context.scene.render.filepath = j["cycles_exr"]
        bpy.ops.render.render(write_still=True)
        print(f"validate-cycles: {rebuilt} materials rebuilt as glTF graphs", file=sys.stderr)
    else:
        result = compare(j)
        result["departures"] = DEPARTURES
        with open(j["result_json"], "w") as f:
            json.dump(result, f, indent=1)


main()
