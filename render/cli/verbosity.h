// -q/--quiet and -v/--verbose, the same two flags on every subcommand; what each leaves out or adds
// is in the subcommand's --help.
#pragma once

#include <CLI/CLI.hpp>

#include "render/jobs/atomic_file.h"
#include <iostream>
#include <memory>
#include <string>

namespace render::cli {

struct Verbosity {
  bool quiet = false;
  bool verbose = false;

  // -q,--quiet and -v,--verbose (which exclude each other), with what each does for this command
  void addTo(CLI::App& command, const std::string& quietDoes, const std::string& verboseDoes);
};

// while it lives, standard output goes nowhere (a quiet run); standard error is untouched, so
// errors are still said
class SilencedOutput {
 public:
  explicit SilencedOutput(bool silenced);
  ~SilencedOutput();
  SilencedOutput(const SilencedOutput&) = delete;
  SilencedOutput& operator=(const SilencedOutput&) = delete;

 private:
  std::streambuf* kept_ = nullptr;
};

// -o FILE of the commands that print (simulate, check): while it lives, standard output goes into
// FILE, written atomically (commit() keeps it; without, the old file stays as it was). An empty
// path leaves standard output alone
class OutputFile {
 public:
  explicit OutputFile(const std::string& path);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  void commit();

 private:
  std::unique_ptr<render::jobs::AtomicFile> file_;
  std::streambuf* kept_ = nullptr;
};

// a stream that keeps nothing, for what --quiet leaves out
std::ostream& nowhere();

// a file's text on standard output (a CSV a command just wrote, for -v)
void printFile(const std::string& path);

}  // namespace render::cli
