// A run killed outright (SIGKILL, a power cut) cannot remove its temporary files. They are named
// after their output and the writer's process id (out/a/.a.part-<pid>.mp4, a.json.part-<pid>), so the
// next run that writes the same output removes those whose process is gone.
#pragma once

#include <string>

namespace render::jobs {

// "<path>.part-<pid>" for this process: the temporary name of a file written in place of `path`
// (a name too long for that cut to partPrefix)
std::string partName(const std::string& path);
// the start of a temporary name: `name`, cut where a 255-byte component would leave no room for
// a leading ".", ".part-" and a process id
std::string partPrefix(const std::string& name);

// removes, beside `path`, the temporary files and folders of `path` left by processes that have
// ended: "[.]<name or stem>.part-<pid>[<anything>]"; those of running processes are kept
void removeStaleParts(const std::string& path);

}  // namespace render::jobs
