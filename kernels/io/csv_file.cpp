#include "kernels/io/csv_file.h"

#include <charconv>
#include <cmath>

#include "kernels/base/error.h"
#include "kernels/io/output_file.h"

namespace selfsim::io {

namespace {

void put_text(std::string& out, const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) {
    out += text;
    return;
  }
  out += '"';
  for (char ch : text) {
    if (ch == '"') out += '"';
    out += ch;
  }
  out += '"';
}

}  // namespace

std::string csv_text(const CsvRows& rows) {
  std::string out;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (rows[r].size() != rows[0].size())
      throw Error("row " + std::to_string(r + 1) + " has " + std::to_string(rows[r].size()) + " cells, row 1 has " +
                  std::to_string(rows[0].size()) + ": every row needs as many");
    for (std::size_t c = 0; c < rows[r].size(); ++c) {
      if (c > 0) out += ',';
      if (const double* v = std::get_if<double>(&rows[r][c])) {
        if (!std::isfinite(*v))
          throw Error("row " + std::to_string(r + 1) + ", cell " + std::to_string(c + 1) + " is not a finite number");
        char buf[32];
        out.append(buf, std::to_chars(buf, buf + sizeof buf, *v).ptr);  // the shortest text that reads back the same
      } else {
        put_text(out, std::get<std::string>(rows[r][c]));
      }
    }
    out += "\r\n";
  }
  return out;
}

std::string save_csv(const std::filesystem::path& root, const std::string& name, const CsvRows& rows) {
  const std::string text = csv_text(rows);  // checked whole before the file is opened
  OutputFile out(root, name);
  out.write(text);
  out.commit();
  return out.path();
}

}  // namespace selfsim::io
