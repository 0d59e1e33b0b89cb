// Bad input in a scene file: what() is "FILE:LINE:COL: message" (or "FILE: message" when there is
// no position), so that every reader reports a fault the same way (exit 2 on the command line).
#pragma once

#include <stdexcept>
#include <string>

namespace sim::yaml {

class SceneError : public std::runtime_error {
 public:
  SceneError(std::string file, int line, int column, const std::string& message)
      : std::runtime_error(line > 0 ? file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message
                                    : file + ": " + message),
        file(std::move(file)),
        line(line),
        column(column),
        message(message) {}
  std::string file;
  int line, column;
  std::string message;
};

}  // namespace sim::yaml
