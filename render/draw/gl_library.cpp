#include "render/draw/gl_library.h"

#include <dlfcn.h>

#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <string>

namespace render::draw {

namespace {

// the soname of Debian's libosmesa6 (Mesa 22); what the linker would have recorded
constexpr const char* kLibrary = "libOSMesa.so.8";

void* library = nullptr;
std::once_flag loaded;

using Function = void (*)();

// the library's own function `name`: OSMesa's through dlsym, GL's through OSMesaGetProcAddress,
// which also finds the extensions (framebuffer objects, multisampling) Mesa does not export by name.
// A GL call before loadGlLibrary() is a bug in the renderer, not a fault of the input: abort.
Function entry(const char* name) {
  if (!library) {
    std::fprintf(stderr, "rigidreel: %s called before the OpenGL library was loaded\n", name);
    std::abort();
  }
  Function f = reinterpret_cast<Function>(::dlsym(library, name));
  if (!f && name[0] == 'g') f = OSMesaGetProcAddress(name);
  if (!f) {
    std::fprintf(stderr, "rigidreel: %s has no function %s\n", kLibrary, name);
    std::abort();
  }
  return f;
}

}  // namespace

void loadGlLibrary() {
  std::call_once(loaded, [] {
    // local: its symbols stay out of the program's namespace, so they never meet the ones below
    library = ::dlopen(kLibrary, RTLD_LAZY | RTLD_LOCAL);
    if (!library)
      throw std::runtime_error(std::string("cannot load ") + kLibrary + ", the software OpenGL that draws frames (" +
                               ::dlerror() + "); install it: apt-get install libosmesa6");
  });
}

bool glLibraryLoaded() { return library != nullptr; }

}  // namespace render::draw

// Each function the renderer calls, defined here with the headers' signature and forwarding to the
// library's, looked up at its first call. A function missing from this list is an undefined reference
// when the program links: add a line.
#define RIGIDREEL_GL(ret, name, params, args)                                                 \
  extern "C" ret name params {                                                                \
    static const auto function = reinterpret_cast<ret(*) params>(render::draw::entry(#name)); \
    return function args;                                                                     \
  }

RIGIDREEL_GL(OSMesaContext, OSMesaCreateContextExt, (GLenum f, GLint d, GLint s, GLint a, OSMesaContext c), (f, d, s, a, c))
RIGIDREEL_GL(void, OSMesaDestroyContext, (OSMesaContext c), (c))
RIGIDREEL_GL(GLboolean, OSMesaMakeCurrent, (OSMesaContext c, void* b, GLenum t, GLsizei w, GLsizei h), (c, b, t, w, h))
RIGIDREEL_GL(void, OSMesaPixelStore, (GLint p, GLint v), (p, v))
RIGIDREEL_GL(OSMESAproc, OSMesaGetProcAddress, (const char* n), (n))

// what the context reports of itself (a golden record's manifest names its renderer)
RIGIDREEL_GL(const GLubyte*, glGetString, (GLenum n), (n))
// whether the frame's buffers could be made (not under a memory limit)
RIGIDREEL_GL(void, glGetRenderbufferParameteriv, (GLenum t, GLenum p, GLint* v), (t, p, v))
RIGIDREEL_GL(void, glBegin, (GLenum m), (m))
RIGIDREEL_GL(void, glEnd, (), ())
RIGIDREEL_GL(void, glVertex2d, (GLdouble x, GLdouble y), (x, y))
RIGIDREEL_GL(void, glColor4d, (GLdouble r, GLdouble g, GLdouble b, GLdouble a), (r, g, b, a))
// a frame's opaque primitives in one batch (gl_canvas.cpp): client vertex and color arrays
RIGIDREEL_GL(void, glEnableClientState, (GLenum a), (a))
RIGIDREEL_GL(void, glDisableClientState, (GLenum a), (a))
RIGIDREEL_GL(void, glVertexPointer, (GLint n, GLenum t, GLsizei s, const GLvoid* p), (n, t, s, p))
RIGIDREEL_GL(void, glColorPointer, (GLint n, GLenum t, GLsizei s, const GLvoid* p), (n, t, s, p))
RIGIDREEL_GL(void, glDrawArrays, (GLenum m, GLint first, GLsizei count), (m, first, count))
// a recorded frame's batches, kept in a buffer object across its sample positions (gl_context.cpp)
RIGIDREEL_GL(void, glGenBuffers, (GLsizei n, GLuint* b), (n, b))
RIGIDREEL_GL(void, glDeleteBuffers, (GLsizei n, const GLuint* b), (n, b))
RIGIDREEL_GL(void, glBindBuffer, (GLenum t, GLuint b), (t, b))
RIGIDREEL_GL(void, glBufferData, (GLenum t, GLsizeiptr n, const void* d, GLenum u), (t, n, d, u))
RIGIDREEL_GL(void, glBufferSubData, (GLenum t, GLintptr o, GLsizeiptr n, const void* d), (t, o, n, d))
// the 3D canvas (render/draw3d): solids with a depth buffer, outlines offset in depth
RIGIDREEL_GL(void, glVertex4d, (GLdouble x, GLdouble y, GLdouble z, GLdouble w), (x, y, z, w))
RIGIDREEL_GL(void, glColor3d, (GLdouble r, GLdouble g, GLdouble b), (r, g, b))
RIGIDREEL_GL(void, glShadeModel, (GLenum mode), (mode))
RIGIDREEL_GL(void, glPolygonOffset, (GLfloat factor, GLfloat units), (factor, units))
RIGIDREEL_GL(void, glFrontFace, (GLenum mode), (mode))
RIGIDREEL_GL(void, glDepthMask, (GLboolean flag), (flag))
RIGIDREEL_GL(void, glDepthFunc, (GLenum func), (func))
RIGIDREEL_GL(void, glCullFace, (GLenum mode), (mode))
RIGIDREEL_GL(void, glClearDepth, (GLclampd depth), (depth))
RIGIDREEL_GL(void, glEnable, (GLenum c), (c))
RIGIDREEL_GL(void, glDisable, (GLenum c), (c))
RIGIDREEL_GL(GLboolean, glIsEnabled, (GLenum c), (c))
RIGIDREEL_GL(void, glBlendFuncSeparate, (GLenum a, GLenum b, GLenum c, GLenum d), (a, b, c, d))
RIGIDREEL_GL(void, glStencilFunc, (GLenum f, GLint r, GLuint m), (f, r, m))
RIGIDREEL_GL(void, glStencilOp, (GLenum a, GLenum b, GLenum c), (a, b, c))
RIGIDREEL_GL(void, glStencilMask, (GLuint m), (m))
RIGIDREEL_GL(void, glClear, (GLbitfield m), (m))
RIGIDREEL_GL(void, glClearColor, (GLclampf r, GLclampf g, GLclampf b, GLclampf a), (r, g, b, a))
RIGIDREEL_GL(void, glClearStencil, (GLint s), (s))
RIGIDREEL_GL(void, glMatrixMode, (GLenum m), (m))
RIGIDREEL_GL(void, glLoadIdentity, (), ())
RIGIDREEL_GL(void, glOrtho, (GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f), (l, r, b, t, n, f))
RIGIDREEL_GL(void, glViewport, (GLint x, GLint y, GLsizei w, GLsizei h), (x, y, w, h))
RIGIDREEL_GL(void, glFinish, (), ())
RIGIDREEL_GL(void, glGenFramebuffers, (GLsizei n, GLuint* f), (n, f))
RIGIDREEL_GL(void, glDeleteFramebuffers, (GLsizei n, const GLuint* f), (n, f))
RIGIDREEL_GL(void, glBindFramebuffer, (GLenum t, GLuint f), (t, f))
RIGIDREEL_GL(GLenum, glCheckFramebufferStatus, (GLenum t), (t))
RIGIDREEL_GL(void, glFramebufferRenderbuffer, (GLenum t, GLenum a, GLenum rt, GLuint r), (t, a, rt, r))
RIGIDREEL_GL(void, glGenRenderbuffers, (GLsizei n, GLuint* r), (n, r))
RIGIDREEL_GL(void, glDeleteRenderbuffers, (GLsizei n, const GLuint* r), (n, r))
RIGIDREEL_GL(void, glBindRenderbuffer, (GLenum t, GLuint r), (t, r))
RIGIDREEL_GL(void, glRenderbufferStorageMultisample, (GLenum t, GLsizei s, GLenum f, GLsizei w, GLsizei h), (t, s, f, w, h))
RIGIDREEL_GL(void, glBlitFramebuffer,
             (GLint a, GLint b, GLint c, GLint d, GLint e, GLint f, GLint g, GLint h, GLbitfield m, GLenum filter),
             (a, b, c, d, e, f, g, h, m, filter))
// frames drawn once per sample position (gl_context.cpp): display lists replayed with the viewport
// shifted, read back top row first
RIGIDREEL_GL(GLuint, glGenLists, (GLsizei n), (n))
RIGIDREEL_GL(void, glDeleteLists, (GLuint l, GLsizei n), (l, n))
RIGIDREEL_GL(void, glNewList, (GLuint l, GLenum m), (l, m))
RIGIDREEL_GL(void, glEndList, (), ())
RIGIDREEL_GL(void, glCallList, (GLuint l), (l))
RIGIDREEL_GL(void, glViewportIndexedf, (GLuint i, GLfloat x, GLfloat y, GLfloat w, GLfloat h), (i, x, y, w, h))
RIGIDREEL_GL(void, glRenderbufferStorage, (GLenum t, GLenum f, GLsizei w, GLsizei h), (t, f, w, h))
RIGIDREEL_GL(void, glPixelStorei, (GLenum p, GLint v), (p, v))
RIGIDREEL_GL(void, glReadPixels, (GLint x, GLint y, GLsizei w, GLsizei h, GLenum f, GLenum t, void* p), (x, y, w, h, f, t, p))
RIGIDREEL_GL(void, glScissor, (GLint x, GLint y, GLsizei w, GLsizei h), (x, y, w, h))
