// writePngFile: libpng's simplified write API (no setjmp error handling needed).
#include <png.h>

#include <cstring>

#include "smachac/sim/snapshot.h"

namespace smachac::sim {

std::string writePngFile(const std::string& path, const Image& image) {
  const size_t expected = static_cast<size_t>(image.width) * static_cast<size_t>(image.height) * 3;
  if (image.width <= 0 || image.height <= 0 || image.rgb.size() != expected) {
    return "image has no pixels or a wrong size";
  }
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = PNG_FORMAT_RGB;
  if (png_image_write_to_file(&png, path.c_str(), 0, image.rgb.data(), 0, nullptr) == 0) {
    return "cannot write `" + path + "`: " + png.message;
  }
  return "";
}

}  // namespace smachac::sim
