// Copyright contactlaws authors.

#include "contactlaws/model_io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstring>

#include <fmt/format.h>

#include "contactlaws/error.h"
#include "scene/model_cache.h"

namespace contactlaws {

namespace {

// MuJoCo's messages may end in a newline; a one-line message must not.
std::string OneLine(const char* text) {
  std::string s(text);
  for (char& c : s) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

// MuJoCo's compile of path; *clean: without an error message or warning.
UniqueModel Compile(const std::string& path, bool* clean) {
  const long warnings = model_cache::WarningsSeen();
  char error[1000] = "";
  UniqueModel m(mj_loadXML(path.c_str(), nullptr, error, sizeof(error)));
  if (!m) {
    throw Error(fmt::format("{}: {}", path, error[0] ? OneLine(error) : "MuJoCo could not load it"));
  }
  *clean = error[0] == 0 && model_cache::WarningsSeen() == warnings;
  return m;
}

}  // namespace

UniqueModel LoadModelFile(const std::string& path) {
  // plain words for the commonest mistakes, before MuJoCo's parser's
  struct stat st;
  if (stat(path.c_str(), &st) != 0) throw Error(fmt::format("{}: no such file", path));
  if (S_ISDIR(st.st_mode)) throw Error(fmt::format("{}: is a directory, not an MJCF file", path));
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw Error(fmt::format("{}: cannot be read", path));
  // the compiled scene (scene/model_cache.h), else MuJoCo's compile, saved
  // when clean and made from the bytes of the key
  std::string xml;
  const bool cacheable = model_cache::On() && model_cache::ReadAll(fd, &xml);
  close(fd);
  bool clean = false;
  if (!cacheable) {
    model_cache::SetOutcome(model_cache::On() ? ModelCacheOutcome::kNotCached
                                              : ModelCacheOutcome::kOff);
    return Compile(path, &clean);
  }
  if (UniqueModel cached = model_cache::Load(xml)) {
    model_cache::SetOutcome(ModelCacheOutcome::kLoaded);
    return cached;
  }
  UniqueModel m = Compile(path, &clean);
  std::string again;
  const bool saved = clean && model_cache::ReadFile(path, &again) && again == xml &&
                     model_cache::Save(xml, m.get());
  model_cache::SetOutcome(saved ? ModelCacheOutcome::kSaved : ModelCacheOutcome::kNotCached);
  return m;
}

UniqueModel LoadModelString(std::string_view xml, const std::string& name) {
  // mjVFS holds mjMAXVFS file names and pointers: too large for the stack
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  if (mj_makeEmptyFileVFS(vfs.get(), name.c_str(), static_cast<int>(xml.size())) != 0) {
    throw Error(fmt::format("{}: could not be put in MuJoCo's virtual file system", name));
  }
  const int index = mj_findFileVFS(vfs.get(), name.c_str());
  std::memcpy(vfs->filedata[index], xml.data(), xml.size());
  char error[1000] = "";
  UniqueModel m(mj_loadXML(name.c_str(), vfs.get(), error, sizeof(error)));
  mj_deleteVFS(vfs.get());
  if (!m) {
    throw Error(fmt::format("{}: {}", name, error[0] ? OneLine(error) : "MuJoCo could not load it"));
  }
  return m;
}

std::string ObjectName(const mjModel* m, mjtObj type, int id) {
  const char* name = mj_id2name(m, type, id);
  if (name && name[0]) return name;
  return fmt::format("{}{}", type == mjOBJ_BODY    ? "body"
                            : type == mjOBJ_JOINT ? "joint"
                            : type == mjOBJ_GEOM  ? "geom"
                                                  : "object",
                     id);
}

int MujocoVersion() { return mj_version(); }

std::string_view LibraryVersion() { return CONTACTLAWS_VERSION; }

}  // namespace contactlaws
