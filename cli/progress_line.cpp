#include "cli/progress_line.h"

#include <unistd.h>

#include <cstdio>

namespace contactcert::cli {

ProgressLine::ProgressLine(std::string label)
    : label_(std::move(label)), enabled_(isatty(STDERR_FILENO) == 1), start_(Clock::now()) {}

ProgressLine::~ProgressLine() { finish(); }

void ProgressLine::finish() {
  if (shown_) std::fputs("\r\033[K", stderr);
  shown_ = false;
}

void ProgressLine::update(const std::string& text, bool force) {
  if (!enabled_) return;
  const Clock::time_point now = Clock::now();
  if (!force && shown_ && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  shown_ = true;
  const double seconds = std::chrono::duration<double>(now - start_).count();
  std::fprintf(stderr, "\r\033[K%s: %s (%.1f s)", label_.c_str(), text.c_str(), seconds);
  std::fflush(stderr);
}

}  // namespace contactcert::cli
