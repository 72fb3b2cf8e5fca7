#pragma once
// The CSV pieces every recording reader shares: a file's lines, a line's fields, a field's
// number, and the rows of numbers under a header, each error naming the file and the row.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace recording {

/// "file: row N" (the header is row 1).
std::string rowWhere(const std::filesystem::path& path, std::size_t row);

/// The lines of a text file without their line ends; the header is line 1. Throws
/// RecordingError if it cannot be opened or is empty.
std::vector<std::string> readCsvLines(const std::filesystem::path& path);

/// A line's comma-separated fields (a trailing comma gives a last, empty field).
std::vector<std::string> splitCsv(const std::string& line);

/// A whole field as a number (surrounding spaces allowed; "nan" and "inf" read as such); an empty
/// field is NaN when `empty_is_nan`, else no number.
std::optional<double> parseCsvNumber(std::string text, bool empty_is_nan);

/// The rows after the header (`lines[0]`) as numbers, one per column of `names`, empty fields
/// NaN. Throws RecordingError naming the row and column of a field that is not a number, and a
/// row of the wrong width (the last: "a truncated last line?").
std::vector<std::vector<double>> readNumberRows(const std::filesystem::path& path,
                                                const std::vector<std::string>& lines,
                                                const std::vector<std::string>& names);

}  // namespace recording
