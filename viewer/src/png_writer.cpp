// PNG files through stb_image_write (Debian's libstb).
#include <stdexcept>

#include "renderer.hpp"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>

namespace viewer::detail {

void writePng(const std::filesystem::path& file, const std::vector<std::uint8_t>& rgb, int width,
              int height) {
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  if (!stbi_write_png(file.c_str(), width, height, 3, rgb.data(), width * 3)) {
    throw std::runtime_error("cannot write " + file.string());
  }
}

}  // namespace viewer::detail
