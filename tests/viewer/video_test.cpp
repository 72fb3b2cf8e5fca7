// A video of the main job, made headless while it runs and read back with FFmpeg's decoder: the
// frames it says it wrote are in the file, at the size asked for, and the video lasts as long as
// the run was simulated at the chosen frame rate.

#include <gtest/gtest.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

#include <memory>

#include "headless_peg_scene.hpp"
#include "scenario/peg_transfer.hpp"
#include "scenario/run_watcher.hpp"
#include "test_files.hpp"

namespace {

/// What a video file holds, by decoding every frame of its first video stream.
struct DecodedVideo {
  int width = 0, height = 0;
  std::int64_t frames = 0;
  double duration_s = 0.0;  ///< the container's
  double frame_rate = 0.0;
  std::string codec;

  static DecodedVideo read(const std::filesystem::path& file) {
    DecodedVideo v;
    AVFormatContext* format = nullptr;
    if (avformat_open_input(&format, file.c_str(), nullptr, nullptr) < 0) {
      throw std::runtime_error("cannot open " + file.string());
    }
    std::unique_ptr<AVFormatContext, void (*)(AVFormatContext*)> closer(
        format, [](AVFormatContext* f) { avformat_close_input(&f); });
    if (avformat_find_stream_info(format, nullptr) < 0) throw std::runtime_error("no streams");
    const int stream = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
    if (stream < 0) throw std::runtime_error("no video stream");
    const AVCodecParameters* parameters = format->streams[stream]->codecpar;
    const AVCodec* decoder = avcodec_find_decoder(parameters->codec_id);
    std::unique_ptr<AVCodecContext, void (*)(AVCodecContext*)> codec(
        avcodec_alloc_context3(decoder), [](AVCodecContext* c) { avcodec_free_context(&c); });
    avcodec_parameters_to_context(codec.get(), parameters);
    codec->thread_count = 1;
    if (avcodec_open2(codec.get(), decoder, nullptr) < 0) throw std::runtime_error("no decoder");
    v.codec = decoder->name;
    v.duration_s = static_cast<double>(format->duration) / AV_TIME_BASE;
    v.frame_rate = av_q2d(format->streams[stream]->r_frame_rate);
    AVPacket* packet = av_packet_alloc();
    AVFrame* frame = av_frame_alloc();
    auto drain = [&] {
      while (avcodec_receive_frame(codec.get(), frame) == 0) {
        ++v.frames;
        v.width = frame->width;
        v.height = frame->height;
      }
    };
    while (av_read_frame(format, packet) >= 0) {
      // A full decoder takes the packet once the frames it holds are out.
      while (packet->stream_index == stream &&
             avcodec_send_packet(codec.get(), packet) == AVERROR(EAGAIN)) {
        drain();
      }
      av_packet_unref(packet);
      drain();
    }
    avcodec_send_packet(codec.get(), nullptr);
    drain();
    av_frame_free(&frame);
    av_packet_free(&packet);
    return v;
  }
};

/// Why this machine cannot render headless, or empty if it can.
std::string headlessUnavailable() {
  return test_support::HeadlessPegScene().why;
}

TEST(Video, OfTheMainJobDecodesToItsFramesSizeAndSimulatedDuration) {
  if (const auto why = headlessUnavailable(); !why.empty()) {
    GTEST_SKIP() << "no headless OpenGL: " << why;
  }
  test_support::TempDir dir;
  scenario::WatchOptions watch;
  watch.video = dir.path() / "main_job.mp4";
  watch.video_options.fps = 25;
  watch.video_options.width = 480;
  watch.video_options.height = 270;
  scenario::RunWatcher watcher(watch);
  scenario::PegTransferOptions options;
  double first = -1.0, last = 0.0;  // the simulated times the observer saw
  options.observe = [&](const ambf_like::World& world, scenario::WorldMoment moment,
                        std::uint64_t seed) {
    if (first < 0.0) first = world.time();
    last = world.time();
    watcher(world, moment, seed);
  };
  const auto result = scenario::runPegTransfer(options);
  ASSERT_EQ(watcher.videos().size(), 1u);
  EXPECT_TRUE(result.allPlaced()) << "the video's run is the main job, placing all six";

  const viewer::VideoSummary written = watcher.videos().front();
  const double simulated = last - first;
  // One frame at the start and one per 1/fps simulated seconds after it.
  EXPECT_EQ(written.frames, static_cast<std::int64_t>(std::floor(simulated * 25 + 1e-6)) + 1);
  const DecodedVideo video = DecodedVideo::read(watch.video);
  EXPECT_EQ(video.frames, written.frames);
  EXPECT_EQ(video.width, 480);
  EXPECT_EQ(video.height, 270);
  EXPECT_EQ(video.codec, "h264");
  EXPECT_NEAR(video.frame_rate, 25.0, 1e-9);
  EXPECT_NEAR(video.duration_s, simulated, 2.0 / 25) << "simulated " << simulated << " s";
  EXPECT_GT(simulated, 60.0) << "the whole main job";
}

TEST(Video, EachRunOfABatchHasItsOwnFile) {
  scenario::WatchOptions watch;
  watch.video = "videos/peg.mp4";
  EXPECT_EQ(scenario::RunWatcher(watch).videoFileFor(7), "videos/peg.mp4");
  watch.video_per_seed = true;
  const scenario::RunWatcher batch(watch);
  EXPECT_EQ(batch.videoFileFor(7), "videos/peg_seed7.mp4");
  EXPECT_EQ(batch.videoFileFor(12), "videos/peg_seed12.mp4");
}

TEST(Video, ABadFileOrSizeIsRefusedByName) {
  if (const auto why = headlessUnavailable(); !why.empty()) {
    GTEST_SKIP() << "no headless OpenGL: " << why;
  }
  viewer::VideoOptions options;
  EXPECT_THROW(options.setSize("641x360"), std::invalid_argument);
  EXPECT_THROW(options.setSize("640"), std::invalid_argument);
  EXPECT_THROW(options.setSize("640x360x2"), std::invalid_argument);
  options.setSize("640x360");
  EXPECT_EQ(options.width, 640);
  ambf_like::MeshLibrary meshes;
  const auto scene =
      ambf_like::loadLaunchFile(std::filesystem::path(RAVEN_MODELS_DIR) / "raven2/launch.yaml", {});
  ambf_like::World world(scene.spec, meshes);
  options.file = "/proc/no_such_dir/run.mp4";
  try {
    viewer::VideoRecorder recorder(world, options, std::nullopt);
    ADD_FAILURE() << "a video written into /proc";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("/proc/no_such_dir/run.mp4"), std::string::npos)
        << e.what();
  }
}

}  // namespace
