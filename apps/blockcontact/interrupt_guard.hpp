#pragma once
// Stopping a run cleanly on SIGINT (Ctrl-C) or SIGTERM (kill, timeout): the handler only records
// the signal; the run checks it once per cycle and unwinds with RunInterrupted, so that the
// simulation flushes its sinks and the HDF5 file is closed and the XDMF file written.
//
// Signals that arrive together are one request: GNU timeout sends SIGTERM to the child and then
// to its process group, a terminal's Ctrl-C reaches every process of the foreground group, and
// both must end in the same clean stop. Only a deliberate repeat, a signal kRepeatSeconds or more
// after the first, ends the process at once (with the signal's default action), for a run that
// does not stop.
#include <stdexcept>
#include <string>

namespace blockcontact {

/// Thrown from the progress callback when a signal is pending; carries the signal number.
class RunInterrupted final : public std::runtime_error {
 public:
  explicit RunInterrupted(int signal_number)
      : std::runtime_error("interrupted by " + signal_name(signal_number)), signal_(signal_number) {}
  int signal_number() const { return signal_; }
  /// "SIGINT", "SIGTERM" or "signal <n>".
  static std::string signal_name(int signal_number);

 private:
  int signal_;
};

/// While alive, SIGINT and SIGTERM set a flag instead of ending the process (the previous
/// dispositions come back on destruction). Any number of them within kRepeatSeconds of the first
/// only set the flag; one later than that ends the process at once.
class InterruptGuard {
 public:
  /// A repeat this long (s) after the first signal forces an immediate exit.
  static constexpr double kRepeatSeconds = 2.0;

  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  /// The first signal received since construction, or 0. Async-signal-safe flag read.
  static int pending();
  /// Throws RunInterrupted when a signal is pending.
  static void throw_if_pending() {
    if (const int s = pending(); s != 0) throw RunInterrupted(s);
  }
};

}  // namespace blockcontact
