#pragma once
// Frames read back from OpenGL into a video file through Debian's FFmpeg libraries: H.264 (libx264)
// in the container the file's extension names (.mp4, .mkv, .avi), MPEG-4 Part 2 if libx264 is
// missing.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace viewer::detail {

/// One open video file; frames are shown 1/fps seconds each. Not thread-safe.
class VideoEncoder {
 public:
  /// Throws std::runtime_error naming the file if it cannot be opened or no encoder fits.
  /// width and height must be even (4:2:0 chroma).
  VideoEncoder(const std::filesystem::path& file, int width, int height, int fps);
  ~VideoEncoder();
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  /// Encodes one frame: RGBA rows, bottom row first (as OpenGL reads them back),
  /// width * height * 4 bytes.
  void write(const std::vector<std::uint8_t>& rgba);
  /// Flushes the encoder and writes the file's trailer; further writes throw.
  void close();

  const std::string& codecName() const { return codec_name_; }
  std::int64_t framesWritten() const { return frames_; }

 private:
  struct Av;     // the FFmpeg contexts
  void drain();  ///< writes every packet the encoder has ready

  std::filesystem::path file_;
  std::unique_ptr<Av> av_;
  std::string codec_name_;
  std::int64_t frames_ = 0;
};

}  // namespace viewer::detail
