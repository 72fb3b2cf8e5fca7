#include "test_images.hpp"

#include <cstdlib>
#include <stdexcept>

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#include <stb/stb_image.h>

namespace test_support {

Image Image::read(const std::filesystem::path& file) {
  Image image;
  int channels = 0;
  unsigned char* data = stbi_load(file.c_str(), &image.width, &image.height, &channels, 3);
  if (!data) throw std::runtime_error("cannot read " + file.string());
  image.rgb.assign(data, data + static_cast<std::size_t>(image.width) * image.height * 3);
  stbi_image_free(data);
  return image;
}

bool isBackground(const unsigned char* p) {
  return std::abs(p[0] - 232) < 4 && std::abs(p[1] - 237) < 4 && std::abs(p[2] - 242) < 4;
}

bool isRingRed(const unsigned char* p) {
  return p[0] > p[1] + 40 && p[0] > p[2] + 30;
}

bool isCollisionOrange(const unsigned char* p) {
  return p[0] > 150 && p[1] > 60 && p[1] < p[0] - 40 && p[2] < p[1] - 30;
}

}  // namespace test_support
