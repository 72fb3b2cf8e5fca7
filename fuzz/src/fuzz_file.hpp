#pragma once
// A fuzzer's input as a file: the project's readers take paths (they name the file in every
// error), so each input is written to a private temporary folder first.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace fuzz {

/// `data` written to `name` in this process's temporary folder; returns the path.
std::filesystem::path asFile(const std::uint8_t* data, std::size_t size, const std::string& name);

/// `text` written to `name` in this process's temporary folder; returns the path.
std::filesystem::path asFile(std::string_view text, const std::string& name);

/// Ends the process with a message when a property of the code under test fails: libFuzzer
/// reports the abort as a finding and saves the input.
[[noreturn]] void fail(const std::string& what);

}  // namespace fuzz
