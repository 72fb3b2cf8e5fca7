#pragma once
// The video flags of every program that records one (--video, --video-fps, --video-size), so
// they read and check the same everywhere.

#include <CLI/CLI.hpp>
#include <string>

#include "common/number_checks.hpp"

namespace common {

/// What the command line asked of a video.
struct VideoFlags {
  std::string file;  ///< FILE.mp4; empty: no video
  int fps = 30;      ///< frames per simulated second
  std::string size = "960x540";
};

/// Adds --video, --video-fps and --video-size; `what` names what the video shows.
inline void addVideoFlags(CLI::App& app, VideoFlags& flags, const std::string& what) {
  app.add_option("--video", flags.file,
                 "FILE.mp4: a video of " + what +
                     ", one frame every 1/fps simulated seconds (headless: no display needed)");
  app.add_option("--video-fps", flags.fps, "frames per simulated second (default 30)")
      ->check(common::finiteWithin(1, 240));
  app.add_option("--video-size", flags.size, "WIDTHxHEIGHT, even (default 960x540)");
}

}  // namespace common
