// The sensor's cost per megapixel (tools/bench, stage 7): the readout of
// --noise on (src/sensor/readout) and the colour filter mosaic of --raw
// (src/sensor/mosaic), against a baseline pass over the same pixels (one
// multiply-add per value) measured in the same run. Prints JSON.
//   bench_sensor [megapixels] [repeat]      (default 4 MP, best of 5)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

#include "image/image.h"
#include "sensor/mosaic.h"
#include "sensor/readout.h"
#include "sensor/sensor_params.h"

namespace {

using Clock = std::chrono::steady_clock;

template <class F>
double bestSeconds(int repeat, F&& f) {
  double best = 1e30;
  for (int i = 0; i < repeat; ++i) {
    const auto start = Clock::now();
    f();
    best = std::min(best, std::chrono::duration<double>(Clock::now() - start).count());
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace lensrt;
  const double megapixels = argc > 1 ? std::atof(argv[1]) : 4.0;
  const int repeat = argc > 2 ? std::atoi(argv[2]) : 5;
  const int width = std::max(2, int(std::sqrt(megapixels * 1e6 * 1.5))),
            height = std::max(2, int(width / 1.5));
  Image image(width, height, {"R", "G", "B", "A"});
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    image.pixels[i] = float((i * 2654435761u) % 1000) / 1000.0f;
  const SensorParams params = sensorParams("default");
  const SensorExposure exposure = normalizedSensorExposure(params, 0.01);
  const double mp = double(width) * height / 1e6;

  volatile float sink = 0;
  const double baseline = bestSeconds(repeat, [&] {
    float acc = 0;
    for (const float v : image.pixels) acc = acc * 0.5f + v;
    sink = acc;
  });
  Image noisy;
  const double readout = bestSeconds(repeat, [&] {
    noisy = image;
    applySensorReadout(noisy, params, exposure, 1);
  });
  const double mosaic = bestSeconds(repeat, [&] {
    const Mosaic m = makeMosaic(noisy, CfaPattern{}, &params, &exposure);
    sink = float(m.dn[0]);
  });
  std::printf(
      "{\"width\": %d, \"height\": %d, \"megapixels\": %.3f, \"threads\": %d, \"baseline_ms_per_mp\": %.3f, "
      "\"readout_ms_per_mp\": %.3f, \"mosaic_ms_per_mp\": %.3f, \"noise_and_mosaic_ms_per_mp\": %.3f}\n",
      width, height, mp, int(std::thread::hardware_concurrency()), 1e3 * baseline / mp, 1e3 * readout / mp,
      1e3 * mosaic / mp, 1e3 * (readout + mosaic) / mp);
  return 0;
}
