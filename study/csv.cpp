#include "csv.h"

#include <cmath>
#include <cstdio>

namespace fosssim::study {

Status CsvWriter::open(const std::string& path, const std::vector<std::string>& header) {
  out_.open(path, std::ios::trunc);
  if (!out_) return Status::error("cannot write " + path);
  path_ = path;
  columns_ = header.size();
  for (size_t k = 0; k < header.size(); ++k) out_ << (k ? "," : "") << header[k];
  out_ << "\n";
  return Status::ok();
}

void CsvWriter::separate() {
  if (cells_++ > 0) row_ << ",";
}

CsvWriter& CsvWriter::operator<<(double value) {
  separate();
  if (std::isfinite(value)) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", value);
    row_ << buffer;
  } else if (std::isinf(value)) {
    row_ << (value > 0 ? "inf" : "-inf");
  }  // NaN: empty cell
  return *this;
}

CsvWriter& CsvWriter::operator<<(long value) {
  separate();
  row_ << value;
  return *this;
}

CsvWriter& CsvWriter::operator<<(const std::string& text) {
  separate();
  if (text.find_first_of(",\"\n") == std::string::npos) {
    row_ << text;
    return *this;
  }
  row_ << '"';
  for (char c : text) {
    if (c == '\n') c = ' ';
    if (c == '"') row_ << '"';
    row_ << c;
  }
  row_ << '"';
  return *this;
}

Status CsvWriter::endRow() {
  const size_t cells = cells_;
  const std::string line = row_.str();
  row_.str("");
  cells_ = 0;
  if (cells != columns_)
    return Status::error(path_ + ": a row has " + std::to_string(cells) + " cells, the header " +
                         std::to_string(columns_));
  out_ << line << "\n";
  ++rows_;
  if (!out_) return Status::error("cannot write " + path_);
  return Status::ok();
}

}  // namespace fosssim::study
