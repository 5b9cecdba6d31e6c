// Copyright contactlaws authors.

#include "scene/model_cache.h"

#include <fcntl.h>
#include <gnu/libc-version.h>
#include <link.h>
#include <sys/stat.h>
#include <unistd.h>
#if defined(__x86_64__) && __has_include(<sys/platform/x86.h>)
// glibc's header spells bool as C's _Bool, which clang's C++ does not accept
#if defined(__clang__)
#define _Bool bool
#include <sys/platform/x86.h>
#undef _Bool
#else
#include <sys/platform/x86.h>
#endif
#endif

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string_view>
#include <vector>

#include <fmt/format.h>

namespace contactlaws {
namespace {

// The first line of every key: a new layout of the entries changes it.
constexpr char kFormat[] = "contactlaws model cache 1\n";
// The name MuJoCo reads a payload under from the virtual file system.
constexpr char kPayloadName[] = "cached.mjb";

struct CacheState {
  std::optional<std::string> directory;
  void (*forward_warning)(const char*) = nullptr;
};
CacheState& State() {
  static CacheState state;
  return state;
}
thread_local long warnings_seen = 0;
thread_local ModelCacheOutcome last_outcome = ModelCacheOutcome::kOff;

// Counts MuJoCo's warnings on this thread, then hands them on.
extern "C" void SeeWarning(const char* text) {
  ++warnings_seen;
  State().forward_warning(text);
}

// FNV-1a, 64 bits: names entries (the key itself decides a hit) and checks
// payloads against damage.
uint64_t Fnv1a(std::string_view bytes) {
  uint64_t hash = 14695981039346656037ull;
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 1099511628211ull;
  }
  return hash;
}

// Every shared library of the process: path, size and modification time.
std::string LoadedLibraries() {
  std::vector<std::string> lines;
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void* out) {
        struct stat st;
        if (info->dlpi_name && info->dlpi_name[0] && stat(info->dlpi_name, &st) == 0) {
          static_cast<std::vector<std::string>*>(out)->push_back(
              fmt::format("library {} {} {}.{:09}\n", info->dlpi_name, st.st_size,
                          st.st_mtim.tv_sec, st.st_mtim.tv_nsec));
        }
        return 0;
      },
      &lines);
  std::sort(lines.begin(), lines.end());
  std::string all;
  for (const std::string& line : lines) all += line;
  return all;
}

// The CPU features the C library's math functions choose their code by, as
// the C library found them (no cpuid of our own: slow in a virtual machine).
std::string CpuFeatures() {
  std::string features = "cpu";
#if defined(__x86_64__) && __has_include(<sys/platform/x86.h>)
  if (CPU_FEATURE_ACTIVE(FMA)) features += " fma";
  if (CPU_FEATURE_ACTIVE(AVX2)) features += " avx2";
  if (CPU_FEATURE_ACTIVE(AVX512F)) features += " avx512f";
#else
  features += " unknown";
#endif
  return features + "\n";
}

std::string Key(const std::string& xml) {
  return fmt::format("{}contactlaws {}\nmujoco {} mjtNum {}\nglibc {}\n{}{}xml {}\n", kFormat,
                     LibraryVersion(), mj_version(), sizeof(mjtNum), gnu_get_libc_version(),
                     CpuFeatures(), LoadedLibraries(), xml.size()) +
         xml;
}

std::string EntryPath(const std::string& key) {
  return fmt::format("{}/{:016x}.entry", *State().directory, Fnv1a(key));
}

// An entry: the key's length and the key, the payload's length and checksum,
// the payload (an .mjb file).
void PutLength(std::string* out, uint64_t n) { out->append(reinterpret_cast<char*>(&n), sizeof n); }

bool TakeLength(const std::string& in, size_t* at, uint64_t* n) {
  if (in.size() - *at < sizeof *n) return false;
  std::memcpy(n, in.data() + *at, sizeof *n);
  *at += sizeof *n;
  return true;
}

// Where the payload of entry starts when its key is key and the payload is
// whole.
std::optional<size_t> Payload(const std::string& entry, const std::string& key) {
  size_t at = 0;
  uint64_t key_size = 0;
  uint64_t payload_size = 0;
  uint64_t checksum = 0;
  if (!TakeLength(entry, &at, &key_size) || key_size != key.size() ||
      entry.compare(at, key.size(), key) != 0) {
    return std::nullopt;
  }
  at += key.size();
  if (!TakeLength(entry, &at, &payload_size) || !TakeLength(entry, &at, &checksum) ||
      payload_size != entry.size() - at) {
    return std::nullopt;
  }
  if (Fnv1a(std::string_view(entry).substr(at)) != checksum) return std::nullopt;
  return at;
}

// MuJoCo reads a model from memory through its virtual file system; the
// system's 2 MB of names is not cleared (mj_defaultVFS would): one entry is
// filled in.
UniqueModel LoadFromMemory(char* payload, size_t size) {
  std::unique_ptr<mjVFS> vfs(new mjVFS);
  vfs->nfile = 1;
  std::strcpy(vfs->filename[0], kPayloadName);
  vfs->filesize[0] = static_cast<int>(size);
  vfs->filedata[0] = payload;
  return UniqueModel(mj_loadModel(kPayloadName, vfs.get()));
}

bool MentionsFiles(const std::string& xml) {
  std::string lower(xml.size(), ' ');
  std::transform(xml.begin(), xml.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower.find("file") != std::string::npos;
}

bool HasSensorNoise(const mjModel* m) {
  return std::any_of(m->sensor_noise, m->sensor_noise + m->nsensor,
                     [](mjtNum noise) { return noise != 0; });
}

// Writes bytes to path through a temporary file renamed over it.
bool WriteAtomically(const std::string& path, const std::string& bytes) {
  std::error_code code;
  std::filesystem::create_directories(*State().directory, code);
  std::string temporary = *State().directory + "/.entry-XXXXXX";
  const int fd = mkstemp(temporary.data());
  if (fd < 0) return false;
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n <= 0) break;
    done += static_cast<size_t>(n);
  }
  const bool whole = close(fd) == 0 && done == bytes.size();
  if (whole && rename(temporary.c_str(), path.c_str()) == 0) return true;
  unlink(temporary.c_str());
  return false;
}

// Removes the oldest entries until the cache is within its bounds.
void Prune() {
  namespace fs = std::filesystem;
  struct Found {
    fs::file_time_type written;
    uintmax_t size;
    fs::path path;
  };
  std::vector<Found> entries;
  uintmax_t bytes = 0;
  std::error_code code;
  for (const fs::directory_entry& e : fs::directory_iterator(*State().directory, code)) {
    if (e.path().extension() != ".entry") continue;
    Found f{e.last_write_time(code), e.file_size(code), e.path()};
    if (code) continue;
    bytes += f.size;
    entries.push_back(std::move(f));
  }
  std::sort(entries.begin(), entries.end(),
            [](const Found& a, const Found& b) { return a.written < b.written; });
  for (size_t i = 0; i < entries.size() && (entries.size() - i > kModelCacheMaxEntries || bytes > kModelCacheMaxBytes);
       ++i) {
    if (fs::remove(entries[i].path, code)) bytes -= entries[i].size;
  }
}

}  // namespace

std::optional<std::string> ModelCacheDirectoryFromEnvironment() {
  const char* setting = std::getenv("CONTACTLAWS_MODEL_CACHE");
  if (setting && (std::strcmp(setting, "off") == 0 || std::strcmp(setting, "0") == 0)) {
    return std::nullopt;
  }
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (xdg && xdg[0] == '/') return std::string(xdg) + "/contactlaws";
  const char* home = std::getenv("HOME");
  if (home && home[0] == '/') return std::string(home) + "/.cache/contactlaws";
  return std::nullopt;
}

void UseModelCache(std::optional<std::string> directory) {
  CacheState& state = State();
  if (directory && mju_user_warning != SeeWarning) {
    if (!mju_user_warning) directory.reset();  // its warnings would not be seen
    state.forward_warning = mju_user_warning;
    if (directory) mju_user_warning = SeeWarning;
  }
  state.directory = std::move(directory);
}

ModelCacheOutcome LastModelCacheOutcome() { return last_outcome; }

namespace model_cache {

bool On() { return State().directory.has_value(); }

bool ReadAll(int fd, std::string* bytes) {
  struct stat st;
  if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) return false;
  bytes->resize(static_cast<size_t>(st.st_size));
  size_t done = 0;
  while (done < bytes->size()) {
    const ssize_t n = read(fd, bytes->data() + done, bytes->size() - done);
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

bool ReadFile(const std::string& path, std::string* bytes) {
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool ok = ReadAll(fd, bytes);
  close(fd);
  return ok;
}

long WarningsSeen() { return warnings_seen; }

void SetOutcome(ModelCacheOutcome outcome) { last_outcome = outcome; }

UniqueModel Load(const std::string& xml) {
  if (MentionsFiles(xml)) return nullptr;
  const std::string key = Key(xml);
  std::string entry;
  if (!ReadFile(EntryPath(key), &entry)) return nullptr;
  const std::optional<size_t> payload = Payload(entry, key);
  if (!payload) return nullptr;
  return LoadFromMemory(entry.data() + *payload, entry.size() - *payload);
}

bool Save(const std::string& xml, const mjModel* m) {
  if (MentionsFiles(xml) || HasSensorNoise(m)) return false;
  std::string payload(static_cast<size_t>(mj_sizeModel(m)), '\0');
  mj_saveModel(m, nullptr, payload.data(), static_cast<int>(payload.size()));
  const std::string key = Key(xml);
  std::string entry;
  PutLength(&entry, key.size());
  entry += key;
  PutLength(&entry, payload.size());
  PutLength(&entry, Fnv1a(payload));
  entry += payload;
  if (!WriteAtomically(EntryPath(key), entry)) return false;
  Prune();
  return true;
}

}  // namespace model_cache
}  // namespace contactlaws
