// The GL library is loaded by the first GL context, not when the program starts: before it, this
// process has no libOSMesa mapped; after it, it has (the command line's side: tests/render/cli/cli_test.sh).
#include <doctest/doctest.h>

#include <fstream>
#include <sstream>

#include "render/draw/gl_context.h"
#include "render/draw/gl_library.h"

namespace {

bool mapped(const std::string& library) {
  std::ifstream maps("/proc/self/maps");
  std::stringstream text;
  text << maps.rdbuf();
  return text.str().find(library) != std::string::npos;
}

}  // namespace

TEST_CASE("libOSMesa is mapped only once a GL context is made") {
  CHECK_FALSE(render::draw::glLibraryLoaded());
  CHECK_FALSE(mapped("libOSMesa"));
  CHECK_FALSE(mapped("libLLVM"));
  render::draw::GlContext gl(8, 8);
  CHECK(render::draw::glLibraryLoaded());
  CHECK(mapped("libOSMesa"));
}
