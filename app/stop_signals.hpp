#pragma once
// SIGINT and SIGTERM ask a run to stop: the first one is recorded and the run writes a
// checkpoint and exits (run/runner.hpp, RunOptions::stop_requested); a second one stops
// the process at once (the previous checkpoint stays). SIGXFSZ is ignored, so that a
// file past the size limit is a failed write with a clear error, not a killed process.
namespace sphdem {

void install_stop_signals();
// 0, or the number of the first stop signal received.
int stop_signal();

}  // namespace sphdem
