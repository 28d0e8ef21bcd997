#include "core/tool_main.hpp"

#include <iostream>
#include <new>

#include "core/errors.hpp"

namespace latmpm {

int run_tool(const std::string& tool, int argc, char** argv,
             const std::function<int(int, char**)>& body) {
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
  } catch (const std::bad_alloc&) {
    std::cerr << tool << ": out of memory\n";
    return exit_internal;
  } catch (const std::exception& e) {
    std::cerr << tool << ": internal error: " << e.what() << "\n";
    return exit_internal;
  }
}

}  // namespace latmpm
