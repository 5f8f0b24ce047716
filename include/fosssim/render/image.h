// A rendered frame in memory.
#pragma once

#include <cstdint>
#include <vector>

namespace fosssim::render {

/// 8-bit RGB pixels, top row first (the order of PNG files and of ffmpeg's rawvideo input).
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  ///< 3 * width * height bytes

  /// The colour of pixel (x, y) counted from the top-left corner.
  const std::uint8_t* pixel(int x, int y) const { return rgb.data() + 3 * (static_cast<std::size_t>(y) * width + x); }
};

}  // namespace fosssim::render
