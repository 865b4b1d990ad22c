#pragma once
// Debian's ParaView renders only through X (GLX); with no display the first render
// aborts the whole process. HeadlessDisplay starts a private Xvfb (with -noreset, which
// avoids the 1-in-10 connection failures of a resetting server) when DISPLAY is unset,
// and stops it at destruction.
#include <sys/types.h>

#include <string>

namespace sphdem {

class HeadlessDisplay {
 public:
  // Ensures DISPLAY names a usable X server. On failure, available() is false and
  // reason() says why.
  HeadlessDisplay();
  ~HeadlessDisplay();
  bool available() const { return available_; }
  bool started_xvfb() const { return pid_ > 0; }
  const std::string& reason() const { return reason_; }

 private:
  pid_t pid_ = -1;
  bool available_ = false;
  std::string reason_;
};

}  // namespace sphdem
