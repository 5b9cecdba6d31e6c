// Copyright contactlaws authors.
//
// EGL and libpng, loaded when render first needs them (dlopen) rather than
// linked into the program: every other command starts without them and the
// libraries they bring (GLdispatch, zlib) (issue 15's start-up).

#ifndef CONTACTLAWS_RENDER_RENDER_LIBRARIES_H_
#define CONTACTLAWS_RENDER_RENDER_LIBRARIES_H_

#include <EGL/egl.h>
#include <png.h>

namespace contactlaws::render {

// The EGL 1.4 functions the offscreen context uses.
struct EglFunctions {
  decltype(&eglGetProcAddress) GetProcAddress;
  decltype(&eglGetError) GetError;
  decltype(&eglInitialize) Initialize;
  decltype(&eglChooseConfig) ChooseConfig;
  decltype(&eglBindAPI) BindAPI;
  decltype(&eglCreateContext) CreateContext;
  decltype(&eglMakeCurrent) MakeCurrent;
  decltype(&eglDestroyContext) DestroyContext;
  decltype(&eglTerminate) Terminate;
};

// libEGL.so.1, loaded once with its symbols global (MuJoCo's OpenGL loader
// looks eglGetProcAddress up in the process); Error naming the library and
// its Debian package when it cannot be loaded.
const EglFunctions& Egl();

// libpng's png_image_write_to_file, from the libpng this program was built
// against (its soname from png.h); Error as Egl.
decltype(&png_image_write_to_file) PngImageWriteToFile();

}  // namespace contactlaws::render

#endif  // CONTACTLAWS_RENDER_RENDER_LIBRARIES_H_
