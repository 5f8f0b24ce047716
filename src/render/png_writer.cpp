// PNG through libpng's simplified API (no setjmp/longjmp across C++ frames).
#include "fosssim/render/png_writer.h"

#include "fosssim/io/staged_file.h"

#include <png.h>

#include <cstdio>
#include <cstring>

namespace fosssim::render {

// Encoded in memory, then written by io::writeWholeFile: libpng's own file writer
// (png_image_write_to_file) removes its file when a write fails, whatever that file is (/dev/full
// as root: the device node), and the Python module wrote PNGs for devices through a temporary file
// because of it.
Status writePng(const std::string& path, const Image& image) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(image.width);
  png.height = static_cast<png_uint_32>(image.height);
  png.format = PNG_FORMAT_RGB;
  png.flags = PNG_IMAGE_FLAG_FAST;
  // One encoding into a buffer of libpng's bound for the image's largest PNG (a sizing call with
  // a null buffer would compress every frame twice).
  std::string bytes(PNG_IMAGE_PNG_SIZE_MAX(png), '\0');
  png_alloc_size_t size = bytes.size();
  const bool encoded = png_image_write_to_memory(&png, bytes.data(), &size, 0, image.rgb.data(), 0, nullptr) != 0;
  if (!encoded) {
    const std::string why = png.message;
    png_image_free(&png);
    return Status::error("cannot write PNG file \"" + path + "\": " + why);
  }
  bytes.resize(size);
  return io::writeWholeFile(path, bytes, "PNG");
}

Status readPng(const std::string& path, Image& image) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str()))
    return Status::error("cannot read PNG file \"" + path + "\": " + png.message);
  png.format = PNG_FORMAT_RGB;
  image.width = static_cast<int>(png.width);
  image.height = static_cast<int>(png.height);
  image.rgb.resize(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, image.rgb.data(), 0, nullptr)) {
    const std::string why = png.message;
    png_image_free(&png);
    return Status::error("cannot read PNG file \"" + path + "\": " + why);
  }
  return Status::ok();
}

std::string pngFrameName(const std::string& dir, long number) {
  char name[32];
  std::snprintf(name, sizeof name, "frame%05ld.png", number);
  return dir.empty() ? std::string(name) : dir + "/" + name;
}

}  // namespace fosssim::render
