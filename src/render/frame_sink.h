// Copyright contactlaws authors.
//
// Where rendered frames go: a video through ffmpeg (raw RGB frames piped to
// `ffmpeg -f rawvideo`: H.264 MP4, or a GIF through ffmpeg's palettegen and
// paletteuse filters), or one PNG file per frame in a directory (libpng:
// Debian's libpng-dev, the reference PNG library, already on every machine
// MuJoCo's own samples run on). Files are written as FILE.tmp and renamed by
// Commit(), as the other outputs of contactlaws are.

#ifndef CONTACTLAWS_RENDER_FRAME_SINK_H_
#define CONTACTLAWS_RENDER_FRAME_SINK_H_

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace contactlaws::render {

enum class OutputFormat { kMp4, kGif, kPngDirectory };

// The format of an --output: FILE.mp4, FILE.gif, or DIR/ (or an existing
// directory). Error naming the formats otherwise.
OutputFormat OutputFormatOf(const std::string& output);

// Error unless the folder output goes in exists: FILE's folder, or DIR/'s
// (DIR itself is made when missing).
void RequireOutputFolder(OutputFormat format, const std::string& output);

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  // width x height x 3 bytes, top row first
  virtual void Write(const std::vector<unsigned char>& rgb) = 0;
  // Completes the output; Error when the encoder failed.
  virtual void Commit() = 0;
};

// ffmpeg (its path) for the video formats; Error when it cannot start.
std::unique_ptr<FrameSink> MakeFrameSink(OutputFormat format, const std::string& output,
                                         const std::string& ffmpeg, int width, int height,
                                         double fps);

}  // namespace contactlaws::render

#endif  // CONTACTLAWS_RENDER_FRAME_SINK_H_
