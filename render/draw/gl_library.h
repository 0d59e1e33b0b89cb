// The OpenGL library, Mesa's libOSMesa (software GL: llvmpipe, and through it LLVM), loaded when the
// first frame is drawn rather than when the program starts. Loading it relocates libLLVM (about
// 400,000 relocations, three quarters of a `check`'s 0.13 s), which commands that draw nothing
// (simulate, check, sweep, stability) never pay. The program does not link libOSMesa: gl_library.cpp
// defines each GL and OSMesa function the renderer calls, forwarding to the library's own.
#pragma once

namespace render::draw {

// loads libOSMesa.so.8 (once; later calls return at once); throws std::runtime_error naming the
// Debian package to install when it is missing
void loadGlLibrary();

// whether this process has loaded it (the tests)
bool glLibraryLoaded();

}  // namespace render::draw
