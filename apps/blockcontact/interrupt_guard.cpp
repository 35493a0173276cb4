// SIGINT/SIGTERM -> a flag that the run checks once per cycle (see interrupt_guard.hpp).
#include "interrupt_guard.hpp"

#include <signal.h>

#include <csignal>

namespace blockcontact {
namespace {

volatile std::sig_atomic_t g_signal = 0;

extern "C" void record_signal(int signal_number) { g_signal = signal_number; }

struct sigaction g_previous_int {};
struct sigaction g_previous_term {};

}  // namespace

std::string RunInterrupted::signal_name(int signal_number) {
  if (signal_number == SIGINT) return "SIGINT";
  if (signal_number == SIGTERM) return "SIGTERM";
  return "signal " + std::to_string(signal_number);
}

InterruptGuard::InterruptGuard() {
  g_signal = 0;
  struct sigaction sa {};
  sa.sa_handler = record_signal;
  sigemptyset(&sa.sa_mask);
  // SA_RESETHAND: a second signal takes the default action (ends the process) if the run does
  // not stop; no SA_RESTART needed, the run makes no blocking calls that a signal would break.
  sa.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &sa, &g_previous_int);
  sigaction(SIGTERM, &sa, &g_previous_term);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
}

int InterruptGuard::pending() { return static_cast<int>(g_signal); }

}  // namespace blockcontact
