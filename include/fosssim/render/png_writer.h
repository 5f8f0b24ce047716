// PNG files through libpng.
#pragma once

#include "fosssim/core/status.h"
#include "fosssim/render/image.h"

#include <string>

namespace fosssim::render {

/// Writes `image` as an 8-bit RGB PNG, compressed for speed rather than size (a run writes one
/// per step; zlib's default level costs several times more for a few percent).
Status writePng(const std::string& path, const Image& image);

/// Reads an 8-bit RGB(A) PNG (for tests and tools), dropping alpha.
Status readPng(const std::string& path, Image& image);

/// -g's file name: dir/frame%05d.png.
std::string pngFrameName(const std::string& dir, long number);

}  // namespace fosssim::render
