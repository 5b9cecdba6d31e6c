// Copyright contactlaws authors.

#include "contactlaws/model_io.h"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

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

std::string ReadBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

UniqueModel LoadModelFile(const std::string& path) {
  // plain words for the commonest mistakes, before MuJoCo's parser's
  std::error_code code;
  const std::filesystem::file_status status = std::filesystem::status(path, code);
  if (!std::filesystem::exists(status)) throw Error(fmt::format("{}: no such file", path));
  if (std::filesystem::is_directory(status)) {
    throw Error(fmt::format("{}: is a directory, not an MJCF file", path));
  }
  if (!std::ifstream(path)) throw Error(fmt::format("{}: cannot be read", path));
  bool clean = false;
  if (!model_cache::On()) {
    model_cache::SetOutcome(ModelCacheOutcome::kOff);
    return Compile(path, &clean);
  }
  // the compiled scene (scene/model_cache.h), else MuJoCo's compile, saved
  // when clean and made from the bytes of the key
  const std::string xml = ReadBytes(path);
  if (UniqueModel cached = model_cache::Load(xml)) {
    model_cache::SetOutcome(ModelCacheOutcome::kLoaded);
    return cached;
  }
  UniqueModel m = Compile(path, &clean);
  const bool saved = clean && ReadBytes(path) == xml && model_cache::Save(xml, m.get());
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
