// A table of rows as CSV (RFC 4180): what analyses (dimension fits) write for spreadsheets and plotting
// tools. Numbers in the shortest form that reads back to the same double, text quoted when it holds a comma, a quote or
// a line break.
#pragma once

#include <filesystem>
#include <string>
#include <variant>
#include <vector>

namespace selfsim::io {

using CsvCell = std::variant<double, std::string>;
using CsvRows = std::vector<std::vector<CsvCell>>;

// Throws Error naming the first row of another length than the first or the first non-finite number.
std::string csv_text(const CsvRows& rows);

// Writes the rows as root/name, atomically (output_file.h); returns the path for messages.
std::string save_csv(const std::filesystem::path& root, const std::string& name, const CsvRows& rows);

}  // namespace selfsim::io
