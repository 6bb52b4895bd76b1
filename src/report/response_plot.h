// The SVG chart of a sensor's spectral response (`lensrt sensor plot`): its
// three curves against wavelength, relative to the largest of them.
#pragma once

#include "report/svg_writer.h"
#include "sensor/sensor_response.h"

namespace lensrt {

// r, g, b in red, green and blue (xbar, ybar, zbar for cie1931), each polyline
// through the tabulated samples (the response is linear between them),
// scaled so that the largest value of the three is 1; the legend gives each
// curve's peak wavelength.
Svg plotSensorResponse(const SensorResponse& response);

}  // namespace lensrt
