// Ctrl-C in Python stops camcov's long calls (run, simulate, bench) within a step and raises
// what Python's signal handler raised, KeyboardInterrupt by default. The C++ work runs without
// the GIL, so Python cannot act on the signal by itself: the check installed here (util/
// interruption.h) lets the thread that imported camcov — Python's main thread, the only one
// that runs signal handlers — take the GIL every 20 ms of work and ask Python whether a signal
// came. Once one did, every thread of the work stops at its next step, and the exception
// Interrupted becomes the handler's Python exception where the call returns to Python.
#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "python/bindings.h"
#include "util/interruption.h"

namespace camcov::python {
namespace {

namespace py = pybind11;

std::thread::id signalThread;                        // the thread that imported the module
std::atomic<bool> stop{false};                       // a signal's handler raised: all work stops
PyObject* pending[3] = {nullptr, nullptr, nullptr};  // what it raised (type, value, traceback)

bool signalRaised() {
  if (stop.load(std::memory_order_relaxed)) return true;
  if (std::this_thread::get_id() != signalThread) return false;
  // Taking the GIL each step would cost a busy Python program its share: every 20 ms is
  // within a step of a person's Ctrl-C.
  using Clock = std::chrono::steady_clock;
  static Clock::time_point last;
  const Clock::time_point now = Clock::now();
  if (now - last < std::chrono::milliseconds(20)) return false;
  last = now;
  const py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() == 0) return false;
  keepPythonError();
  return true;
}

}  // namespace

void keepPythonError() {
  // With the GIL: the error the handler (or a controller) raised, kept until the call returns.
  PyErr_Fetch(&pending[0], &pending[1], &pending[2]);
  stop = true;
}

void bindInterruption(py::module_&) {
  signalThread = std::this_thread::get_id();
  installInterruptCheck(&signalRaised);
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const Interrupted&) {
      if (pending[0] != nullptr) {
        PyErr_Restore(pending[0], pending[1], pending[2]);  // takes the references
      } else {
        PyErr_SetNone(PyExc_KeyboardInterrupt);
      }
      pending[0] = pending[1] = pending[2] = nullptr;
      stop = false;  // the next call starts afresh
    }
  });
}

}  // namespace camcov::python
