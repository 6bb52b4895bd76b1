// The sensor's readout (api/sensor_spec.h). Rows of the option table (api/option_table.h).
#include "api/options/rows.h"

namespace lensrt {

void addSensorRows(std::vector<Option>& table) {
  const auto add = [&table](Option o) -> Option& { return addRow(table, "sensor", std::move(o)); };
  add(onOff(
      row("--noise", "noise", "on|off",
          "on: the sensor reads the exposure out as a camera does: photo-electrons (from the lux "
          "seconds on a pixel with --exposure physical, else 1.0 = full well), shot noise, dark "
          "current, read noise, PRNU/DSNU, full-well clipping, ISO gain and ADC; R,G,B hold the "
          "reading, noiseless.R/G/B the render (default off)",
          "on", PyValue::Switch),
      [](auto& s) -> auto& { return s.sensor.noise; }));
  add(text(
      row("--sensor-params", "sensor_params", "NAME|FILE.json",
          "the sensor for --noise on: a preset (default, full-frame, smartphone, machine-vision) or a "
          "JSON file of full_well_e, gain_dn_per_e, base_iso, read_noise_e, dark_current_e_per_s, "
          "prnu_percent, dsnu_percent, adc_bits, black_level_dn, quantum_efficiency (see README)",
          "smartphone", PyValue::Path),
      [](auto& s) -> auto& { return s.sensor.params; }));
}

}  // namespace lensrt
