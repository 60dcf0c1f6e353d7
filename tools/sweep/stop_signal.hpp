// Ctrl-C or SIGTERM of a sweep: no run starts or is retried after it, running children are stopped
// (tools::terminate_children, process.hpp: their logs stay resumable), and the tables hold what finished.
// install_stop_handler sets that up; the pools ask stop_requested before each run.
#pragma once

namespace ede::sweep {

void install_stop_handler();
bool stop_requested();
int stop_signal();

}  // namespace ede::sweep
