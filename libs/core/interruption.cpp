#include "core/interruption.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <climits>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace latmpm {
namespace {

// Fixed storage: the handler may only touch memory that no allocation can move, and call
// async-signal-safe functions (unlink, _exit).
constexpr int slot_count = 64;
char registered_paths[slot_count][PATH_MAX];
std::atomic<int> slot_state[slot_count];  // 0 free, 1 being written, 2 registered
volatile sig_atomic_t deferring = 0;
volatile sig_atomic_t received = 0;
volatile sig_atomic_t child_process = 0;
char tool_name[64] = "latmpm";

// The handler's one line, with write(2) only (async-signal-safe; signal_name returns literals).
void say_stopped(int signo) {
  for (const char* part : {static_cast<const char*>(tool_name), ": stopped by ", signal_name(signo),
                           ", temporary files removed\n"})
    if (::write(STDERR_FILENO, part, std::strlen(part)) < 0) return;
}

void remove_registered() {
  for (int i = 0; i < slot_count; ++i)
    if (slot_state[i].load() == 2) ::unlink(registered_paths[i]);
}

extern "C" void on_stop_signal(int signo) {
  if (deferring && !received) {
    received = signo;
    return;
  }
  if (child_process > 0) {
    ::kill(child_process, SIGKILL);
    ::waitpid(child_process, nullptr, 0);
  }
  remove_registered();
  say_stopped(signo);
  ::_exit(128 + signo);
}

}  // namespace

void install_signal_handlers(const std::string& tool) {
  std::snprintf(tool_name, sizeof tool_name, "%s", tool.c_str());
  struct sigaction action;
  std::memset(&action, 0, sizeof action);
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&action.sa_mask, s);
  for (int s : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(s, &action, nullptr);
  ::signal(SIGPIPE, SIG_IGN);
}

int register_temporary(const std::string& path) {
  if (path.size() >= PATH_MAX) return -1;
  for (int i = 0; i < slot_count; ++i) {
    int expected = 0;
    if (slot_state[i].compare_exchange_strong(expected, 1)) {
      std::memcpy(registered_paths[i], path.c_str(), path.size() + 1);
      slot_state[i].store(2);
      return i;
    }
  }
  return -1;
}

void unregister_temporary(int slot) {
  if (slot >= 0 && slot < slot_count) slot_state[slot].store(0);
}

void set_child_process(int pid) { child_process = pid; }

int interruption_signal() { return received; }

const char* signal_name(int signo) {
  switch (signo) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    default: return "a signal";
  }
}

static_assert(sizeof(sigset_t) <= 128, "SignalsHeld keeps a sigset_t");

SignalsHeld::SignalsHeld() {
  sigset_t stop;
  sigemptyset(&stop);
  for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&stop, s);
  ::sigprocmask(SIG_BLOCK, &stop, reinterpret_cast<sigset_t*>(saved_));
}

SignalsHeld::~SignalsHeld() { ::sigprocmask(SIG_SETMASK, reinterpret_cast<sigset_t*>(saved_), nullptr); }

TemporaryPath::~TemporaryPath() {
  ::unlink(path_.c_str());  // gone already when it was moved into place
  unregister_temporary(slot_);
}

InterruptionDeferral::InterruptionDeferral() { deferring = 1; }
InterruptionDeferral::~InterruptionDeferral() { deferring = 0; }

int remove_stale_temporaries(const std::string& directory) {
  namespace fs = std::filesystem;
  // mkstemp's names: ".<name>.tmp." and six characters.
  auto staging = [](const std::string& name) {
    const size_t tmp = name.rfind(".tmp.");
    return name.size() > 1 && name[0] == '.' && tmp != std::string::npos && tmp > 1 && name.size() == tmp + 11;
  };
  int removed = 0;
  std::error_code ec;
  for (fs::directory_iterator it(directory, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file(ec) && staging(it->path().filename().string()) && fs::remove(it->path(), ec)) ++removed;
  return removed;
}

}  // namespace latmpm
