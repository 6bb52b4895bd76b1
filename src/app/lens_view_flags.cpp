#include "app/lens_view_flags.h"

namespace lensrt {

void addLensViewOptions(CLI::App& command, LensViewOptions& o, bool outputRequired) {
  command
      .add_option("lens", o.lens, "Lens file (.lens, .json, .dat, .zmx) or library name, e.g. dgauss-50mm")
      ->required();
  command.add_option("-o,--output", o.output, "Output SVG file")->required(outputRequired);
  command.add_option("--fstop", o.fNumber, "Stop down to this f-number (default: widest)");
  command.add_option("--focus", o.focus, "Focus distance in metres from the entrance pupil, or 'inf'")
      ->capture_default_str();
  command.add_option("--sensor", o.sensor, "Sensor size WIDTHxHEIGHT in mm (sets the field)")
      ->capture_default_str();
}

}  // namespace lensrt
