// Copyright contactlaws authors.

#include "render/frame_sink.h"

#include <sys/stat.h>
#include <sys/wait.h>

#include <cstdio>
#include <string_view>

#include <fmt/format.h>
#include <png.h>

#include "contactlaws/contact_model.h"
#include "render/render_libraries.h"

namespace contactlaws::render {
namespace {

bool EndsWith(std::string_view text, std::string_view end) {
  return text.size() >= end.size() && text.substr(text.size() - end.size()) == end;
}

bool IsDirectory(const std::string& path) {
  struct stat s;
  return stat(path.c_str(), &s) == 0 && S_ISDIR(s.st_mode);
}

// Quoted for sh -c.
std::string Quote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// Raw RGB frames into ffmpeg's standard input.
class FfmpegSink : public FrameSink {
 public:
  FfmpegSink(OutputFormat format, std::string output, const std::string& ffmpeg, int width,
             int height, double fps)
      : output_(std::move(output)), tmp_(output_ + ".tmp") {
    const std::string encode =
        format == OutputFormat::kMp4
            ? "-c:v libx264 -pix_fmt yuv420p -crf 20 -f mp4"
            : "-vf 'split[a][b];[a]palettegen[p];[b][p]paletteuse' -loop 0 -f gif";
    const std::string command = fmt::format(
        "{} -hide_banner -loglevel error -y -f rawvideo -pix_fmt rgb24 -s {}x{} -framerate {} "
        "-i - {} {}",
        Quote(ffmpeg), width, height, fps, encode, Quote(tmp_));
    pipe_ = popen(command.c_str(), "w");
    if (!pipe_) throw Error(fmt::format("render: could not start {}", ffmpeg));
  }
  ~FfmpegSink() override {
    if (pipe_) {
      pclose(pipe_);
      std::remove(tmp_.c_str());
    }
  }
  void Write(const std::vector<unsigned char>& rgb) override {
    if (std::fwrite(rgb.data(), 1, rgb.size(), pipe_) != rgb.size()) {
      throw Error(fmt::format("render: {}: ffmpeg stopped reading frames", output_));
    }
  }
  void Commit() override {
    const int status = pclose(pipe_);
    pipe_ = nullptr;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 ||
        std::rename(tmp_.c_str(), output_.c_str()) != 0) {
      std::remove(tmp_.c_str());
      throw Error(fmt::format("render: {}: ffmpeg failed (its message above)", output_));
    }
  }

 private:
  std::string output_;
  std::string tmp_;
  std::FILE* pipe_ = nullptr;
};

// DIR/frame_00000.png, frame_00001.png, ...
class PngSink : public FrameSink {
 public:
  PngSink(std::string directory, int width, int height)
      : directory_(std::move(directory)), width_(width), height_(height) {
    if (!IsDirectory(directory_) && mkdir(directory_.c_str(), 0777) != 0) {
      throw Error(fmt::format("render: --output={}: cannot create the directory", directory_));
    }
  }
  void Write(const std::vector<unsigned char>& rgb) override {
    const std::string name = fmt::format("{}/frame_{:05d}.png", directory_, frames_++);
    const std::string tmp = name + ".tmp";
    png_image image = {};
    image.version = PNG_IMAGE_VERSION;
    image.width = static_cast<png_uint_32>(width_);
    image.height = static_cast<png_uint_32>(height_);
    image.format = PNG_FORMAT_RGB;
    if (!PngImageWriteToFile()(&image, tmp.c_str(), 0, rgb.data(), 0, nullptr) ||
        std::rename(tmp.c_str(), name.c_str()) != 0) {
      throw Error(fmt::format("render: {}: cannot write ({})", name, image.message));
    }
  }
  void Commit() override {}

 private:
  std::string directory_;
  int width_;
  int height_;
  int frames_ = 0;
};

}  // namespace

OutputFormat OutputFormatOf(const std::string& output) {
  if (EndsWith(output, ".mp4")) return OutputFormat::kMp4;
  if (EndsWith(output, ".gif")) return OutputFormat::kGif;
  if (EndsWith(output, "/") || IsDirectory(output)) return OutputFormat::kPngDirectory;
  throw Error(fmt::format("--output={} is not a format render writes: FILE.mp4 (H.264), "
                          "FILE.gif, or DIR/ (one PNG per frame)", output));
}

void RequireOutputFolder(OutputFormat format, const std::string& output) {
  std::string path = output;
  if (format == OutputFormat::kPngDirectory) {
    while (path.size() > 1 && path.back() == '/') path.pop_back();
  }
  const size_t slash = path.rfind('/');
  const std::string folder =
      slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
  if (!IsDirectory(folder)) {
    throw Error(fmt::format("--output={} needs the folder {}, which does not exist", output,
                            folder));
  }
}

std::unique_ptr<FrameSink> MakeFrameSink(OutputFormat format, const std::string& output,
                                         const std::string& ffmpeg, int width, int height,
                                         double fps) {
  if (format == OutputFormat::kPngDirectory) {
    std::string directory = output;
    while (directory.size() > 1 && directory.back() == '/') directory.pop_back();
    return std::make_unique<PngSink>(directory, width, height);
  }
  return std::make_unique<FfmpegSink>(format, output, ffmpeg, width, height, fps);
}

}  // namespace contactlaws::render
