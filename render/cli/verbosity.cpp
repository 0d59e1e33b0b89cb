#include "render/cli/verbosity.h"

#include <fstream>

#include "render/jobs/exit_status.h"
#include "render/jobs/interrupt.h"

namespace render::cli {

void Verbosity::addTo(CLI::App& command, const std::string& quietDoes, const std::string& verboseDoes) {
  CLI::Option* q = command.add_flag("-q,--quiet", quiet, quietDoes);
  CLI::Option* v = command.add_flag("-v,--verbose", verbose, verboseDoes);
  q->excludes(v);
}

namespace {
// a stream buffer that takes every character and keeps none
struct NullBuffer : std::streambuf {
  int overflow(int c) override { return traits_type::not_eof(c); }
};
}  // namespace

std::ostream& nowhere() {
  static NullBuffer buffer;
  static std::ostream stream(&buffer);
  return stream;
}

SilencedOutput::SilencedOutput(bool silenced) {
  if (silenced) kept_ = std::cout.rdbuf(nowhere().rdbuf());
}

SilencedOutput::~SilencedOutput() {
  if (kept_) std::cout.rdbuf(kept_);
}

OutputFile::OutputFile(const std::string& path) {
  if (path.empty()) return;
  try {
    file_ = std::make_unique<render::jobs::AtomicFile>(path);
  } catch (const render::jobs::Interrupted&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw render::jobs::UsageError(std::string("-o: ") + e.what());
  }
  kept_ = std::cout.rdbuf(file_->stream().rdbuf());
}

OutputFile::~OutputFile() {
  if (kept_) std::cout.rdbuf(kept_);
}

void OutputFile::commit() {
  if (!file_) return;
  std::cout.flush();
  std::cout.rdbuf(kept_);
  kept_ = nullptr;
  file_->commit();
}

void printFile(const std::string& path) {
  std::ifstream in(path);
  // (an empty file's buffer would set the stream's failbit)
  if (in.peek() != std::ifstream::traits_type::eof()) std::cout << in.rdbuf();
  std::cout.flush();
}

}  // namespace render::cli
