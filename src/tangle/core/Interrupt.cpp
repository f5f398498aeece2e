#include "tangle/core/Interrupt.hpp"

#include <csignal>

namespace tangle::core {

namespace {
volatile std::sig_atomic_t g_interrupted = 0;

extern "C" void onInterrupt(int signal) {
  if (g_interrupted) {
    std::signal(signal, SIG_DFL);  // second request: let the next one kill the program
    return;
  }
  g_interrupted = 1;
}
}  // namespace

void installInterruptHandler() {
  std::signal(SIGINT, onInterrupt);
  std::signal(SIGTERM, onInterrupt);
}

bool interruptRequested() { return g_interrupted != 0; }

}  // namespace tangle::core
