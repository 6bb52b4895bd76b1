// SIGINT and SIGTERM during a render: the first asks the render to stop after
// the pass in flight (the loop polls interruptSignal()), so that a valid image
// with the samples done is written; a second one exits at once (status 128 +
// signal) without touching the output. The handler only stores the signal
// number: all the work is done by the render loop.
#pragma once

#include <signal.h>

namespace lensrt {

// Installs the handlers for its lifetime and restores the previous ones after.
class InterruptHandler {
 public:
  InterruptHandler();
  ~InterruptHandler();
  InterruptHandler(const InterruptHandler&) = delete;
  InterruptHandler& operator=(const InterruptHandler&) = delete;

  // 0, or the first signal received (SIGINT, SIGTERM).
  int signal() const;
  // The conventional exit status for that signal: 130 for SIGINT, 143 for SIGTERM.
  int exitStatus() const { return 128 + signal(); }

 private:
  struct sigaction previousInt_ {};
  struct sigaction previousTerm_ {};
};

}  // namespace lensrt
