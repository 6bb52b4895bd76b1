// Every test binary's main: GoogleTest's, then the leak check that
// LeakSanitizer would otherwise run at exit (core/leak_check.h says why).
#include <gtest/gtest.h>

#include "core/leak_check.h"

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  const int status = RUN_ALL_TESTS();
  lensrt::checkLeaksBeforeExit();
  return status;
}
