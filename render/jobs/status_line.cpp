#include "render/jobs/status_line.h"

#include <unistd.h>

namespace render::jobs {

StatusLine::StatusLine(bool enabled, Duration delay, Duration interval, std::FILE* out)
    : enabled_(enabled && ::isatty(::fileno(out))),
      delay_(delay),
      interval_(interval),
      out_(out),
      start_(std::chrono::steady_clock::now()) {}

StatusLine::~StatusLine() { erase(); }

bool StatusLine::due() const {
  if (!enabled_) return false;
  const auto now = std::chrono::steady_clock::now();
  return now - start_ >= delay_ && (!drawn_ || now - lastDrawn_ >= interval_);
}

void StatusLine::draw(const std::string& text) {
  if (!enabled_) return;
  lastDrawn_ = std::chrono::steady_clock::now();
  // "\033[K" (ECMA-48 EL) clears what a longer line before left to the right of this one
  std::fprintf(out_, "\r%s\033[K", text.c_str());
  std::fflush(out_);
  drawn_ = true;
}

void StatusLine::keep() {
  if (drawn_) std::fputc('\n', out_);
  drawn_ = enabled_ = false;
}

void StatusLine::erase() {
  if (drawn_) std::fputs("\r\033[K", out_), std::fflush(out_);
  drawn_ = enabled_ = false;
}

double StatusLine::elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

}  // namespace render::jobs
