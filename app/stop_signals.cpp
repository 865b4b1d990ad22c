#include "stop_signals.hpp"

#include <unistd.h>

#include <csignal>

namespace sphdem {

namespace {
// The one piece of process-wide state of the program: POSIX lets a signal handler reach
// nothing else. Written only by the handler, read by the time loop.
volatile std::sig_atomic_t g_stop_signal = 0;

extern "C" void on_stop_signal(int sig) {
  if (g_stop_signal != 0) {  // the second one: stop now
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  g_stop_signal = sig;
  const char msg[] =
      "\nsphdem: stopping: finishing the step and writing a checkpoint (again to stop at "
      "once)\n";
  const ssize_t ignored = ::write(STDERR_FILENO, msg, sizeof msg - 1);  // async-signal-safe
  (void)ignored;
}
}  // namespace

void install_stop_signals() {
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
  std::signal(SIGXFSZ, SIG_IGN);
}

int stop_signal() {
  return g_stop_signal;
}

}  // namespace sphdem
