// Files the program reads must be regular (regular_file.cpp): a FIFO, a folder, a device or a
// socket is named for what it is; a regular file, a symlink to one, or nothing there is fine.
#include "render/jobs/regular_file.h"

#include <doctest/doctest.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/scratch_folder.h"

namespace fs = std::filesystem;
using render::jobs::notRegularFile;

TEST_CASE("a regular file, a symlink to one and a missing path are not refused") {
  const support::ScratchFolder f("regular_file_test");
  std::ofstream(f.at("scene.yaml")) << "name: a\n";
  fs::create_symlink(f.at("scene.yaml"), f.at("link.yaml"));
  CHECK(notRegularFile(f.at("scene.yaml")) == "");
  CHECK(notRegularFile(f.at("link.yaml")) == "");
  CHECK(notRegularFile(f.at("missing.yaml")) == "");
}

TEST_CASE("a FIFO, a folder, a device and a socket are each named for what they are") {
  const support::ScratchFolder f("regular_file_test");
  REQUIRE(::mkfifo(f.at("pipe.yaml").c_str(), 0600) == 0);
  CHECK(notRegularFile(f.at("pipe.yaml")) == "is a FIFO (named pipe), not a regular file");
  CHECK(notRegularFile(f.dir.string()) == "is a directory, not a regular file");
  CHECK(notRegularFile("/dev/null") == "is a device, not a regular file");
  // a symlink to a FIFO is the FIFO
  fs::create_symlink(f.at("pipe.yaml"), f.at("to-pipe.yaml"));
  CHECK(notRegularFile(f.at("to-pipe.yaml")) == "is a FIFO (named pipe), not a regular file");

  const std::string socketPath = f.at("s");
  const int s = ::socket(AF_UNIX, SOCK_STREAM, 0);
  REQUIRE(s >= 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  REQUIRE(socketPath.size() < sizeof address.sun_path);
  std::strcpy(address.sun_path, socketPath.c_str());
  REQUIRE(::bind(s, reinterpret_cast<const sockaddr*>(&address), sizeof address) == 0);
  CHECK(notRegularFile(socketPath) == "is a socket, not a regular file");
  ::close(s);
}
