# Type stubs of lensrt (the compiled lensrt._lensrt and TraceResult), so that
# IDEs complete the keywords of Scene.render and friends. Units in the names:
# _mm millimetres, _m metres, _deg degrees, _nm nanometres.
import os
from typing import Any, Callable, NamedTuple, Sequence

import numpy as np
import numpy.typing as npt

__version__: str

_Path = str | os.PathLike[str]
_Distance = float | str  # metres, or "inf"
_Sensor = str | tuple[float, float]  # "WxH" mm or (w, h) mm

class TraceResult(NamedTuple):
    points: npt.NDArray[np.float64]  # N x 3, mm, where rays leave the front surface
    directions: npt.NDArray[np.float64]  # N x 3, unit
    weights: npt.NDArray[np.float64]  # N, transmitted fraction
    passed: npt.NDArray[np.bool_]  # N

class Projection(NamedTuple):
    pixels: npt.NDArray[np.float64]  # N x 2, raster: (0, 0) the top-left corner, y down
    visible: npt.NDArray[np.bool_]  # N
    status: npt.NDArray[np.uint8]  # N: 0 visible, 1 outside the frame, 2 blocked, 3 behind

class Unprojection(NamedTuple):
    origins: npt.NDArray[np.float64]  # N x 3, metres
    directions: npt.NDArray[np.float64]  # N x 3, unit, toward the scene
    visible: npt.NDArray[np.bool_]  # N
    status: npt.NDArray[np.uint8]  # N

class Lens:
    def __init__(self, lens: _Path) -> None: ...
    @property
    def name(self) -> str: ...
    @property
    def file(self) -> str: ...
    @property
    def surfaces(self) -> list[dict[str, Any]]: ...
    def info(
        self,
        fstop: float | None = None,
        focus: _Distance = "inf",
        sensor: _Sensor = "36x24",
        coc: float | None = None,
        coatings: str = "none",
    ) -> dict[str, Any]: ...
    def trace(
        self,
        origins: npt.ArrayLike,
        directions: npt.ArrayLike,
        wavelength_nm: float = 587.5618,
        fstop: float | None = None,
        coatings: str | None = None,
    ) -> TraceResult: ...
    def focus(self, distance_m: _Distance) -> float: ...
    def spot(
        self,
        field_deg: float = 0.0,
        fstop: float | None = None,
        focus: _Distance = "inf",
        rays: int = 41,
        wavelength_nm: float = 587.5618,
        coatings: str | None = None,
    ) -> npt.NDArray[np.float64]: ...
    def relative_illumination(
        self, fstop: float | None = None, focus: _Distance = "inf", sensor: _Sensor = "36x24", points: int = 33
    ) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
    def distortion(
        self, fstop: float | None = None, focus: _Distance = "inf", sensor: _Sensor = "36x24", points: int = 41
    ) -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]: ...
    def ghosts(self, coatings: str = "none") -> dict[str, Any]: ...
    def project(
        self,
        world_points: npt.ArrayLike,
        camera_to_world: npt.ArrayLike | None,
        *,
        res: str | tuple[int, int],
        focus: _Distance,
        sensor: _Sensor = "full-frame",
        fstop: float | None = None,
        wavelength_nm: float = 587.5618,
        camera: str = "lens",
    ) -> Projection: ...
    def unproject(
        self,
        pixels: npt.ArrayLike,
        camera_to_world: npt.ArrayLike | None = None,
        *,
        res: str | tuple[int, int],
        focus: _Distance,
        sensor: _Sensor = "full-frame",
        fstop: float | None = None,
        wavelength_nm: float = 587.5618,
        camera: str = "lens",
    ) -> Unprojection: ...
    def calibrate(
        self,
        *,
        res: str | tuple[int, int],
        focus: _Distance,
        sensor: _Sensor = "full-frame",
        fstop: float | None = None,
        model: str = "opencv",
        wavelength_nm: float = 587.5618,
        camera: str = "lens",
        max_residual: float = 1.0,
    ) -> dict[str, Any]: ...
    def psf(
        self,
        field_deg: float = 0.0,
        fstop: float | None = None,
        focus: _Distance = "inf",
        wavelengths_nm: Sequence[float] | None = None,
        weights: Sequence[float] | None = None,
        pupil_samples: int = 0,
        padding: int = 4,
        blades: int = 0,
        blade_rotation_deg: float = 0.0,
        aperture_mask: str | os.PathLike[str] | None = None,
        coatings: str | None = None,
    ) -> dict[str, Any]: ...
    def mtf(
        self,
        field_deg: float = 0.0,
        fstop: float | None = None,
        focus: _Distance = "inf",
        wavelengths_nm: Sequence[float] | None = None,
        weights: Sequence[float] | None = None,
        pupil_samples: int = 0,
        padding: int = 4,
        blades: int = 0,
        blade_rotation_deg: float = 0.0,
        aperture_mask: str | os.PathLike[str] | None = None,
        coatings: str | None = None,
        max_frequency: float | None = None,
        points: int = 101,
        focus_frequency: float | None = None,
        focus_range_mm: float | None = None,
    ) -> dict[str, Any]: ...

class RenderResult:
    @property
    def rgb(self) -> npt.NDArray[np.float32]: ...  # H x W x 3, a view
    @property
    def channels(self) -> dict[str, npt.NDArray[np.float32]]: ...  # each H x W, a view
    @property
    def metadata(self) -> dict[str, str]: ...
    @property
    def seconds(self) -> float: ...
    @property
    def spp(self) -> int: ...
    @property
    def finished(self) -> bool: ...
    @property
    def camera(self) -> str: ...
    def write(self, path: _Path) -> None: ...

class Scene:
    def __init__(
        self,
        file: _Path,
        scene_index: int | None = None,
        allow_external_files: bool = False,
        max_texture_memory: int | None = None,
        time: float = 0.0,
        animation: str | int | None = None,
    ) -> None: ...
    @property
    def file(self) -> str: ...
    def at(self, time: float) -> Scene: ...
    def render(
        self,
        *,
        # BEGIN generated by tools/gen-reference from the option table
        camera: str = "pinhole",
        lens: _Path | None = None,
        fstop: float | str | None = None,
        focus: float | str = "auto",
        focus_pixel: tuple[float, float] | float | str | None = None,
        sensor: tuple[float, float] | float | str = "36x24",
        blades: int = 0,
        blade_rotation: float = 0,
        focal_length: float | None = None,
        exposure: str = "normalized",
        iso: float | None = None,
        dispersion: str | bool = "on",
        diffraction: str | bool = "off",
        film: str | None = None,
        shift: tuple[float, float] | float | str = "0,0",
        tilt: tuple[float, float] | float | str = 0,
        aperture_mask: _Path | None = None,
        coatings: str | None = None,
        shutter: float | str = 0.01,
        shutter_curve: str = "box",
        rolling_shutter: float | str = 0,
        readout: str = "top-down",
        flare: str | bool = "off",
        flare_bounces: int = 2,
        barrel_reflectance: float = 0,
        spectral: str | bool = "auto",
        sensor_response: _Path | None = None,
        white_balance: float | str | None = None,
        output_space: str = "srgb",
        noise: str | bool = "off",
        sensor_params: _Path | None = None,
        spp: int = 16,
        noise_threshold: float | None = None,
        min_spp: int | None = None,
        seed: int = 0,
        max_depth: int = 8,
        light_sampler: str = "tree",
        threads: int = 0,
        tile_size: int = 16,
        res: tuple[float, float] | float | str | None = None,
        camera_node: float | str | None = None,
        env: float | str | None = None,
        env_rotate: float = 0,
        env_intensity: float = 1,
        aov: Sequence[str | int] | str | None = None,
        raw: _Path | None = None,
        cfa: str = "RGGB",
        crop: Sequence[str | int] | str | None = None,
        flow_step: float = 0,
        camera_to_world: npt.ArrayLike | None = None,
        progress: Callable[[int, int], bool | None] | None = None,
        # END generated
    ) -> RenderResult: ...

def diff(
    a: _Path | RenderResult,
    b: _Path | RenderResult,
    *,
    fail: float | None = None,
    fail_relative: float | None = None,
    fail_percent: float | None = None,
    hard_fail: float | None = None,
    warn: float | None = None,
    warn_relative: float | None = None,
    warn_percent: float | None = None,
    hard_warn: float | None = None,
    relative_floor: float | None = None,
    noise_aware: bool = False,
    pixel_alpha: float | None = None,
    image_alpha: float | None = None,
    variance_floor: float | None = None,
    spp: int | None = None,
    heatmap: _Path | None = None,
    heatmap_max: float | None = None,
) -> dict[str, Any]: ...
def read(path: _Path) -> RenderResult: ...
