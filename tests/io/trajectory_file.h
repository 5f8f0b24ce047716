// Trajectory files packed by hand from the format description (spec section 6), so that the
// reader is checked against the format and not only against the writer.
#pragma once

#include "fosssim/core/collision_log.h"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace fosssim::testing {

/// Little-endian bytes of a record, appended piece by piece.
struct Bytes {
  std::string data;
  Bytes& i32(std::int32_t v) {
    unsigned char b[4];
    for (int k = 0; k < 4; ++k) b[k] = static_cast<unsigned char>((static_cast<std::uint32_t>(v) >> (8 * k)) & 0xff);
    data.append(reinterpret_cast<const char*>(b), 4);
    return *this;
  }
  Bytes& f64(double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, 8);
    unsigned char b[8];
    for (int k = 0; k < 8; ++k) b[k] = static_cast<unsigned char>((bits >> (8 * k)) & 0xff);
    data.append(reinterpret_cast<const char*>(b), 8);
    return *this;
  }
  Bytes& f64s(const std::vector<double>& vs) {
    for (double v : vs) f64(v);
    return *this;
  }
};

/// A folder for one test's files, removed with the object.
class TempDir {
 public:
  explicit TempDir(const std::string& tag) {
    static int counter = 0;
    path_ = std::filesystem::temp_directory_path() /
            ("fosssim-" + tag + "-" + std::to_string(getpid()) + "-" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  std::string write(const std::string& name, const std::string& bytes) const {
    std::ofstream out(file(name), std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return file(name);
  }

 private:
  std::filesystem::path path_;
};

inline std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace fosssim::testing
