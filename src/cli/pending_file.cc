// Copyright contactlaws authors.

#include "cli/pending_file.h"

#include <cerrno>
#include <cstring>
#include <utility>

#include <fmt/format.h>

#include "cli/cluster.h"
#include "contactlaws/contact_model.h"

namespace contactlaws::cli {

PendingFile::PendingFile(std::string path, const char* mode) : path_(std::move(path)) {
  if (!WritesOutputs()) return;  // another rank of the job writes it
  temp_ = path_ + ".tmp";
  file_ = std::fopen(temp_.c_str(), mode);
  if (!file_) {
    throw Error(fmt::format("{}: cannot write ({})", path_, std::strerror(errno)));
  }
  // a trajectory of many bodies is 100 MB: written in 1 MB system calls
  // rather than stdio's 4 KB ones (25,000 of them, a fifth of the file's
  // system time)
  buffer_ = std::make_unique<char[]>(kBuffer);
  std::setvbuf(file_, buffer_.get(), _IOFBF, kBuffer);
}

PendingFile::~PendingFile() {
  if (file_) {
    std::fclose(file_);
    std::remove(temp_.c_str());
  }
}

void PendingFile::Commit() {
  if (!file_) return;
  const bool ok = std::fflush(file_) == 0 && !std::ferror(file_);
  std::fclose(file_);
  file_ = nullptr;
  if (!ok || std::rename(temp_.c_str(), path_.c_str()) != 0) {
    const int error = errno;
    std::remove(temp_.c_str());
    throw Error(fmt::format("{}: cannot write ({})", path_, std::strerror(error)));
  }
}

}  // namespace contactlaws::cli
