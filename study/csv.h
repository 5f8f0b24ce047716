// A small CSV writer: a header, then rows of numbers and text. Numbers keep 9 significant digits
// (plenty for charts and readable in a diff); NaN, the study's "does not apply", is an empty cell.
#pragma once

#include "fosssim/core/status.h"

#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>
#include <vector>

namespace fosssim::study {

class CsvWriter {
 public:
  /// Opens (truncates) `path` and writes the header line.
  Status open(const std::string& path, const std::vector<std::string>& header);

  /// Cells of the row under construction, in header order.
  CsvWriter& operator<<(double value);
  CsvWriter& operator<<(long value);
  CsvWriter& operator<<(int value) { return *this << static_cast<long>(value); }
  CsvWriter& operator<<(const std::string& text);
  CsvWriter& operator<<(const char* text) { return *this << std::string(text); }
  /// Ends the row. Fails if it has a different number of cells than the header.
  Status endRow();

  int rows() const { return rows_; }

 private:
  void separate();
  std::ofstream out_;
  std::string path_;
  std::ostringstream row_;
  size_t columns_ = 0;
  size_t cells_ = 0;
  int rows_ = 0;
};

}  // namespace fosssim::study
