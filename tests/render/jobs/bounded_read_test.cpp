// What rigidreel reads back goes through one reader (bounded_read.cpp): a regular file whole; a FIFO,
// a device and a folder refused when opened (never waited on); a file past its bound refused before
// it is read; a byte order mark dropped where text is read.
#include "render/jobs/bounded_read.h"

#include <doctest/doctest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "render/jobs/exit_status.h"
#include "support/scratch_folder.h"

namespace fs = std::filesystem;
using render::jobs::readBounded;
using render::jobs::UsageError;

namespace {

std::string read(const std::string& path, size_t bound = 1000) { return readBounded(path, bound, "trace", "give a trace"); }

}  // namespace

TEST_CASE("a regular file is read whole, up to its bound") {
  const support::ScratchFolder f("bounded_read_test");
  std::ofstream(f.at("a.csv")) << "t,body\n0,a\n";
  CHECK(read(f.at("a.csv")) == "t,body\n0,a\n");
  CHECK(read(f.at("a.csv"), 11) == "t,body\n0,a\n");
  std::ofstream(f.at("empty.csv")).flush();
  CHECK(read(f.at("empty.csv")) == "");
}

TEST_CASE("past its bound a file is refused, saying the bound and what it is") {
  const support::ScratchFolder f("bounded_read_test");
  std::ofstream(f.at("a.csv")) << std::string(2048, 'x');
  CHECK_THROWS_WITH_AS(read(f.at("a.csv"), 1024),
                       doctest::Contains("2 KiB, more than the limit of 1 KiB for a trace; give a trace"), UsageError);
  // a sparse file of 3 GB: refused by its size, nothing read
  const std::string sparse = f.at("sparse.csv");
  std::ofstream(sparse).flush();
  fs::resize_file(sparse, size_t{3} << 30);
  CHECK_THROWS_WITH_AS(read(sparse, size_t{1} << 20), doctest::Contains("3072 MiB, more than the limit of 1 MiB"), UsageError);
}

TEST_CASE("a FIFO, a device and a folder are refused at open, a missing file named") {
  const support::ScratchFolder f("bounded_read_test");
  REQUIRE(::mkfifo(f.at("pipe.csv").c_str(), 0600) == 0);
  // (no writer: a blocking open would wait here forever)
  CHECK_THROWS_WITH_AS(read(f.at("pipe.csv")), doctest::Contains("pipe.csv: is a FIFO (named pipe), not a regular file"),
                       UsageError);
  CHECK_THROWS_WITH_AS(read("/dev/zero"), doctest::Contains("/dev/zero: is a device"), UsageError);
  CHECK_THROWS_WITH_AS(read(f.dir.string()), doctest::Contains("is a directory"), UsageError);
  CHECK_THROWS_WITH_AS(read(f.at("missing.csv")), doctest::Contains("missing.csv: cannot read the trace (No such file"),
                       UsageError);
}

TEST_CASE("a byte order mark is dropped, other text kept") {
  CHECK(render::jobs::withoutBom("\xEF\xBB\xBFt,body") == "t,body");
  CHECK(render::jobs::withoutBom("t,body") == "t,body");
  CHECK(render::jobs::withoutBom("\xEF\xBB") == "\xEF\xBB");
}
