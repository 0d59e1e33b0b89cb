// Scene and variant names become file names (out/<scene>/<scene>-<variant>.mp4), so each must be one
// plain path component: no way out of the output folder, no hidden or empty name, nothing a shell or
// ffmpeg would read as something else.
#pragma once

#include <string>
#include <string_view>

namespace sim::yaml {

// the longest name, bytes: file systems allow 255 per component, and the renderer adds suffixes
// (the variant's name, the kind of output, a temporary ".part-<pid>") to the scene's name
inline constexpr size_t kMaxNameBytes = 100;

// why `name` cannot be a file name ("" when it can), e.g. "contains '/'"
std::string pathNameFault(std::string_view name);

// `name` as a message quotes it: each control character as \xNN, so that a refused name cannot send
// an escape sequence to the terminal that shows the message
std::string shownName(std::string_view name);

}  // namespace sim::yaml
