#pragma once
// Private helpers shared by the model readers: reading a file whole, splitting lines into
// tokens, parsing numbers strictly, and error messages that name the file and the line.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "util/result.hpp"

namespace gem::import {

// The whole file as bytes; "path: cannot open (No such file or directory)" when it cannot.
Result<std::string> read_whole_file(const std::filesystem::path& path);

// "file:line: message", the form every reader's errors take.
Error line_error(const std::filesystem::path& path, std::size_t line, const std::string& message);
// "file: message", for errors that belong to the whole file (an open mesh, a truncated binary).
Error file_error(const std::filesystem::path& path, const std::string& message);

// Whitespace-separated tokens of one line.
std::vector<std::string_view> split_tokens(std::string_view line);

// A finite number spelled by the whole token (a leading '+' allowed), else nothing.
std::optional<double> parse_number(std::string_view token);
// A whole integer spelled by the whole token (a leading '+' allowed), else nothing.
std::optional<long long> parse_integer(std::string_view token);

// Walks a text line by line (LF, CRLF or lone CR), counting lines from 1.
class LineCursor {
  public:
    explicit LineCursor(std::string_view text);
    // The next line without its terminator; false at the end of the text.
    bool next(std::string_view& line);
    std::size_t line_number() const { return line_number_; }

  private:
    std::string_view text_;
    std::size_t pos_ = 0;
    std::size_t line_number_ = 0;
};

// Case-insensitive comparison of ASCII keywords.
bool iequals(std::string_view a, std::string_view b);
bool istarts_with(std::string_view text, std::string_view prefix);

}  // namespace gem::import
