#include "run/interrupt.h"

#include <unistd.h>

#include <csignal>

namespace lensrt {
namespace {

// A signal handler can reach nothing but globals; this is the only one, and
// only the handler writes it.
volatile std::sig_atomic_t receivedSignal = 0;

extern "C" void onSignal(int sig) {
  if (receivedSignal != 0) ::_exit(128 + sig);  // the second signal: at once, async-signal-safe
  receivedSignal = sig;
}

}  // namespace

InterruptHandler::InterruptHandler() {
  receivedSignal = 0;
  struct sigaction action {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  ::sigaction(SIGINT, &action, &previousInt_);
  ::sigaction(SIGTERM, &action, &previousTerm_);
}

InterruptHandler::~InterruptHandler() {
  ::sigaction(SIGINT, &previousInt_, nullptr);
  ::sigaction(SIGTERM, &previousTerm_, nullptr);
}

int InterruptHandler::signal() const {
  return receivedSignal;
}

}  // namespace lensrt
