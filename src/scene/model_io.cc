// Copyright contactlaws authors.

#include "contactlaws/contact_model.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstring>

#include <fmt/format.h>


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

}  // namespace

UniqueModel LoadModelFile(const std::string& path) {
  // plain words for the commonest mistakes, before MuJoCo's parser's
  struct stat st;
  if (stat(path.c_str(), &st) != 0) throw Error(fmt::format("{}: no such file", path));
  if (S_ISDIR(st.st_mode)) throw Error(fmt::format("{}: is a directory, not an MJCF file", path));
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw Error(fmt::format("{}: cannot be read", path));
  close(fd);
  char error[1000] = "";
  UniqueModel m(mj_loadXML(path.c_str(), nullptr, error, sizeof(error)));
  if (!m) {
    throw Error(fmt::format("{}: {}", path, error[0] ? OneLine(error) : "MuJoCo could not load it"));
  }
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
