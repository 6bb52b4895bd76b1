#include "image/capture_date.h"

#include <cstdlib>
#include <ctime>

namespace lensrt {

std::string captureDate() {
  std::time_t when = std::time(nullptr);
  std::tm tm{};
  bool fixed = false;
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) {
    char* end = nullptr;
    const long long seconds = std::strtoll(epoch, &end, 10);
    if (end != epoch && *end == '\0' && seconds >= 0) {
      when = std::time_t(seconds);
      fixed = true;
    }
  }
  if (!(fixed ? gmtime_r(&when, &tm) : localtime_r(&when, &tm))) return {};
  char text[32];
  return std::strftime(text, sizeof text, "%Y:%m:%d %H:%M:%S", &tm) ? std::string(text) : std::string();
}

}  // namespace lensrt
