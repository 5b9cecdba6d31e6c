// Copyright contactlaws authors.

#include "render/render_libraries.h"

#include <dlfcn.h>

#include <mutex>
#include <string>

#include <fmt/format.h>

#include "contactlaws/contact_model.h"

namespace contactlaws::render {
namespace {

#define CONTACTLAWS_STRING(x) #x
#define CONTACTLAWS_EXPAND(x) CONTACTLAWS_STRING(x)

// The Linux OpenGL ABI's EGL library (libglvnd).
constexpr char kEglLibrary[] = "libEGL.so.1";
constexpr char kEglPackage[] = "libegl1";
// libpng's soname: libpng<DLLNUM>.so.<SONUM> of the png.h built against.
constexpr char kPngLibrary[] =
    "libpng" CONTACTLAWS_EXPAND(PNG_LIBPNG_VER_DLLNUM) ".so." CONTACTLAWS_EXPAND(PNG_LIBPNG_VER_SONUM);
constexpr char kPngPackage[] = "libpng16-16";

void* Open(const char* library, const char* package) {
  void* handle = dlopen(library, RTLD_NOW | RTLD_GLOBAL);
  if (!handle) {
    throw Error(fmt::format("render: cannot load {} (Debian package {}): {}", library, package,
                            dlerror()));
  }
  return handle;
}

template <typename Function>
void Find(void* handle, const char* library, const char* name, Function* function) {
  *function = reinterpret_cast<Function>(dlsym(handle, name));
  if (!*function) throw Error(fmt::format("render: {} has no {}", library, name));
}

EglFunctions LoadEgl() {
  void* h = Open(kEglLibrary, kEglPackage);
  EglFunctions f;
  Find(h, kEglLibrary, "eglGetProcAddress", &f.GetProcAddress);
  Find(h, kEglLibrary, "eglGetError", &f.GetError);
  Find(h, kEglLibrary, "eglInitialize", &f.Initialize);
  Find(h, kEglLibrary, "eglChooseConfig", &f.ChooseConfig);
  Find(h, kEglLibrary, "eglBindAPI", &f.BindAPI);
  Find(h, kEglLibrary, "eglCreateContext", &f.CreateContext);
  Find(h, kEglLibrary, "eglMakeCurrent", &f.MakeCurrent);
  Find(h, kEglLibrary, "eglDestroyContext", &f.DestroyContext);
  Find(h, kEglLibrary, "eglTerminate", &f.Terminate);
  return f;
}

}  // namespace

const EglFunctions& Egl() {
  // loaded once (a static's initialisation is thread-safe; a failure throws
  // and the next call tries again)
  static const EglFunctions functions = LoadEgl();
  return functions;
}

decltype(&png_image_write_to_file) PngImageWriteToFile() {
  static const auto function = [] {
    decltype(&png_image_write_to_file) f = nullptr;
    Find(Open(kPngLibrary, kPngPackage), kPngLibrary, "png_image_write_to_file", &f);
    return f;
  }();
  return function;
}

}  // namespace contactlaws::render
