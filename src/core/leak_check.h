// Under LeakSanitizer the leak check normally runs at exit, while libraries'
// static destructors join their threads: the OpenImageIO plugin's
// dependencies start four (log4cplus's pool) when it is loaded. LSan's
// tracer can crash on a thread halfway out ("Tracer caught signal 11",
// google/sanitizers#1353), which failed CI once. Processes that may load the
// plugin run the same check here instead, just before main returns, with
// every thread idle; the check at exit is then skipped. A no-op in builds
// without LeakSanitizer or with detect_leaks=0.
#pragma once

#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(leak_sanitizer)
#define LENSRT_LEAK_SANITIZER 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define LENSRT_LEAK_SANITIZER 1
#endif

#ifdef LENSRT_LEAK_SANITIZER
#include <sanitizer/lsan_interface.h>
#endif

namespace lensrt {

inline void checkLeaksBeforeExit() {
#ifdef LENSRT_LEAK_SANITIZER
  __lsan_do_leak_check();
#endif
}

}  // namespace lensrt
