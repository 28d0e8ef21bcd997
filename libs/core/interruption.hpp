// What a tool does when it is stopped by a signal, and the temporary files it must not leave.
// run_tool installs the handlers. SIGINT, SIGTERM and SIGHUP remove every registered
// temporary file and end the tool with status 128 + signal number (130 for Ctrl-C, 143 for
// kill). SIGPIPE is ignored: a closed pipe becomes an ordinary write error (exit status 5)
// that unwinds through the destructors, which remove their temporary files.
// A long run defers instead (latmpm-solve): while an InterruptionDeferral is alive, the first
// signal only sets interruption_signal(), which the run polls between steps to finish the
// step, save and stop; a second signal ends the tool at once, as above.
// A SIGKILL cannot be caught: a run removes the stale temporary files of its run directory
// when it starts (remove_stale_temporaries).
#pragma once
#include <string>
#include <utility>

namespace latmpm {

// `tool` names the tool in the one line the handler writes ("latmpm-x: stopped by SIGTERM").
void install_signal_handlers(const std::string& tool);

// Registers a temporary file for removal by the signal handler; returns a slot for
// unregister_temporary (-1 when every slot is taken: the file is then only removed by its
// owner's destructor).
int register_temporary(const std::string& path);
void unregister_temporary(int slot);

// Holds SIGINT, SIGTERM and SIGHUP back while alive (they are delivered when it goes): for
// creating a temporary file and registering it as one step, so that no signal can come
// between the two and leave the file behind.
class SignalsHeld {
 public:
  SignalsHeld();
  ~SignalsHeld();
  SignalsHeld(const SignalsHeld&) = delete;
  SignalsHeld& operator=(const SignalsHeld&) = delete;

 private:
  unsigned char saved_[128];  // a sigset_t, kept opaque here
};

// A file another library writes under a name of its choosing (gmsh picks the format by the
// extension): registered for the signal handler and removed when the guard goes, unless
// the file was moved into place first.
class TemporaryPath {
 public:
  explicit TemporaryPath(std::string path) : path_(std::move(path)), slot_(register_temporary(path_)) {}
  ~TemporaryPath();
  TemporaryPath(const TemporaryPath&) = delete;
  TemporaryPath& operator=(const TemporaryPath&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int slot_;
};

// A child process writing registered temporaries (gnuplot): the handler kills and reaps it
// before removing them, so it cannot create one afterwards. 0: none.
void set_child_process(int pid);

// The signal that asked a deferring run to stop, 0 while none has.
int interruption_signal();
const char* signal_name(int signo);  // "SIGTERM"

class InterruptionDeferral {
 public:
  InterruptionDeferral();
  ~InterruptionDeferral();
  InterruptionDeferral(const InterruptionDeferral&) = delete;
  InterruptionDeferral& operator=(const InterruptionDeferral&) = delete;
};

// Removes the staging files OutputFile names ".<name>.tmp.XXXXXX" in `directory`, left by a
// run that was killed outright. Returns how many were removed.
int remove_stale_temporaries(const std::string& directory);

}  // namespace latmpm
