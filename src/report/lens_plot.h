// SVG plots of a lens's field performance from exact ray tracing:
// relative illumination, distortion, spot diagrams and chromatic aberration.
#pragma once

#include <string>
#include <vector>

#include "api/lens_view.h"
#include "report/svg_writer.h"

namespace lensrt {

// The plotted series as numbers: named columns, one row per plotted point.
struct PlotTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  // A header line of the column names, then one comma-separated line per row
  // (9 significant digits).
  std::string csv() const;
};

// A plot drawn once and its data, so --csv matches the picture exactly.
struct LensPlot {
  Svg svg;
  PlotTable table;
};

// Columns: film_radius_mm, relative_illumination, vignetting, cos4.
LensPlot plotRelativeIllumination(const LensView& view);
// Columns: field_angle_deg, real_height_mm, paraxial_height_mm, distortion_percent.
LensPlot plotDistortion(const LensView& view);
// Columns: field_angle_deg, image_height_mm, dx_um, dy_um (each ray's film
// point from its spot's centroid; every ray, also those outside the drawing).
LensPlot plotSpotDiagrams(const LensView& view);

// Columns: wavelength_nm, focal_shift_mm (paraxial BFL minus the d line's),
// image_height_mm, lateral_color_um (F minus C chief rays; nan where none
// reaches): two curves of 41 points side by side.
LensPlot plotChromatic(const LensView& view);

}  // namespace lensrt
