// One line on stderr for whatever a command that reads files threw, so that `diff` and `info` fail the same way.
#include <cstdio>
#include <exception>
#include <new>
#include <string>

#include "frontend/cli/commands.h"

namespace selfsim::interp {

// Called inside a catch: prints the one-line error ("selfsim info: cannot read 'x.vtp': ...") whatever was
// thrown (the readers throw Error; std::bad_alloc or a std::filesystem error would abort otherwise) and
// returns exit status 2.
int report_failure(const char* command) {
  std::string message;
  try {
    throw;
  } catch (const std::bad_alloc&) {
    message = "out of memory";
  } catch (const std::exception& e) {
    message = e.what();
  } catch (...) {
    message = "unknown error";
  }
  for (char& c : message)
    if (c == '\n' || c == '\r') c = ' ';
  std::fprintf(stderr, "selfsim %s: %s\n", command, message.c_str());
  return 2;
}

}  // namespace selfsim::interp
