#include "core/tool_main.hpp"

#include <cstdio>
#include <iostream>
#include <new>

#include "core/errors.hpp"
#include "core/interruption.hpp"

namespace latmpm {
namespace {

int run_body(const std::string& tool, int argc, char** argv, const std::function<int(int, char**)>& body) {
  try {
    return body(argc, argv);
  } catch (const HelpShown&) {
    return exit_ok;
  } catch (const UsageError& e) {
    std::cerr << tool << ": " << e.what() << "\n";
    return exit_usage;
  } catch (const InputError& e) {
    std::cerr << tool << ": " << e.what() << "\n";
    return exit_bad_input;
  } catch (const NumericalError& e) {
    std::cerr << tool << ": numerical failure: " << e.what() << "\n";
    return exit_numerical;
  } catch (const OutputError& e) {
    std::cerr << tool << ": cannot write output: " << e.what() << "\n";
    return exit_output;
  } catch (const std::bad_alloc&) {
    std::cerr << tool << ": out of memory\n";
    return exit_internal;
  } catch (const std::exception& e) {
    std::cerr << tool << ": internal error: " << e.what() << "\n";
    return exit_internal;
  } catch (...) {  // a library throwing something else (gmsh throws std::string): still one line
    std::cerr << tool << ": internal error: an exception of unknown type\n";
    return exit_internal;
  }
}

}  // namespace

int run_tool(const std::string& tool, int argc, char** argv,
             const std::function<int(int, char**)>& body) {
  install_signal_handlers(tool);
  int status = run_body(tool, argc, argv, body);
  // What went to standard output (a summary, --help, a staged file) must have arrived: a full
  // disk or a closed pipe is an error, not a silent success.
  std::cout.flush();
  const bool stdout_failed = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout);
  if (stdout_failed && status == exit_ok) {
    std::cerr << tool << ": cannot write output: standard output: write failed (disk full or closed pipe?)\n";
    status = exit_output;
  }
  return status;
}

}  // namespace latmpm
