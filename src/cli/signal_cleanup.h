#pragma once
// A command ended by a signal (Ctrl-C's SIGINT, SIGTERM, a closed terminal's SIGHUP) leaves no
// temporary file behind: the signals are blocked in every thread and one watcher thread waits
// for them, removes the registered temporary outputs (util/temporary_outputs.h), then ends the
// process by the same signal, so the shell sees what it sent. Whole outputs already written
// stay, as after any other end.
namespace camcov::cli {

// Call once in main(), before any thread starts (threads inherit the blocked signals).
void removeTemporaryOutputsOnSignal();

}  // namespace camcov::cli
