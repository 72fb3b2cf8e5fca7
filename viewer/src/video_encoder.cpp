#include "video_encoder.hpp"

#include <fmt/format.h>

#include <stdexcept>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

namespace viewer::detail {

/// The FFmpeg objects of one file, freed in reverse order of making.
struct VideoEncoder::Av {
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  SwsContext* scale = nullptr;
  bool header_written = false;
  bool closed = false;

  ~Av() {
    sws_freeContext(scale);
    av_packet_free(&packet);
    av_frame_free(&frame);
    avcodec_free_context(&codec);
    if (format && !(format->oformat->flags & AVFMT_NOFILE)) avio_closep(&format->pb);
    avformat_free_context(format);
  }
};

namespace {

std::string avError(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

/// libx264 when Debian's libavcodec has it (it does), else FFmpeg's own MPEG-4 Part 2.
const AVCodec* pickEncoder() {
  if (const AVCodec* h264 = avcodec_find_encoder_by_name("libx264")) return h264;
  return avcodec_find_encoder(AV_CODEC_ID_MPEG4);
}

}  // namespace

VideoEncoder::VideoEncoder(const std::filesystem::path& file, int width, int height, int fps)
    : file_(file), av_(std::make_unique<Av>()) {
  av_log_set_level(AV_LOG_ERROR);  // errors reach the caller as exceptions; no encoder chatter
  auto fail = [&](const std::string& what, int code = 0) {
    return std::runtime_error(fmt::format("video {}: {}{}", file.string(), what,
                                          code ? ": " + avError(code) : std::string()));
  };
  if (width % 2 || height % 2 || width <= 0 || height <= 0) {
    throw fail(fmt::format("{}x{} is not an even frame size", width, height));
  }
  if (fps <= 0) throw fail(fmt::format("frame rate {} is not positive", fps));
  std::error_code no_folder;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), no_folder);
  if (no_folder) throw fail("cannot make its folder: " + no_folder.message());
  int rc = avformat_alloc_output_context2(&av_->format, nullptr, nullptr, file.c_str());
  if (rc < 0 || !av_->format) throw fail("no container for this extension (use .mp4)", rc);
  const AVCodec* encoder = pickEncoder();
  if (!encoder) throw fail("neither libx264 nor MPEG-4 in this libavcodec");
  codec_name_ = encoder->name;
  av_->stream = avformat_new_stream(av_->format, nullptr);
  av_->codec = avcodec_alloc_context3(encoder);
  if (!av_->stream || !av_->codec) throw fail("out of memory");
  AVCodecContext* c = av_->codec;
  c->width = width;
  c->height = height;
  c->time_base = AVRational{1, fps};
  c->framerate = AVRational{fps, 1};
  c->pix_fmt = AV_PIX_FMT_YUV420P;
  c->gop_size = 2 * fps;
  // One encoding thread: the recorder's thread has a core, the physics thread the other.
  c->thread_count = 1;
  if (encoder->id == AV_CODEC_ID_H264) {
    av_opt_set(c->priv_data, "preset", "ultrafast", 0);
    av_opt_set(c->priv_data, "crf", "23", 0);
  } else {
    c->bit_rate = 8'000'000;
  }
  if (av_->format->oformat->flags & AVFMT_GLOBALHEADER) c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  if ((rc = avcodec_open2(c, encoder, nullptr)) < 0) throw fail("cannot open the encoder", rc);
  if ((rc = avcodec_parameters_from_context(av_->stream->codecpar, c)) < 0) {
    throw fail("encoder parameters", rc);
  }
  av_->stream->time_base = c->time_base;
  if (!(av_->format->oformat->flags & AVFMT_NOFILE) &&
      (rc = avio_open(&av_->format->pb, file.c_str(), AVIO_FLAG_WRITE)) < 0) {
    throw fail("cannot write the file", rc);
  }
  if ((rc = avformat_write_header(av_->format, nullptr)) < 0) throw fail("header", rc);
  av_->header_written = true;
  av_->frame = av_frame_alloc();
  av_->packet = av_packet_alloc();
  if (!av_->frame || !av_->packet) throw fail("out of memory");
  av_->frame->format = c->pix_fmt;
  av_->frame->width = width;
  av_->frame->height = height;
  if ((rc = av_frame_get_buffer(av_->frame, 0)) < 0) throw fail("frame buffer", rc);
  av_->scale = sws_getContext(width, height, AV_PIX_FMT_RGBA, width, height, AV_PIX_FMT_YUV420P,
                              SWS_BILINEAR, nullptr, nullptr, nullptr);
  if (!av_->scale) throw fail("no RGBA to YUV 4:2:0 converter");
}

VideoEncoder::~VideoEncoder() {
  try {
    close();
  } catch (...) {  // a destructor must not throw; close() says what failed to a caller who asks
  }
}

void VideoEncoder::write(const std::vector<std::uint8_t>& rgba) {
  AVCodecContext* c = av_->codec;
  if (av_->closed) throw std::runtime_error("video " + file_.string() + ": already closed");
  const std::size_t row = static_cast<std::size_t>(c->width) * 4;
  if (rgba.size() != row * c->height) {
    throw std::runtime_error(fmt::format("video {}: a frame of {} bytes, not {}x{} RGBA",
                                         file_.string(), rgba.size(), c->width, c->height));
  }
  int rc = av_frame_make_writable(av_->frame);
  if (rc < 0) throw std::runtime_error("video " + file_.string() + ": " + avError(rc));
  // From the last row upwards: the picture's top row first.
  const std::uint8_t* source[] = {rgba.data() + row * (c->height - 1)};
  const int stride[] = {-static_cast<int>(row)};
  sws_scale(av_->scale, source, stride, 0, c->height, av_->frame->data, av_->frame->linesize);
  av_->frame->pts = frames_++;
  if ((rc = avcodec_send_frame(c, av_->frame)) < 0) {
    throw std::runtime_error("video " + file_.string() + ": encoding: " + avError(rc));
  }
  drain();
}

void VideoEncoder::drain() {
  for (;;) {
    const int rc = avcodec_receive_packet(av_->codec, av_->packet);
    if (rc == AVERROR(EAGAIN) || rc == AVERROR_EOF) return;
    if (rc < 0) throw std::runtime_error("video " + file_.string() + ": " + avError(rc));
    // Each frame lasts one period; without it MP4's edit list would end at the last frame's start
    // and a demuxer would drop that frame.
    if (av_->packet->duration == 0) av_->packet->duration = 1;
    av_packet_rescale_ts(av_->packet, av_->codec->time_base, av_->stream->time_base);
    av_->packet->stream_index = av_->stream->index;
    const int written = av_interleaved_write_frame(av_->format, av_->packet);
    if (written < 0) {
      throw std::runtime_error("video " + file_.string() + ": writing: " + avError(written));
    }
  }
}

void VideoEncoder::close() {
  if (av_->closed || !av_->header_written) return;
  av_->closed = true;
  avcodec_send_frame(av_->codec, nullptr);
  drain();
  const int rc = av_write_trailer(av_->format);
  if (rc < 0) throw std::runtime_error("video " + file_.string() + ": trailer: " + avError(rc));
}

}  // namespace viewer::detail
