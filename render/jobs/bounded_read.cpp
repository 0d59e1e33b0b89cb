#include "render/jobs/bounded_read.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "render/jobs/exit_status.h"
#include "render/jobs/interrupt.h"
#include "render/jobs/regular_file.h"

namespace render::jobs {

namespace {

// bytes read between two looks at the interrupt flag
constexpr size_t kPieceBytes = size_t{1} << 20;

// "256 MiB", "1 MiB", "64 KiB"
std::string sizeText(size_t bytes) {
  if (bytes >= (size_t{1} << 20) && bytes % (size_t{1} << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
  if (bytes >= 1024 && bytes % 1024 == 0) return std::to_string(bytes >> 10) + " KiB";
  return std::to_string(bytes) + " bytes";
}

// closes the descriptor whatever ends the read
struct Descriptor {
  int fd;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

std::string readBounded(const std::string& path, size_t maxBytes, const std::string& what, const std::string& remedy) {
  const auto refuse = [&](const std::string& why) { throw UsageError(path + ": " + why + "; " + remedy); };
  // O_NONBLOCK: opening a FIFO for reading returns at once instead of waiting for a writer
  const Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY)};
  if (file.fd < 0) {
    const int error = errno;
    checkInterrupted();
    refuse("cannot read the " + what + " (" + std::strerror(error) + ")");
  }
  struct stat info {};
  if (::fstat(file.fd, &info) != 0) refuse("cannot read the " + what + " (" + std::strerror(errno) + ")");
  if (!S_ISREG(info.st_mode)) {
    // (named by the path's type: what was opened is what the path names)
    const std::string kind = notRegularFile(path);
    refuse((kind.empty() ? std::string("is not a regular file") : kind) + "; the " + what + " must be one");
  }
  const auto tooLarge = [&](const std::string& size) {
    refuse(size + ", more than the limit of " + sizeText(maxBytes) + " for a " + what);
  };
  if (static_cast<unsigned long long>(info.st_size) > maxBytes) tooLarge(sizeText(static_cast<size_t>(info.st_size)));
  // a regular file does not block; reads go on as usual
  ::fcntl(file.fd, F_SETFL, ::fcntl(file.fd, F_GETFL) & ~O_NONBLOCK);
  std::string text;
  text.reserve(static_cast<size_t>(info.st_size));
  for (;;) {
    checkInterrupted();
    const size_t at = text.size();
    // one byte past the bound, to tell a file that grew past it
    const size_t want = std::min(kPieceBytes, maxBytes + 1 - at);
    text.resize(at + want);
    const ssize_t n = ::read(file.fd, text.data() + at, want);
    if (n < 0 && errno == EINTR) {
      text.resize(at);
      continue;
    }
    if (n < 0) refuse("cannot read the " + what + " (" + std::strerror(errno) + ")");
    text.resize(at + static_cast<size_t>(n));
    if (n == 0) break;
    if (text.size() > maxBytes) tooLarge("more than " + sizeText(maxBytes) + " (it grew while read)");
  }
  return text;
}

std::string_view withoutBom(std::string_view text) {
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
  return text;
}

}  // namespace render::jobs
