// Copyright contactlaws authors.
//
// Compiled scenes kept between runs (issue 15's start-up): MuJoCo 2.2.2's
// compiler makes and zeroes an mjData sized by its defaults and steps it
// once for every scene it loads, which costs more than the rest of a short
// run. A scene MuJoCo compiled cleanly is saved in MuJoCo's binary format
// (mj_saveModel) and loaded from there (mj_loadModel) while nothing it was
// made from has changed.
//
// An entry is found by a hash of its key and used only when the key stored
// in it equals the whole key, byte for byte: the XML's bytes, this library's
// version, MuJoCo's, the size and modification time of every shared library
// the process has loaded (MuJoCo's and the C library's among them) and the
// CPU features the C library's math picks its code by. A payload is checked
// against its length and checksum before MuJoCo reads it. Not cached:
// - a scene whose text contains "file" anywhere (an <include>, a mesh,
//   height field, skin or texture file, or anything resembling one): its
//   files are not in the key;
// - a scene MuJoCo refuses, or accepts with a warning (the compile runs
//   again each time, so its message comes again);
// - a scene with sensor noise (MuJoCo's compiler seeds rand(), which the
//   noise draws from, and a loaded model would not);
// - a scene whose bytes changed while it compiled, or that is not a regular
//   file (a pipe, a device).
// Entries are written to a temporary file and renamed: a reader sees a whole
// entry or none. Any failure to read or write the cache falls back to the
// compile, silently.

#ifndef CONTACTLAWS_SCENE_MODEL_CACHE_H_
#define CONTACTLAWS_SCENE_MODEL_CACHE_H_

#include <cstddef>
#include <optional>
#include <string>

#include "contactlaws/model_io.h"

namespace contactlaws {

// The cache's bounds: past either, the oldest entries are removed when one
// is saved.
constexpr size_t kModelCacheMaxEntries = 256;
constexpr unsigned long long kModelCacheMaxBytes = 64ull << 20;

// The cache's directory from the environment: off when
// CONTACTLAWS_MODEL_CACHE is "off" or "0"; else $XDG_CACHE_HOME/contactlaws
// (an absolute XDG_CACHE_HOME), else $HOME/.cache/contactlaws; none without
// either.
std::optional<std::string> ModelCacheDirectoryFromEnvironment();

// Makes LoadModelFile use the cache in directory (created when first
// written), or none (std::nullopt, the default). Call before loading scenes
// on other threads. MuJoCo's warnings while a scene loads must reach the
// cache, so it wraps mju_user_warning, which must be set before (the cache
// stays off otherwise); the wrapper passes every warning on.
void UseModelCache(std::optional<std::string> directory);

// What the last LoadModelFile of this thread did with the cache.
enum class ModelCacheOutcome { kOff, kLoaded, kSaved, kNotCached };
ModelCacheOutcome LastModelCacheOutcome();

namespace model_cache {

// Whether UseModelCache turned the cache on.
bool On();

// The bytes of the regular file open as fd (of path); false when it is not
// a regular file or cannot be read whole.
bool ReadAll(int fd, std::string* bytes);
bool ReadFile(const std::string& path, std::string* bytes);

// The cached model whose key holds xml (a scene's bytes), or nullptr.
UniqueModel Load(const std::string& xml);

// MuJoCo warnings seen on this thread since the cache was turned on: a
// compile that adds one is not cached.
long WarningsSeen();

// Saves m, compiled cleanly from xml, when the scene may be cached; whether
// it did.
bool Save(const std::string& xml, const mjModel* m);

void SetOutcome(ModelCacheOutcome outcome);

}  // namespace model_cache
}  // namespace contactlaws

#endif  // CONTACTLAWS_SCENE_MODEL_CACHE_H_
