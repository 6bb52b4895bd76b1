"""lensrt: render glTF scenes through real camera optics, into numpy arrays.

    import lensrt
    lens = lensrt.Lens("dgauss-50mm")
    scene = lensrt.Scene("scenes/dof_row.gltf")
    image = scene.render(camera="lens", lens=lens.file, fstop=2.8, res=(320, 180), spp=16)
    image.rgb          # H x W x 3 float32, linear
    image.write("out/dof_row.exr")

Lens, Scene, RenderResult and diff are the command line's `lens info`,
`render` and `diff`, on the same library: the same seed gives the same bits.
read opens what the command wrote (an EXR and its AOVs, a frame of --frames).
"""

from collections import namedtuple as _namedtuple

TraceResult = _namedtuple("TraceResult", ["points", "directions", "weights", "passed"])
TraceResult.__doc__ = """Lens.trace's result: exit points (N x 3, mm), unit directions (N x 3),
transmitted fractions (N) and which rays passed (N, bool)."""

Projection = _namedtuple("Projection", ["pixels", "visible", "status"])
Projection.__doc__ = """Lens.project's result: raster positions (N x 2, pixels from the top-left
corner), which lie inside the frame (N, bool), and the reason (N, uint8): 0
visible, 1 outside the frame, 2 blocked by the lens, 3 behind the camera."""

Unprojection = _namedtuple("Unprojection", ["origins", "directions", "visible", "status"])
Unprojection.__doc__ = """Lens.unproject's result: the chief rays' origins (N x 3, metres) and unit
directions (N x 3), world space, and visible and status as Projection's."""

from ._lensrt import Lens, RenderResult, Scene, __version__, diff, read  # noqa: E402

__all__ = ["Lens", "Scene", "RenderResult", "TraceResult", "Projection", "Unprojection", "diff", "read", "__version__"]
