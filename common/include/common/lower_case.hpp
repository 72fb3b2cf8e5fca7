#pragma once
// ASCII lower-casing, for case-insensitive keywords (shape names, joint types, file extensions).

#include <algorithm>
#include <cctype>
#include <string>

namespace common {

inline std::string lowerCase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

}  // namespace common
