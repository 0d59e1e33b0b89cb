// Running a helper program (gnuplot): an argument vector, no shell, text on its standard input.
#pragma once

#include <string>
#include <vector>

namespace render {

struct ProcessResult {
  int status = -1;        // exit status, or -1 when it was killed by a signal
  std::string errorTail;  // the last lines it wrote to standard error
};

// runs argv[0] (looked up on PATH) with `input` on its standard input and waits for it; throws
// std::runtime_error naming the program when it cannot be started
ProcessResult runProgram(const std::vector<std::string>& argv, const std::string& input);

}  // namespace render
