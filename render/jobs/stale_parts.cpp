#include "render/jobs/stale_parts.h"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <string_view>
#include <vector>

namespace render::jobs {

namespace fs = std::filesystem;

namespace {

// the process id after "<prefix>.part-" at the start of `entry`, or 0
pid_t partOwner(std::string_view entry, const std::string& prefix) {
  const std::string start = prefix + ".part-";
  if (!entry.starts_with(start)) return 0;
  pid_t pid = 0;
  size_t k = start.size();
  for (; k < entry.size() && entry[k] >= '0' && entry[k] <= '9' && pid < 100000000; ++k) pid = pid * 10 + (entry[k] - '0');
  return k > start.size() ? pid : 0;
}

// kill(pid, 0) fails with ESRCH only when no such process exists (EPERM: it exists, not ours)
bool ended(pid_t pid) { return pid != ::getpid() && ::kill(pid, 0) != 0 && errno == ESRCH; }

}  // namespace

std::string partPrefix(const std::string& name) {
  // 255 bytes a component, less a leading ".", ".part-" and a process id of up to 10 digits
  constexpr size_t kMaxPrefix = 255 - 1 - 6 - 10;
  return name.substr(0, kMaxPrefix);
}

std::string partName(const std::string& path) {
  const fs::path p(path);
  return (p.parent_path() / partPrefix(p.filename().string())).string() + ".part-" + std::to_string(::getpid());
}

void removeStaleParts(const std::string& path) {
  const fs::path p(path);
  const fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
  const std::string name = p.filename().string(), stem = p.stem().string();
  std::vector<fs::path> stale;
  std::error_code ignored;
  for (fs::directory_iterator it(dir, ignored), end; !ignored && it != end; it.increment(ignored)) {
    const std::string file = it->path().filename().string();
    std::string_view entry = file;
    if (entry.starts_with('.')) entry.remove_prefix(1);
    pid_t owner = partOwner(entry, partPrefix(name));
    if (!owner) owner = partOwner(entry, partPrefix(stem));
    if (owner > 0 && ended(owner)) stale.push_back(it->path());
  }
  // best effort: a file another run removes first, or one we may not remove, is left to it
  for (const fs::path& s : stale) fs::remove_all(s, ignored);
}

}  // namespace render::jobs
