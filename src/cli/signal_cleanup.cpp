#include "cli/signal_cleanup.h"

#include <pthread.h>

#include <csignal>
#include <system_error>
#include <thread>

#include "util/temporary_outputs.h"

namespace camcov::cli {

void removeTemporaryOutputsOnSignal() {
  sigset_t ending;
  sigemptyset(&ending);
  for (const int signal : {SIGINT, SIGTERM, SIGHUP})
    sigaddset(&ending, signal);
  if (const int error = pthread_sigmask(SIG_BLOCK, &ending, nullptr))
    throw std::system_error(error, std::generic_category(), "blocking signals");
  // A thread of its own rather than a handler: it may take the registry's lock and free
  // memory, which no signal handler may.
  std::thread([ending] {
    int signal = 0;
    while (sigwait(&ending, &signal) != 0) {
    }
    removeTemporaryOutputsForExit();
    std::signal(signal, SIG_DFL);
    sigset_t one;
    sigemptyset(&one);
    sigaddset(&one, signal);
    pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
    std::raise(signal);  // ends the process: the default action of each of these signals
  }).detach();
}

}  // namespace camcov::cli
