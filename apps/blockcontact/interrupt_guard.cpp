// SIGINT/SIGTERM -> a flag that the run checks once per cycle (see interrupt_guard.hpp).
#include "interrupt_guard.hpp"

#include <signal.h>
#include <time.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdint>

namespace blockcontact {
namespace {

std::atomic<int> g_signal{0};
// CLOCK_MONOTONIC time of the first signal (ns; 0: none yet). Lock-free atomics are
// async-signal-safe, and two signals may be handled at once on two threads.
std::atomic<std::int64_t> g_first_ns{0};
static_assert(std::atomic<std::int64_t>::is_always_lock_free && std::atomic<int>::is_always_lock_free);

std::int64_t monotonic_ns() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);  // async-signal-safe (POSIX)
  return std::int64_t(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

extern "C" void record_signal(int signal_number) {
  const std::int64_t now = std::max<std::int64_t>(monotonic_ns(), 1);
  std::int64_t first = 0;
  if (g_first_ns.compare_exchange_strong(first, now)) {
    g_signal = signal_number;
    return;
  }
  // A repeat: one that comes with the first (timeout's second SIGTERM, Ctrl-C reaching the whole
  // process group) is the same request; a deliberate one later ends the process now.
  if (double(now - first) < 1e9 * InterruptGuard::kRepeatSeconds) return;
  signal(signal_number, SIG_DFL);
  raise(signal_number);
}

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
  g_first_ns = 0;
  struct sigaction sa {};
  sa.sa_handler = record_signal;
  sigemptyset(&sa.sa_mask);
  // Both signals blocked while the handler runs on a thread; no SA_RESETHAND (a second signal
  // must not kill the run mid-cycle: interrupt_guard.hpp); no SA_RESTART needed, the run makes no
  // blocking calls that a signal would break.
  sigaddset(&sa.sa_mask, SIGINT);
  sigaddset(&sa.sa_mask, SIGTERM);
  sa.sa_flags = 0;
  sigaction(SIGINT, &sa, &g_previous_int);
  sigaction(SIGTERM, &sa, &g_previous_term);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
}

int InterruptGuard::pending() { return g_signal.load(); }

}  // namespace blockcontact
