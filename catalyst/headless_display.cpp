#include "headless_display.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

namespace sphdem {

HeadlessDisplay::HeadlessDisplay() {
  const char* d = std::getenv("DISPLAY");
  if (d && *d) {
    available_ = true;
    return;
  }
  int fds[2];
  if (pipe(fds) != 0) {
    reason_ = "cannot create a pipe for Xvfb";
    return;
  }
  pid_ = fork();
  if (pid_ == 0) {
    // Xvfb goes with sphdem, however sphdem ends (a SIGKILL too), and holds none of its
    // descriptors: MPI's singleton daemon waits for the end of one of them to exit.
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() == 1) _exit(127);  // the parent is already gone
    close(fds[0]);
    for (int k = 3, n = static_cast<int>(sysconf(_SC_OPEN_MAX)); k < n && k < 65536; ++k)
      if (k != fds[1]) close(k);
    const std::string fd = std::to_string(fds[1]);
    // Xvfb picks a free display and writes its number to fd (-displayfd).
    execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1280x1024x24", "-nolisten",
           "tcp", "-noreset", static_cast<char*>(nullptr));
    _exit(127);
  }
  close(fds[1]);
  if (pid_ < 0) {
    close(fds[0]);
    reason_ = "cannot fork to start Xvfb";
    return;
  }
  std::string number;
  pollfd p{fds[0], POLLIN, 0};
  while (poll(&p, 1, 10000) > 0) {  // wait up to 10 s for the display number
    char c;
    if (read(fds[0], &c, 1) != 1 || c == '\n') break;
    number += c;
  }
  close(fds[0]);
  if (number.empty()) {
    kill(pid_, SIGTERM);
    waitpid(pid_, nullptr, 0);
    pid_ = -1;
    reason_ = "DISPLAY is unset and Xvfb could not be started (apt-get install xvfb)";
    return;
  }
  setenv("DISPLAY", (":" + number).c_str(), 1);
  available_ = true;
}

HeadlessDisplay::~HeadlessDisplay() {
  if (pid_ > 0) {
    kill(pid_, SIGTERM);
    waitpid(pid_, nullptr, 0);
  }
}

}  // namespace sphdem
