// Copyright contactlaws authors.
//
// An output file that appears complete or not at all: written to PATH.tmp,
// renamed to PATH by Commit, removed when dropped uncommitted. On a rank of a
// cluster job that does not write the outputs (cluster.h), nothing is
// opened: get() is null and the writers drop what they would write.

#ifndef CONTACTLAWS_CLI_PENDING_FILE_H_
#define CONTACTLAWS_CLI_PENDING_FILE_H_

#include <cstdio>
#include <memory>
#include <string>

namespace contactlaws::cli {

class PendingFile {
 public:
  // mode: fopen's ("w", "wb"). Throws Error "PATH: cannot write (reason)".
  PendingFile(std::string path, const char* mode);
  ~PendingFile();

  PendingFile(const PendingFile&) = delete;
  PendingFile& operator=(const PendingFile&) = delete;

  std::FILE* get() const { return file_; }
  const std::string& path() const { return path_; }

  // Flushes and closes PATH.tmp and renames it to PATH; throws Error "PATH:
  // cannot write (reason)" when any of it fails (the temporary removed).
  void Commit();

 private:
  static constexpr size_t kBuffer = 1 << 20;  // bytes

  std::string path_;
  std::string temp_;
  // stdio's buffer, ours: glibc's setvbuf takes the size of none it
  // allocates itself (it then buffers st_blksize, 4 KB); freed after file_
  std::unique_ptr<char[]> buffer_;
  std::FILE* file_ = nullptr;
};

}  // namespace contactlaws::cli

#endif  // CONTACTLAWS_CLI_PENDING_FILE_H_
