// Camera images over ROS 1, against a real rosmaster: sensor_msgs/Image read back in every
// encoding a camera driver uses (and refused, named, when it is not a whole image), the twin
// node's rendered peg-transfer cameras taken in by the client a policy uses.

#include <gtest/gtest.h>
#include <ros/ros.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "bridge/ros/image_conversions.hpp"
#include "bridge/ros/ros_camera_images.hpp"
#include "bridge/ros/ros_image_publisher.hpp"
#include "raven/platform_profile.hpp"
#include "scenario/peg_cameras.hpp"
#include "twin/ros/camera_topics.hpp"
#include "twin/twin_platform.hpp"
#include "viewer/viewer.hpp"

namespace {

using bridge::CameraFrame;
using bridge::ros1::frameFromImage;
using bridge::ros1::toImage;

/// A 3 x 2 frame whose every byte differs.
CameraFrame smallFrame() {
  CameraFrame f{3, 2, {}, {}, 12.5};
  for (int i = 0; i < 18; ++i) f.rgb.push_back(static_cast<std::uint8_t>(10 + i));
  return f;
}

TEST(ImageConversions, AnRgbFrameComesBackAsItWent) {
  const auto parsed = frameFromImage(toImage(smallFrame(), "left-task"));
  ASSERT_TRUE(parsed.value) << parsed.error;
  EXPECT_EQ(parsed.value->rgb, smallFrame().rgb);
  EXPECT_EQ(parsed.value->width, 3);
  EXPECT_EQ(parsed.value->height, 2);
  EXPECT_DOUBLE_EQ(parsed.value->time, 12.5);
  EXPECT_EQ(toImage(smallFrame(), "left-task").header.frame_id, "left-task");
}

TEST(ImageConversions, BgrAlphaAndGreyImagesWithPaddedRowsBecomeRgb) {
  sensor_msgs::Image bgra;
  bgra.width = 2;
  bgra.height = 1;
  bgra.encoding = "bgra8";
  bgra.step = 10;  // two bytes of padding
  bgra.data = {1, 2, 3, 255, 4, 5, 6, 255, 0, 0};
  const auto colour = frameFromImage(bgra);
  ASSERT_TRUE(colour.value) << colour.error;
  EXPECT_EQ(colour.value->rgb, (std::vector<std::uint8_t>{3, 2, 1, 6, 5, 4}));

  sensor_msgs::Image grey;
  grey.width = 2;
  grey.height = 2;
  grey.encoding = "mono8";
  grey.step = 3;
  grey.data = {7, 8, 0, 9, 10, 0};
  const auto g = frameFromImage(grey);
  ASSERT_TRUE(g.value) << g.error;
  EXPECT_EQ(g.value->rgb, (std::vector<std::uint8_t>{7, 7, 7, 8, 8, 8, 9, 9, 9, 10, 10, 10}));
}

TEST(ImageConversions, WhatIsNotAWholeImageIsRefusedSayingWhy) {
  sensor_msgs::Image m = toImage(smallFrame(), "x");
  m.data.pop_back();
  EXPECT_NE(frameFromImage(m).error.find("17 bytes of data, not step x height = 18"),
            std::string::npos)
      << frameFromImage(m).error;
  m = toImage(smallFrame(), "x");
  m.step = 8;
  EXPECT_NE(frameFromImage(m).error.find("step 8 is shorter"), std::string::npos);
  m = toImage(smallFrame(), "x");
  m.encoding = "bayer_rggb8";
  EXPECT_NE(frameFromImage(m).error.find("encoding 'bayer_rggb8'"), std::string::npos);
  m = toImage(smallFrame(), "x");
  m.width = 0;
  EXPECT_FALSE(frameFromImage(m).value);
  CameraFrame short_frame = smallFrame();
  short_frame.rgb.resize(5);
  EXPECT_THROW(toImage(short_frame, "x"), std::invalid_argument);
}

TEST(ImageConversions, ADepthFrameComesBackInMetresAsTheDriversSendIt) {
  CameraFrame depth;
  depth.width = 2;
  depth.height = 2;
  depth.depth = {0.2f, 0.25f, std::numeric_limits<float>::infinity(), 1.5f};
  const sensor_msgs::Image m = toImage(depth, "left-task");
  EXPECT_EQ(m.encoding, "32FC1");
  EXPECT_EQ(m.step, 8u);
  const auto back = frameFromImage(m);
  ASSERT_TRUE(back.value) << back.error;
  EXPECT_TRUE(back.value->rgb.empty());
  EXPECT_EQ(back.value->depth, depth.depth);
  // A 16-bit driver's millimetres, big-endian, a padded row, 0 for no reading.
  sensor_msgs::Image mm;
  mm.encoding = "16UC1";
  mm.width = 2;
  mm.height = 1;
  mm.step = 6;
  mm.is_bigendian = 1;
  mm.data = {0x00, 0xC8, 0x00, 0x00, 0xEE, 0xEE};  // 200 mm, none, padding
  const auto read = frameFromImage(mm);
  ASSERT_TRUE(read.value) << read.error;
  ASSERT_EQ(read.value->depth.size(), 2u);
  EXPECT_FLOAT_EQ(read.value->depth[0], 0.2f);
  EXPECT_TRUE(std::isinf(read.value->depth[1]));
  mm.data.resize(5);
  EXPECT_NE(frameFromImage(mm).error.find("5 bytes of data, not step x height = 6"),
            std::string::npos);
  depth.depth.pop_back();
  EXPECT_THROW(toImage(depth, "x"), std::invalid_argument);
}

TEST(CameraImagesOverRos, TheLatestImageAfterACountAndARefusedOneNamed) {
  bridge::ros1::RosImagePublisher camera({"/test_camera/image_raw"}, {"test"});
  ros::NodeHandle node;
  ros::Publisher raw = node.advertise<sensor_msgs::Image>("/test_camera/image_raw", 2);
  bridge::ros1::RosCameraImages images({{"/test_camera/image_raw"}, 2.0});
  EXPECT_EQ(images.received(0), 0u);
  camera.publish(0, smallFrame());
  const CameraFrame first = images.latest(0, 0);  // waits for the first
  EXPECT_EQ(first.rgb, smallFrame().rgb);
  EXPECT_EQ(images.received(0), 1u);

  sensor_msgs::Image cut = toImage(smallFrame(), "test");
  cut.data.resize(4);
  raw.publish(cut);
  bridge::ros1::RosCameraImages impatient({{"/test_camera/image_raw"}, 0.3});
  raw.publish(cut);
  try {
    impatient.latest(0, 0);
    FAIL() << "a cut image was taken in";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/test_camera/image_raw"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("refused: 4 bytes of data"), std::string::npos)
        << e.what();
  }
}

/// The peg-transfer twin on the simulated clock, and its camera topics once start() made them.
class TwinNodeCameras : public ::testing::Test {
 protected:
  static twin::TwinOptions pegTransfer() {
    twin::TwinOptions options;
    options.launch_file = raven::modelDirectory() / "peg_transfer" / "launch.yaml";
    options.clock = bridge::ClockKind::Simulated;
    return options;
  }

  /// `views` at 64 x 48, 10 frames a second, colour only.
  static twin::ros1::CameraTopicOptions small(std::vector<std::string> views) {
    twin::ros1::CameraTopicOptions options;
    options.views = std::move(views);
    options.width = 64;
    options.height = 48;
    options.rate = 10.0;
    return options;
  }

  /// The topics of `options`' views; empty, saying why in `no_display_`, without headless GL.
  bool start(const twin::ros1::CameraTopicOptions& options) {
    try {
      cameras_.emplace(twin_.world(), options);
      return true;
    } catch (const viewer::NoDisplay& e) {
      no_display_ = e.what();
      return false;
    }
  }

  twin::TwinPlatform twin_{pegTransfer()};
  std::optional<twin::ros1::CameraTopics> cameras_;
  std::string no_display_;
};

TEST_F(TwinNodeCameras, TheTwinNodesTaskCamerasReachAPolicysClient) {
  if (!start(small({"left-task", "right-task"}))) {
    GTEST_SKIP() << "no headless OpenGL here: " << no_display_;
  }
  EXPECT_EQ(twin::ros1::CameraTopics::topicOf("left-task"), "cameras/left_task/image_raw");
  bridge::ros1::RosCameraImages images({{ros::names::resolve("cameras/left_task/image_raw"),
                                         ros::names::resolve("cameras/right_task/image_raw")},
                                        5.0});
  cameras_->update(twin_.world(), 0.0, 0.0);
  const CameraFrame left = images.latest(0, 0);
  const CameraFrame right = images.latest(1, 0);
  ASSERT_EQ(left.width, 64);
  ASSERT_EQ(left.height, 48);
  ASSERT_EQ(left.rgb.size(), 64u * 48 * 3);
  EXPECT_NE(left.rgb, right.rgb);  // two views of two arms' posts
  const auto [darkest, brightest] = std::minmax_element(left.rgb.begin(), left.rgb.end());
  EXPECT_GT(*brightest - *darkest, 100);  // a scene, not a blank
}

TEST_F(TwinNodeCameras, AnRgbdTwinNodePublishesEachViewsDepthBesideItsColour) {
  twin::ros1::CameraTopicOptions rgbd = small({"left-task"});
  rgbd.depth = true;
  if (!start(rgbd)) GTEST_SKIP() << "no headless OpenGL here: " << no_display_;
  EXPECT_EQ(twin::ros1::CameraTopics::depthTopicOf("left-task"),
            "cameras/left_task/depth/image_raw");
  bridge::ros1::RosCameraImages images({{ros::names::resolve("cameras/left_task/image_raw"),
                                         ros::names::resolve("cameras/left_task/depth/image_raw")},
                                        5.0});
  cameras_->update(twin_.world(), 0.0, 0.0);
  const CameraFrame colour = images.latest(0, 0);
  const CameraFrame depth = images.latest(1, 0);
  EXPECT_EQ(colour.rgb.size(), 64u * 48 * 3);
  ASSERT_EQ(depth.depth.size(), 64u * 48);
  // The task camera stands 0.2 m from a point over the board: what it sees lies about that far.
  const float middle = depth.depth[24 * 64 + 32];
  EXPECT_GT(middle, 0.15f);
  EXPECT_LT(middle, 0.30f);
}

TEST_F(TwinNodeCameras, ItsDepthCanReadAsAStereoCameraReadsIt) {
  twin::ros1::CameraTopicOptions biased = small({"left-task"});
  biased.depth = true;
  biased.depth_scale = 1.02;  // a depth camera's 2 % bias, nothing else
  if (!start(biased)) GTEST_SKIP() << "no headless OpenGL here: " << no_display_;
  bridge::ros1::RosCameraImages images(
      {{ros::names::resolve("cameras/left_task/depth/image_raw")}, 5.0});
  cameras_->update(twin_.world(), 0.0, 0.0);
  const std::vector<float> read = images.latest(0, 0).depth;
  const std::vector<float> exact = scenario::PegCameras(twin_.world(), {"left-task"}, 64, 48)
                                       .render(twin_.world(), false, true, false)[0]
                                       .depth;
  ASSERT_EQ(read.size(), exact.size());
  int seen = 0;
  for (std::size_t i = 0; i < exact.size(); ++i) {
    if (!std::isfinite(exact[i])) continue;
    EXPECT_FLOAT_EQ(read[i], 1.02f * exact[i]) << "pixel " << i;
    ++seen;
  }
  EXPECT_GT(seen, 1000);
}

}  // namespace
